"""A distributed dataset lit by clustered lights renders the same on 1, 2 and 4 ranks.

Scene: a Sphere source (radius 10, 256 x 128), its pieces on different ranks, in one solid
color, lit only by 448 clustered lights whose data is split over the ranks too: the cell
centers of a coarse sphere around it (cells are split without duplicates), colored from
their coordinates. Every rank's pass must get all 448 lights (the representation gathers
them and delivers them to every rank), and IceT composites the pieces. The sphere's
pieces are ranges of longitude computed by the same formulas as the whole sphere, so
the triangles do not depend on the split.

Checks:
 - the sphere and the lights really are split over all ranks (Process Id Scalars ranges
   0 .. ranks - 1), and rank 0's pass clustered all 448 lights;
 - the image is lit;
 - on N > 1 ranks (--reference: the output folder of the 1-rank run), the image equals
   the 1-rank image within one 8-bit step at every pixel (the README's bound for
   clustered against stock VTK). The stock RenderView's image of the same split sphere,
   lit by its light kit, is compared the same way, with the same tolerance: what it
   shows is how much ParaView's own rendering changes with the number of ranks;
 - ghost points are one light: the 226 points of a 16 x 16 Sphere source, with ghost
   points marked by Ghost Cells Generator, give 226 lights on every rank count
   (unmarked, the pieces would give the points they share once each).

Also saves the frame colored by process id (which rank owns which piece).
"""

from paraview.simple import *  # noqa: F401,F403

import clustered_test as t

t.setup(__doc__, reference=True)
n = t.ranks()


def make_view(kind):
    view = CreateView(kind)
    view.ViewSize = [480, 360]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.08, 0.08, 0.1]
    view.CameraPosition = [28.0, -34.0, 22.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    return view


body = Sphere(Radius=10.0, ThetaResolution=256, PhiResolution=128)

view = make_view("ClusteredLightingView")
view.UseLight = 0  # only clustered lights
view.Falloff = "Windowed"
body_display = Show(body, view)
body_display.ColorArrayName = ["POINTS", ""]
body_display.DiffuseColor = [0.85, 0.85, 0.85]

# 448 lights: the cell centers of a coarse sphere around the body (cells are split over
# the ranks without duplicates, unlike the points that pieces share).
light_sphere = Sphere(Radius=12.0, ThetaResolution=16, PhiResolution=16)
centers = CellCenters(Input=light_sphere)
colors = Calculator(Input=centers, ResultArrayName="Color",
                    Function="(0.5+coordsX/24)*iHat+(0.5+coordsY/24)*jHat+(0.5+coordsZ/24)*kHat")
lights = Show(colors, view)
lights.Representation = "Clustered Lights"
lights.LightColorArray = "Color"
lights.LightDefaultIntensity = 0.8
lights.LightDefaultAttenuation = [1.0, 0.0, 0.4]
lights.LightDefaultRadius = 3.5

for name, source in (("body", body), ("lights", centers)):
    ids = ProcessIdScalars(Input=source)
    ids.UpdatePipeline()
    low, high = ids.PointData["ProcessId"].GetRange()
    t.check(low == 0 and high == n - 1,
            "%s split over ranks 0 .. %d (process ids %g .. %g)" % (name, n - 1, low, high))

image = t.save(view, t.output("distributed"))
expected = centers.GetDataInformation().GetNumberOfPoints()
t.check(expected == 448, "%d light points in the data (448 cells of the light sphere)" % expected)
clustered = t.info(view, "NumberOfClusteredLights")
t.check(clustered == expected, "rank 0 clustered %d lights (%d expected)" % (clustered, expected))
lit = int((image.max(axis=2) > 40).sum())
t.check(lit > 0.1 * image.shape[0] * image.shape[1],
        "lit pixels: %d of %d (more than 10%% expected)" % (lit, image.shape[0] * image.shape[1]))

# The stock render view of the same split sphere, lit by its light kit: how much ParaView's
# own images change with the number of ranks.
stock = make_view("RenderView")
stock_display = Show(body, stock)
stock_display.ColorArrayName = ["POINTS", ""]
stock_display.DiffuseColor = [0.85, 0.85, 0.85]
stock_image = t.save(stock, t.output("distributed-stock"))

if t.args.reference:
    d = t.difference(image, t.read(t.args.reference + "/distributed-np1.png"))
    t.check(d["max"] <= 1,
            "against 1 rank: max difference %d step(s) (tolerance 1), %d pixels differ, %d by "
            "more than 1" % (d["max"], d["pixels_differing"], d["pixels_over_1"]))
    d = t.difference(stock_image, t.read(t.args.reference + "/distributed-stock-np1.png"))
    t.check(d["max"] <= 1,
            "stock RenderView against 1 rank: max difference %d step(s) (tolerance 1), %d "
            "pixels differ" % (d["max"], d["pixels_differing"]))
Delete(stock)

# Ghost points: one light per point of the sphere, whatever the number of ranks.
Hide(colors, view)
ghosts = GhostCellsGenerator(Input=light_sphere, BuildIfRequired=0)
ghost_lights = Show(ghosts, view)
ghost_lights.Representation = "Clustered Lights"
ghost_lights.LightDefaultAttenuation = [1.0, 0.0, 0.15]
ghost_lights.LightDefaultRadius = 7.0
Render(view)
points = ghosts.GetDataInformation().GetNumberOfPoints()
clustered = t.info(view, "NumberOfClusteredLights")
t.check(clustered == 226,
        "sphere with ghost points: %d lights (226 expected; %d points with ghosts)"
        % (clustered, points))
Hide(ghosts, view)
Show(colors, view)

# The frame colored by the rank that owns each piece (for the eye; not compared: the
# colors depend on the rank count).
ids_display = Show(ProcessIdScalars(Input=body), view)
Hide(body, view)
view.CameraPosition = [28.0, -34.0, 22.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ColorBy(ids_display, ("POINTS", "ProcessId"))
lut = GetColorTransferFunction("ProcessId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0.0, 3.0)
t.save(view, t.output("distributed-process-ids"))

t.finish()
