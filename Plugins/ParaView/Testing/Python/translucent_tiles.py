"""A translucent representation keeps depth-aware clusters everywhere but where it is.

With depth-aware clusters each tile's clusters are cut to the depths of its visible
opaque fragments; a translucent fragment lies in front of them, so the tiles a
translucent prop may cover keep wide clusters. ParaView draws its surfaces with
vtkPVLODActor, which until 2026-11-29 the pass could not bound: one translucent
representation widened every tile of the view. Now its box (the bounds of the mapper it
draws in this render, full or level of detail, under its matrix) is projected to the
screen and only the tiles near that rectangle stay wide.

Scene: an opaque floor and body, a small glass sphere (opacity 0.4, depth peeling; moved
by its display's Position) near one corner of the view, 576 clustered lights 3 units over the floor (radius 4, windowed falloff),
the depth prepass in every frame (Automatic Depth Prepass off).

Checks, on every rank count (the counts are rank 0's, over its own pieces):
 - with the glass translucent, depth-aware clusters are used and the image equals the one
   rendered with them off, bit for bit (no light lost where the glass is), and as many
   lights reach a pixel on average with them as without;
 - on 1 rank: lights evaluated per pixel (heat map) glass opaque <= translucent < off
   (measured 19.30, 19.44, 35.17; with every tile wide, as before, 20.26), and away from
   the glass (more than 3 tiles from any pixel it changes) the Evaluated count view is
   the same, pixel for pixel, with the glass translucent as opaque (with every tile wide:
   27,718 of 91,384 pixels differ). On N > 1 ranks ParaView redistributes the data when a
   representation turns translucent, so those two frames hold other pieces per rank;
 - an interactive render with level of detail (LOD threshold 0: the actor draws its
   decimated mapper) uses depth-aware clusters, evaluates fewer lights per pixel than
   without them, and counts as many reaching.
"""

from paraview.simple import *  # noqa: F401,F403

import numpy

import clustered_test as t

t.setup(__doc__)

floor = Plane(Origin=[-20.0, -20.0, 0.0], Point1=[20.0, -20.0, 0.0], Point2=[-20.0, 20.0, 0.0],
              XResolution=40, YResolution=40)
body = Sphere(Radius=4.0, Center=[0.0, 0.0, 4.0], ThetaResolution=64, PhiResolution=32)
# The glass's source is 2 units to the left of where its display's Position puts it: its
# box must be taken under the actor's matrix.
glass = Sphere(Radius=2.5, Center=[-10.0, -9.0, 3.0], ThetaResolution=48, PhiResolution=24)
grid = Plane(Origin=[-18.0, -18.0, 3.0], Point1=[18.0, -18.0, 3.0], Point2=[-18.0, 18.0, 3.0],
             XResolution=24, YResolution=24)

view = CreateView("ClusteredLightingView")
view.ViewSize = [400, 300]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.08, 0.08, 0.1]
view.UseLight = 0
view.Falloff = "Windowed"
view.AutomaticDepthPrepass = 0
view.DepthPrepass = 1
view.DepthAwareClusters = 1
view.UseFXAA = 0
for source in (floor, body):
    display = Show(source, view)
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [0.85, 0.85, 0.85]
glass_display = Show(glass, view)
glass_display.ColorArrayName = ["POINTS", ""]
glass_display.DiffuseColor = [0.9, 0.5, 0.3]
glass_display.Opacity = 0.4
glass_display.Position = [2.0, 0.0, 0.0]

lights = Show(CellCenters(Input=grid), view)
lights.Representation = "Clustered Lights"
lights.LightDefaultIntensity = 0.8
lights.LightDefaultAttenuation = [1.0, 0.0, 0.3]
lights.LightDefaultRadius = 4.0
# After the first render, which resets the camera.
Render(view)
view.CameraPosition = [0.0, -30.0, 16.0]
view.CameraFocalPoint = [0.0, -2.0, 2.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 40.0

Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 576,
        "the pass clustered %d lights (576 expected)" % t.info(view, "NumberOfClusteredLights"))


def counts(what, depth_aware, opacity, render=Render):
    """Lights evaluated and reaching per pixel of rank 0 (heat map), and whether the
    render used depth-aware clusters."""
    view.DepthAwareClusters = depth_aware
    glass_display.Opacity = opacity
    view.DebugView = "Heat map"
    render(view)
    evaluated, reaching = t.light_counts(view)
    used = t.info(view, "DepthAwareClustersUsed") == 1
    view.DebugView = "None"
    print("%s: %.3f lights evaluated, %.3f reaching per pixel, depth-aware clusters %s"
          % (what, evaluated, reaching, "used" if used else "not used"))
    return evaluated, reaching, used


def evaluated_counts(name, opacity):
    """Lights evaluated at each pixel with depth-aware clusters (the Evaluated count view:
    R + 256 G)."""
    glass_display.Opacity = opacity
    view.DepthAwareClusters = 1
    view.DebugView = "Evaluated count"
    image = t.save(view, t.output(name)).astype(numpy.int32)
    view.DebugView = "None"
    t.check(t.info(view, "DepthAwareClustersUsed") == 1,
            "%s: depth-aware clusters used" % name)
    return image[:, :, 0] + 256 * image[:, :, 1]


# The shaded image, depth-aware clusters on and off.
view.DepthAwareClusters = 1
on = t.save(view, t.output("translucent-tiles"))
t.check(t.info(view, "DepthPrepassUsed") == 1 and t.info(view, "DepthAwareClustersUsed") == 1,
        "glass translucent: the prepass drawn and depth-aware clusters used")
view.DepthAwareClusters = 0
off = t.save(view, t.output("translucent-tiles-off"))
d = t.difference(on, off)
t.check(d["max"] == 0, "glass translucent: the same image with depth-aware clusters off "
        "(max difference %d, %d pixels differ)" % (d["max"], d["pixels_differing"]))
lit = int((on.max(axis=2) > 40).sum())
t.check(lit > 0.2 * d["pixels"], "lit pixels: %d of %d (more than 20%% expected)"
        % (lit, d["pixels"]))

translucent = counts("glass translucent", 1, 0.4)
opaque = counts("glass opaque", 1, 1.0)
wide = counts("glass translucent, depth-aware clusters off", 0, 0.4)
t.check(translucent[2] and opaque[2] and not wide[2],
        "depth-aware clusters used where on (translucent and opaque glass), not where off")
t.check(translucent[1] == wide[1],
        "as many lights reach a pixel with depth-aware clusters on as off (%.4f and %.4f)"
        % (translucent[1], wide[1]))
# On N > 1 ranks ParaView redistributes the data when a representation turns translucent
# (ordered compositing): each rank then holds other pieces, and only 1 rank compares the
# glass translucent with the glass opaque.
if t.ranks() == 1:
    t.check(opaque[0] <= translucent[0] < wide[0],
            "lights evaluated per pixel: glass opaque %.3f, translucent %.3f, depth-aware clusters "
            "off %.3f (in this order)" % (opaque[0], translucent[0], wide[0]))
    # Where the glass is: the pixels it changes, and every pixel within 3 tiles of them.
    Hide(glass, view)
    hidden = t.save(view, t.output("translucent-tiles-no-glass"))
    Show(glass, view)
    footprint = numpy.argwhere(t.pixel_difference(on, hidden) > 0)
    height, width = on.shape[:2]
    margin = (3 * height // view.TilesY, 3 * width // view.TilesX)
    near_glass = numpy.zeros((height, width), dtype=bool)
    near_glass[max(0, footprint[:, 0].min() - margin[0]):footprint[:, 0].max() + margin[0] + 1,
               max(0, footprint[:, 1].min() - margin[1]):footprint[:, 1].max() + margin[1] + 1] = True
    with_opaque = evaluated_counts("translucent-tiles-count-opaque", 1.0)
    with_translucent = evaluated_counts("translucent-tiles-count", 0.4)
    away = ~near_glass
    differ = int((with_opaque[away] != with_translucent[away]).sum())
    t.check(len(footprint) > 500 and away.sum() > 0.5 * away.size and differ == 0,
            "away from the glass (%d of %d pixels, the glass changes %d), the lights evaluated at "
            "each pixel are the same with the glass translucent as opaque (%d pixels differ; "
            "mean %.3f and %.3f)" % (away.sum(), away.size, len(footprint), differ,
                                      with_translucent[away].mean(), with_opaque[away].mean()))

# Level of detail: interactive renders draw the decimated mapper.
view.LODThreshold = 0.0
lod = counts("glass translucent, level of detail", 1, 0.4, render=lambda v: v.InteractiveRender())
t.check(lod[2], "interactive render (the level-of-detail mapper): depth-aware clusters used")
lod_off = counts("glass translucent, level of detail, depth-aware clusters off", 0, 0.4,
                 render=lambda v: v.InteractiveRender())
t.check(lod[1] == lod_off[1] and lod[0] < lod_off[0],
        "level of detail: as many lights reach a pixel (%.4f and %.4f), fewer evaluated "
        "(%.3f against %.3f)" % (lod[1], lod_off[1], lod[0], lod_off[0]))

t.finish()
