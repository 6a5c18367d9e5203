"""Scale demonstration: 65,536 clustered lights fed from a pipeline over a large
distributed isosurface, timed at the rank count pvbatch runs on.

Scene:
 - an isosurface of the Wavelet source on a 201^3 grid (8.1 million points, split over
   the ranks by the source), solid color;
 - 65,536 lights: the cell centers of a 64 x 64 x 16-cell Wavelet grid (split over the
   ranks too), spread over the isosurface's box, colored from their position by a
   Calculator, intensity from the grid's scalars, quadratic attenuation with an explicit
   radius and the windowed falloff (so each light reaches a few units only);
 - the Clustered Lighting view, 1024 x 768, light kit off; the camera orbits 2 degrees
   per frame, so every timed frame assigns the lights again.

Prints one line "RESULT ..." with the numbers (scripts/run-paraview-demo.sh makes the table
from them) and saves the last frame, and the same frame colored by process id.
Usage: pvbatch scale_demo.py --plugin ClusteredLighting.so --output DIR [--frames N]
"""

import argparse
import os
import statistics
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--plugin", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--frames", type=int, default=10)
parser.add_argument("--size", type=int, nargs=2, default=[1024, 768])
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
os.makedirs(args.output, exist_ok=True)


def info(proxy, name):
    proxy.UpdatePropertyInformation()
    return vtkSMPropertyHelper(proxy.SMProxy, name).GetAsDouble(0)


start = time.perf_counter()
wavelet = Wavelet(WholeExtent=[-100, 100, -100, 100, -100, 100])
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[180.0])
surface.ComputeScalars = 0
surface.UpdatePipeline()
triangles = surface.GetDataInformation().GetNumberOfCells()
points = wavelet.GetDataInformation().GetNumberOfPoints()
pipeline_seconds = time.perf_counter() - start

# 65,536 lights: one per cell of a 64 x 64 x 16-cell grid, placed in the isosurface's box.
grid = Wavelet(WholeExtent=[0, 64, 0, 64, 0, 16])
centers = CellCenters(Input=grid)
placed = Transform(Input=centers)
placed.Transform.Translate = [-96.0, -96.0, -96.0]
placed.Transform.Scale = [3.0, 3.0, 12.0]
colored = Calculator(Input=placed, ResultArrayName="Color",
                     Function="(0.55+0.45*sin(coordsX/23))*iHat+(0.55+0.45*sin(coordsY/19+2))*jHat"
                              "+(0.55+0.45*sin(coordsZ/29+4))*kHat")
lights_data = Calculator(Input=colored, ResultArrayName="Intensity",
                         Function="0.6+RTData/300")

view = CreateView("ClusteredLightingView")
view.ViewSize = args.size
view.UseLight = 0
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.02, 0.02, 0.03]
view.Falloff = "Windowed"
surface_display = Show(surface, view)
surface_display.ColorArrayName = ["POINTS", ""]
surface_display.DiffuseColor = [0.9, 0.9, 0.9]
surface_display.Specular = 0.3
lights = Show(lights_data, view)
lights.Representation = "Clustered Lights"
lights.LightColorArray = "Color"
lights.LightIntensityArray = "Intensity"
lights.LightDefaultAttenuation = [1.0, 0.0, 0.08]
lights.LightDefaultRadius = 9.0

view.CameraPosition = [330.0, -420.0, 260.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0

start = time.perf_counter()
Render(view)
first = time.perf_counter() - start
clustered = int(info(view, "NumberOfClusteredLights"))

camera = view.GetActiveCamera()
times = []
for _ in range(args.frames):
    camera.Azimuth(2.0)
    start = time.perf_counter()
    Render(view)
    times.append(time.perf_counter() - start)
assigned = int(info(view, "NumberOfAssignedLights"))
updates = int(info(view, "NumberOfAssignmentUpdates"))

# The same frames without the lights (representation hidden): the cost of the geometry.
Hide(lights_data, view)
Render(view)
unlit_times = []
for _ in range(args.frames):
    camera.Azimuth(-2.0)
    start = time.perf_counter()
    Render(view)
    unlit_times.append(time.perf_counter() - start)
Show(lights_data, view)
for _ in range(args.frames):
    camera.Azimuth(2.0)
Render(view)

image = os.path.join(args.output, "paraview-scale-demo-np%d.png" % ranks)
SaveScreenshot(image, view, ImageResolution=args.size, TransparentBackground=0)
ids = Show(ProcessIdScalars(Input=surface), view)
Hide(surface, view)
ColorBy(ids, ("POINTS", "ProcessId"))
lut = GetColorTransferFunction("ProcessId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0.0, 3.0)
Hide(lights_data, view)
view.UseLight = 1
SaveScreenshot(os.path.join(args.output, "paraview-scale-demo-ranks-np%d.png" % ranks), view,
               ImageResolution=args.size, TransparentBackground=0)

print("RESULT ranks=%d points=%d triangles=%d lights=%d assigned=%d assignment_updates=%d "
      "pipeline_s=%.2f first_frame_s=%.2f frame_ms_median=%.1f frame_ms_min=%.1f "
      "unlit_frame_ms_median=%.1f image=%s"
      % (ranks, points, triangles, clustered, assigned, updates, pipeline_seconds, first,
         1000 * statistics.median(times), 1000 * min(times),
         1000 * statistics.median(unlit_times), image))
