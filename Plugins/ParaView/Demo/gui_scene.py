"""Scene for the screenshot of the ParaView GUI (scripts/make-paraview-screenshot.sh).

Run by `paraview --script` (connected to pvserver or not): loads the plugin on the server
and on the client, replaces the layout's render view by a Clustered Lighting view, shows an
isosurface of the Wavelet source and 16,384 lights fed from a pipeline (cell centers of a
Wavelet grid, colors from a Calculator) with the Clustered Lights representation, adds
two positional lights as the Light Inspector does, selects the lights' source so that the
Properties panel shows the representation's and the view's properties, and writes the
file named by CLUSTERED_LIGHTING_READY when done.
"""

import os

from paraview.simple import *  # noqa: F401,F403

plugin = os.environ["CLUSTERED_LIGHTING_PLUGIN"]
LoadPlugin(plugin, remote=True, ns=globals())
if servermanager.ActiveConnection.IsRemote():
    LoadPlugin(plugin, remote=False, ns=globals())

layout = GetLayout()
stock = GetActiveView()
view = CreateView("ClusteredLightingView")
if stock:
    Delete(stock)
AssignViewToLayout(view=view, layout=layout, hint=0)
view.OrientationAxesVisibility = 1
view.UseColorPaletteForBackground = 0
view.Background = [0.02, 0.02, 0.03]
view.UseLight = 0
view.Falloff = "Windowed"

wavelet = Wavelet(WholeExtent=[-60, 60, -60, 60, -60, 60])
RenameSource("Wavelet", wavelet)
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[180.0])
surface.ComputeScalars = 0
RenameSource("Isosurface", surface)
surface_display = Show(surface, view)
surface_display.ColorArrayName = ["POINTS", ""]
surface_display.DiffuseColor = [0.9, 0.9, 0.9]

grid = Wavelet(WholeExtent=[0, 32, 0, 32, 0, 16])
RenameSource("Light grid", grid)
centers = CellCenters(Input=grid)
placed = Calculator(Input=centers, CoordinateResults=1,
                    Function="(3.6*coordsX-57.6)*iHat+(3.6*coordsY-57.6)*jHat"
                             "+(7.2*coordsZ-57.6)*kHat")
RenameSource("Light positions", placed)
colors = Calculator(Input=placed, ResultArrayName="Color",
                    Function="(0.55+0.45*sin(coordsX/13))*iHat+(0.55+0.45*sin(coordsY/11+2))*jHat"
                             "+(0.55+0.45*sin(coordsZ/17+4))*kHat")
RenameSource("Lights", colors)
lights = Show(colors, view)
lights.Representation = "Clustered Lights"
lights.LightDefaultIntensity = 1.5
lights.LightDefaultAttenuation = [1.0, 0.0, 0.15]
lights.LightDefaultRadius = 4.0

for position, color in (([-70.0, -70.0, 40.0], [1.0, 0.9, 0.8]), ([70.0, -40.0, -30.0], [0.5, 0.6, 1.0])):
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Positional"
    light.Position = position
    light.DiffuseColor = color
    light.Intensity = 0.35

view.CameraPosition = [150.0, -190.0, 120.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
SetActiveView(view)
SetActiveSource(colors)
Render(view)
view.CameraPosition = [150.0, -190.0, 120.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
Render(view)

ready = os.environ.get("CLUSTERED_LIGHTING_READY")
if ready:
    with open(ready, "w") as f:
        f.write("ready\n")
