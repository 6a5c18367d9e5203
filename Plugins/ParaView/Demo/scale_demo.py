"""Scale demonstration: 65,536 clustered lights fed from a pipeline over a large
distributed isosurface, timed at the rank count pvbatch runs on.

Scene:
 - an isosurface of the Wavelet source on a 201^3 grid (8.1 million points, split over
   the ranks by the source), solid color;
 - 65,536 lights: the cell centers of a 32 x 64 x 32-cell Wavelet grid (split over the
   ranks too), moved with a jitter into the isosurface's box by a Calculator, colored
   from their position, intensity from the grid's scalars, quadratic attenuation with an
   explicit radius of 5 and the windowed falloff (each light reaches 5 units only);
 - the Clustered Lighting view, 1024 x 768, light kit off; the camera orbits 2 degrees
   per frame, so every timed frame assigns the lights again.

Times: the first frame (data delivery, light upload, shader compilation); the median and
fastest of --frames frames (Render() on rank 0, which returns after IceT composited the
ranks' images); one frame with the pass's timers (rank 0's assignment and shading, after
a glFinish); the lights evaluated per pixel of the isosurface, against those that reach
it (the evaluated-count debug view); and the same frames without the lights. On N > 1
ranks, the last frame is compared with the 1-rank run's (if it is in --output), and so is
the stock RenderView's frame of the same isosurface (light kit, same camera).
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
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

import numpy

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--plugin", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--frames", type=int, default=5)
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

# 65,536 lights: one per cell of a 32 x 64 x 32-cell Wavelet grid (cell centers, with the
# grid's scalars averaged to each cell), moved with a jitter into the isosurface's box.
grid = Wavelet(WholeExtent=[0, 32, 0, 64, 0, 32])
centers = CellCenters(Input=PointDatatoCellData(Input=grid))
placed = Calculator(Input=centers, CoordinateResults=1,
                    Function="(6*coordsX-96+2*sin(7.1*coordsY+3.3*coordsZ))*iHat"
                             "+(3*coordsY-96+1.5*sin(5.3*coordsX+9.7*coordsZ))*jHat"
                             "+(6*coordsZ-96+2*sin(8.9*coordsX+2.1*coordsY))*kHat")
colored = Calculator(Input=placed, ResultArrayName="Color",
                     Function="(0.55+0.45*sin(coordsX/23))*iHat+(0.55+0.45*sin(coordsY/19+2))*jHat"
                              "+(0.55+0.45*sin(coordsZ/29+4))*kHat")
lights_data = Calculator(Input=colored, ResultArrayName="Intensity",
                         Function="1.0+RTData/100")

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
lights.LightDefaultAttenuation = [1.0, 0.0, 0.12]
lights.LightDefaultRadius = 5.0

# The first frame: data delivery, light upload, shader compilation (and paraview.simple's
# camera reset); then the camera this demonstration looks from.
start = time.perf_counter()
Render(view)
first = time.perf_counter() - start
view.CameraPosition = [230.0, -290.0, 190.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
clustered = int(info(view, "NumberOfClusteredLights"))

camera = view.GetActiveCamera()
times = []
for _ in range(args.frames):
    camera.Azimuth(2.0)
    start = time.perf_counter()
    Render(view)
    times.append(time.perf_counter() - start)
assigned = int(info(view, "NumberOfAssignedLights"))

# One more frame with the pass's own timers (rank 0's; they wait for the GPU).
view.MeasureTimings = 1
camera.Azimuth(2.0)
Render(view)
assignment_ms = info(view, "LastAssignmentTime")
shading_ms = info(view, "LastShadingTime")
view.MeasureTimings = 0

# Lights evaluated per pixel of the isosurface (the evaluated-count debug view on a black
# background; the count is R + 256 G) against the lights that really reach it (B).
view.Background = [0.0, 0.0, 0.0]
view.DebugView = "Evaluated count"
counts_path = os.path.join(args.output, "evaluated-np%d.png" % ranks)
SaveScreenshot(counts_path, view, ImageResolution=args.size, TransparentBackground=0)
reader = vtkPNGReader()
reader.SetFileName(counts_path)
reader.Update()
counts = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(numpy.int64)
surface_pixels = counts.sum(axis=1) > 0
evaluated = float((counts[surface_pixels, 0] + 256 * counts[surface_pixels, 1]).mean())
reaching = float(counts[surface_pixels, 2].mean())
view.DebugView = "None"
view.Background = [0.02, 0.02, 0.03]
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
camera.Azimuth(2.0 * (args.frames + 1))
Render(view)

image = os.path.join(args.output, "paraview-scale-demo-np%d.png" % ranks)
SaveScreenshot(image, view, ImageResolution=args.size, TransparentBackground=0)

# The stock render view of the same isosurface (light kit), same camera: how much
# ParaView's own image of it changes with the number of ranks.
stock = CreateView("RenderView")
stock.ViewSize = args.size
stock.OrientationAxesVisibility = 0
stock.UseColorPaletteForBackground = 0
stock.Background = [0.02, 0.02, 0.03]
stock_display = Show(surface, stock)
stock_display.ColorArrayName = ["POINTS", ""]
stock_display.DiffuseColor = [0.9, 0.9, 0.9]
Render(stock)
stock.CameraPosition = view.CameraPosition
stock.CameraFocalPoint = view.CameraFocalPoint
stock.CameraViewUp = view.CameraViewUp
stock.CameraViewAngle = view.CameraViewAngle
stock_image = os.path.join(args.output, "stock-np%d.png" % ranks)
SaveScreenshot(stock_image, stock, ImageResolution=args.size, TransparentBackground=0)
Delete(stock)


def read(path):
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    return vtk_to_numpy(png.GetOutput().GetPointData().GetScalars())[:, :3].astype(numpy.int64)


def against_one_rank(path, name):
    """Largest channel difference and pixels differing by more than 1 from the 1-rank
    run's image, if there is one ("-" otherwise)."""
    reference = os.path.join(args.output, name + "-np1.png")
    if ranks == 1 or not os.path.exists(reference):
        return "-", "-"
    d = numpy.abs(read(path) - read(reference)).max(axis=1)
    return str(int(d.max())), str(int((d > 1).sum()))


diff_max, diff_pixels = against_one_rank(image, "paraview-scale-demo")
stock_diff_max, stock_diff_pixels = against_one_rank(stock_image, "stock")
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
      "assignment_ms=%.1f shading_ms=%.1f evaluated_per_pixel=%.1f reaching_per_pixel=%.1f "
      "unlit_frame_ms_median=%.1f diff_max=%s diff_pixels=%s stock_diff_max=%s "
      "stock_diff_pixels=%s image=%s"
      % (ranks, points, triangles, clustered, assigned, updates, pipeline_seconds, first,
         1000 * statistics.median(times), 1000 * min(times), assignment_ms, shading_ms,
         evaluated, reaching, 1000 * statistics.median(unlit_times), diff_max, diff_pixels,
         stock_diff_max, stock_diff_pixels, image))
