"""Lights whose data lives on one rank light the pieces of other ranks.

Scene: a Sphere source (radius 10) split over the ranks in wedges of longitude, and 8
clustered lights from a Line source next to its surface at longitude 225 degrees. A Line
source is not split: its points exist on rank 0 only. The lights (radius 4) do not reach
rank 0's piece on 2 or 4 ranks: the lit region lies on another rank's piece, which only
lights delivered to every rank can light.

Checks:
 - the lights' data is on rank 0 only (Process Id Scalars range 0 .. 0), and no light's
   sphere of influence touches the bounding box of rank 0's piece (on N > 1 ranks);
 - rank 0's pass clustered the 8 lights, and they light a region of the sphere (more
   than 1,500 pixels brighter than 40 of 255; the rest of the frame is black: no other
   light);
 - on N > 1 ranks (--reference: the output folder of the 1-rank run), the image equals
   the 1-rank image within one 8-bit step (see distributed.py), and so does the lit
   region's pixel count; lit by lights rank 1 never received, the region would be black;
 - hiding the representation switches its lights off: no clustered light, and the frame
   equals the stock RenderView's without any light; showing it again brings them back.

Also saves the frame with the sphere colored by process id and a dim light kit: the lit
region lies on another rank's color.
"""

from paraview.simple import *  # noqa: F401,F403

import clustered_test as t

t.setup(__doc__, reference=True)
n = t.ranks()

view = CreateView("ClusteredLightingView")
view.ViewSize = [400, 400]
view.UseLight = 0  # only the clustered lights: unlit surfaces are black
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]

body = Sphere(Radius=10.0, ThetaResolution=256, PhiResolution=128)
body_display = Show(body, view)
body_display.ColorArrayName = ["POINTS", ""]
body_display.DiffuseColor = [0.9, 0.9, 0.9]

radius = 4.0
line = Line(Point1=[-8.5, -8.5, -3.5], Point2=[-8.5, -8.5, 3.5], Resolution=7)
lights = Show(line, view)
lights.Representation = "Clustered Lights"
lights.LightDefaultColor = [1.0, 0.75, 0.4]
lights.LightDefaultAttenuation = [1.0, 0.0, 0.3]
lights.LightDefaultRadius = radius
view.Falloff = "Windowed"


def set_camera():
    view.CameraPosition = [-30.0, -30.0, 10.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0


set_camera()

ids = ProcessIdScalars(Input=line)
ids.UpdatePipeline()
low, high = ids.PointData["ProcessId"].GetRange()
t.check(low == 0 and high == 0, "the lights' data is on rank 0 only (process ids %g .. %g)"
        % (low, high))

if n > 1:
    # The bounding box of rank 0's piece of the sphere.
    owned = Threshold(Input=ProcessIdScalars(Input=body), Scalars=["POINTS", "ProcessId"],
                      LowerThreshold=0, UpperThreshold=0)
    owned.UpdatePipeline()
    box = owned.GetDataInformation().GetBounds()
    points = [[-8.5, -8.5, -3.5 + i] for i in range(8)]
    nearest = min(
        sum(max(box[2 * a] - p[a], 0.0, p[a] - box[2 * a + 1]) ** 2 for a in range(3)) ** 0.5
        for p in points)
    t.check(nearest > radius,
            "no light reaches rank 0's piece: nearest light %.2f from its box %s, radius %g"
            % (nearest, ["%.2f" % b for b in box], radius))

image = t.save(view, t.output("lights-across-ranks"))
clustered = t.info(view, "NumberOfClusteredLights")
t.check(clustered == 8, "rank 0 clustered %d lights (8 expected)" % clustered)
lit = int((image.max(axis=2) > 40).sum())
t.check(lit > 1500, "lit pixels: %d (more than 1,500 expected)" % lit)

if t.args.reference:
    reference = t.read(t.args.reference + "/lights-across-ranks-np1.png")
    d = t.difference(image, reference)
    t.check(d["max"] <= 1,
            "against 1 rank: max difference %d step(s) (tolerance 1), %d pixels differ"
            % (d["max"], d["pixels_differing"]))
    reference_lit = int((reference.max(axis=2) > 40).sum())
    t.check(abs(lit - reference_lit) <= d["pixels_differing"],
            "lit pixels: %d on %d ranks, %d on 1 rank" % (lit, n, reference_lit))

# Hidden lights are off: no clustered light, and the frame is the stock render view's
# without any light (VTK then draws surfaces unlit). Shown again, they are back.
Hide(line, view)
hidden = t.save(view, t.output("lights-across-ranks-hidden"))
stock = CreateView("RenderView")
stock.ViewSize = view.ViewSize
stock.UseLight = 0
stock.OrientationAxesVisibility = 0
stock.UseColorPaletteForBackground = 0
stock.Background = [0.0, 0.0, 0.0]
stock_display = Show(body, stock)
stock_display.ColorArrayName = ["POINTS", ""]
stock_display.DiffuseColor = [0.9, 0.9, 0.9]
stock.CameraPosition = view.CameraPosition
stock.CameraFocalPoint = view.CameraFocalPoint
stock.CameraViewUp = view.CameraViewUp
stock.CameraViewAngle = view.CameraViewAngle
unlit = t.save(stock, t.output("lights-across-ranks-stock-unlit"))
d = t.difference(hidden, unlit)
t.check(t.info(view, "NumberOfClusteredLights") == 0 and d["max"] == 0,
        "hidden: %d clustered lights (0 expected), max difference %d from the stock view "
        "without lights (0 expected)" % (t.info(view, "NumberOfClusteredLights"), d["max"]))
Show(line, view)
again = t.save(view, t.output("lights-across-ranks-again"))
t.check(t.info(view, "NumberOfClusteredLights") == 8 and t.difference(again, image)["max"] == 0,
        "shown again: %d clustered lights (8 expected), max difference %d from the first frame"
        % (t.info(view, "NumberOfClusteredLights"), t.difference(again, image)["max"]))
Delete(stock)

# For the eye: which rank owns which piece, under a dim light kit.
ids_display = Show(ProcessIdScalars(Input=body), view)
Hide(body, view)
ColorBy(ids_display, ("POINTS", "ProcessId"))
lut = GetColorTransferFunction("ProcessId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0.0, 3.0)
ids_display.Diffuse = 0.35
ids_display.Ambient = 0.15
view.UseLight = 1
set_camera()
t.save(view, t.output("lights-across-ranks-process-ids"))

t.finish()
