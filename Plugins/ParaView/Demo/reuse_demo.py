"""Still frames in ParaView: the depth prepass reused against drawn, side by side.

Scene: the scale demonstration's isosurface (the Wavelet source on a 201^3 grid, about
555,000 triangles, solid color) lit by 4,096 clustered lights (the cell centers of a
16 x 16 x 16-cell Wavelet grid spread over the isosurface's box, attenuation (1, 0, 0.12),
radius 12, windowed falloff), the Clustered Lighting view at --size, light kit off, the
prepass drawn in every frame (Automatic Depth Prepass off), the camera still.

Two kinds of still frames, as an interactive session makes them: the scene re-rendered
unchanged, and every light's intensity changed before each frame (what editing lights
does: the lights are uploaded and assigned again, the geometry is not touched). Each kind
is timed with Reuse Depth Prepass on and off in alternating rounds (--rounds, --frames
Render() calls each, after one untimed frame), so both see the same machine; prints the
median frame of each and their ratio, and checks that the reused frames did reuse.
Usage: pvbatch reuse_demo.py --plugin ClusteredLighting.so [--frames N] [--rounds N]
"""

import argparse
import statistics
import time

from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--plugin", required=True)
parser.add_argument("--frames", type=int, default=5)
parser.add_argument("--rounds", type=int, default=3)
parser.add_argument("--size", type=int, nargs=2, default=[1024, 768])
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())


def info(proxy, name):
    proxy.UpdatePropertyInformation()
    return vtkSMPropertyHelper(proxy.SMProxy, name).GetAsDouble(0)


wavelet = Wavelet(WholeExtent=[-100, 100, -100, 100, -100, 100])
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[180.0])
surface.ComputeScalars = 0
surface.UpdatePipeline()
triangles = surface.GetDataInformation().GetNumberOfCells()

grid = Wavelet(WholeExtent=[0, 16, 0, 16, 0, 16])
centers = CellCenters(Input=grid)
placed = Calculator(Input=centers, CoordinateResults=1,
                    Function="(12*coordsX-96)*iHat+(12*coordsY-96)*jHat+(12*coordsZ-96)*kHat")

view = CreateView("ClusteredLightingView")
view.ViewSize = args.size
view.UseLight = 0
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.02, 0.02, 0.03]
view.Falloff = "Windowed"
view.AutomaticDepthPrepass = 0
view.DepthPrepass = 1
surface_display = Show(surface, view)
surface_display.ColorArrayName = ["POINTS", ""]
surface_display.DiffuseColor = [0.9, 0.9, 0.9]
lights = Show(placed, view)
lights.Representation = "Clustered Lights"
lights.LightDefaultIntensity = 1.0
lights.LightDefaultAttenuation = [1.0, 0.0, 0.12]
lights.LightDefaultRadius = 12.0
Render(view)
view.CameraPosition = [230.0, -290.0, 190.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
Render(view)
clustered = int(info(view, "NumberOfClusteredLights"))


def unchanged(frame):
    pass


def lights_edited(frame):
    lights.LightDefaultIntensity = 1.0 + 0.01 * (frame % 2)


times = {}
reused = {}
for rnd in range(args.rounds):
    for kind, change in (("unchanged", unchanged), ("lights edited", lights_edited)):
        for reuse in ((1, 0) if rnd % 2 == 0 else (0, 1)):
            view.ReuseDepthPrepass = reuse
            change(1)
            Render(view)  # untimed: draws (and keeps) the prepass once
            for frame in range(args.frames):
                change(frame)
                start = time.perf_counter()
                Render(view)
                times.setdefault((kind, reuse), []).append(time.perf_counter() - start)
                reused.setdefault((kind, reuse), []).append(info(view, "DepthPrepassReused"))

print("isosurface triangles: %d, clustered lights: %d, %d x %d, %d rounds of %d frames"
      % (triangles, clustered, args.size[0], args.size[1], args.rounds, args.frames))
print("| still frame | reuse on (ms) | reuse off (ms) | on / off | frames that reused (on, off) |")
print("|---|---:|---:|---:|---|")
ok = True
for kind in ("unchanged", "lights edited"):
    on = 1000.0 * statistics.median(times[(kind, 1)])
    off = 1000.0 * statistics.median(times[(kind, 0)])
    n_on = int(sum(reused[(kind, 1)]))
    n_off = int(sum(reused[(kind, 0)]))
    print("| %s | %.1f | %.1f | %.2f | %d of %d, %d of %d |"
          % (kind, on, off, on / off, n_on, len(reused[(kind, 1)]), n_off, len(reused[(kind, 0)])))
    ok = ok and n_on == len(reused[(kind, 1)]) and n_off == 0
if not ok:
    raise AssertionError("a frame with the reuse on drew its prepass, or one without reused")
