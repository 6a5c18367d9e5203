"""Selections in the Clustered Lighting view match the stock RenderView's.

ParaView selects with a hardware selector: the view renders ids instead of light. Until
2026-11-28 the pass rendered such a frame as a lit one in a plain VTK renderer, and every
selection came back empty there; this test keeps ParaView's selections working through
the plugin's view too.

Scene, the same in both views: a distributed Sphere source, a translucent sphere in
front of it (opacity 0.4: depth peeling), two positional lights (AddLight), and in the
Clustered Lighting view 500 clustered lights from a point cloud as well.

Checks, on every rank count:
 - the pass clustered the lights (the view renders through it);
 - SelectSurfaceCells and SelectSurfacePoints over the whole view and over a small
   rectangle (where the glass covers the body) select the same number of cells or points
   of each sphere in both views, and some;
 - the view renders the same image after the selections as before them;
 - on N > 1 ranks, without the glass, the image equals the 1-rank image within one 8-bit
   step: every rank's far field covers the bounds of the whole data (the view sets them as
   the pass's FarFieldRegion), not those of its own piece. (With the glass the stock
   view's image changes with the split too: ParaView composites the translucent pieces in
   another order.)
"""

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

import clustered_test as t

t.setup(__doc__, reference=True)

body = Sphere(Radius=10.0, ThetaResolution=64, PhiResolution=32)
glass = Sphere(Radius=5.0, Center=[6.0, -9.0, 4.0], ThetaResolution=48, PhiResolution=24)
cloud = PointSource(NumberOfPoints=500, Radius=14.0)


def make_view(kind):
    view = CreateView(kind)
    view.ViewSize = [400, 300]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.12]
    view.UseLight = 0
    Show(body, view).ColorArrayName = ["POINTS", ""]
    glass_display = Show(glass, view)
    glass_display.ColorArrayName = ["POINTS", ""]
    glass_display.Opacity = 0.4
    for position in ([-14.0, -12.0, 10.0], [15.0, -6.0, -8.0]):
        light = AddLight(view=view)
        light.Coords = "Scene"
        light.Type = "Positional"
        light.Position = position
        light.ConeAngle = 180.0
    return view


def set_camera(view):
    view.CameraPosition = [10.0, -45.0, 18.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0


stock = make_view("RenderView")
clustered = make_view("ClusteredLightingView")
lights = Show(cloud, clustered)
lights.Representation = "Clustered Lights"
lights.LightDefaultIntensity = 0.05
lights.LightDefaultAttenuation = [1.0, 0.0, 0.05]
for view in (stock, clustered):
    Render(view)  # paraview.simple resets the camera at a view's first Render()
    set_camera(view)
stock_before = t.save(stock, t.output("selection-stock"))

before = t.save(clustered, t.output("selection-before"))
count = t.info(clustered, "NumberOfClusteredLights")
t.check(count == 502, "the pass clustered %d lights (502 expected)" % count)


def selected(view, kind, rectangle):
    """Number of cells (or points) of each sphere a surface selection selects."""
    counts = []
    for source in (body, glass):
        ClearSelection(source)
    if kind == "cells":
        SelectSurfaceCells(Rectangle=rectangle, View=view)
    else:
        SelectSurfacePoints(Rectangle=rectangle, View=view)
    for source in (body, glass):
        selection = source.SMProxy.GetSelectionInput(0)
        if selection is None:
            counts.append(0)
            continue
        extract = ExtractSelection(Input=source,
                                   Selection=servermanager._getPyProxy(selection))
        extract.UpdatePipeline()
        info = extract.GetDataInformation()
        counts.append(info.GetNumberOfCells() if kind == "cells" else info.GetNumberOfPoints())
        Delete(extract)
        ClearSelection(source)
    return counts


for kind in ("cells", "points"):
    for name, rectangle in (("the whole view", [0, 0, 399, 299]),
                            ("a small rectangle", [180, 110, 260, 170])):
        a = selected(stock, kind, rectangle)
        b = selected(clustered, kind, rectangle)
        t.check(a == b and sum(a) > 0,
                "%s, %s: body and glass %s in the stock view, %s in the Clustered Lighting "
                "view" % (kind, name, a, b))

stock_after = t.save(stock, t.output("selection-stock-after"))
t.check(t.difference(stock_before, stock_after)["max"] == 0,
        "the stock view's image after the selections: the same as before")
after = t.save(clustered, t.output("selection-after"))
d = t.difference(before, after)
t.check(d["max"] == 0, "the image after the selections: max difference %d step(s) from before"
        % d["max"])

# Across rank counts, without the glass (ParaView composites translucent pieces in an
# order that changes with the split: the stock view's image changes by up to 50 steps).
for view in (stock, clustered):
    Hide(glass, view)
opaque = t.save(clustered, t.output("selection-opaque"))
opaque_stock = t.save(stock, t.output("selection-opaque-stock"))
if t.args.reference:
    for name, image in (("selection-opaque", opaque), ("selection-opaque-stock", opaque_stock)):
        d = t.difference(image, t.read(t.args.reference + "/%s-np1.png" % name))
        t.check(d["max"] <= 1, "%s view, no glass, against 1 rank: max difference %d step(s) "
                "(tolerance 1), %d pixels differ"
                % ("stock" if "stock" in name else "Clustered Lighting", d["max"],
                   d["pixels_differing"]))

t.finish()
