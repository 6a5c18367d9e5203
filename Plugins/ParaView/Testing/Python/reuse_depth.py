"""The view reuses its depth prepass on still frames of ParaView's own representations.

ParaView draws surfaces with vtkPVLODActor and vtkCompositePolyDataMapper2; the pass
copies the last frame's prepass depths back when nothing they depend on changed (the
actor's mapper choice, full or level of detail, the mapper's blocks and their display
attributes included) and draws the prepass again otherwise.

Scene: a multiblock of two spheres (Group Datasets: a distributed body and a moon) lit
by 448 clustered lights, the prepass drawn in every frame (Automatic Depth Prepass off).

Checks, on every rank count: after each change the frame draws or reuses as expected,
its depths are kept for the next frame (no reason given), and the image equals the one
rendered with Reuse Depth Prepass off, exactly:
 - still frames reuse;
 - the body's source changed, the moon hidden by the block selectors (the display
   attributes of a block), shown again, the camera turned, the center axes shown: the
   frame draws (and the next reuses);
 - an interactive render with level of detail (LOD threshold 0: the actor draws its
   decimated mapper) draws, and so does the still render after it (the full mapper),
   whose image equals the one without reuse;
 - hiding the moon changes the image (the check could fail).
"""

from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper

import clustered_test as t

t.setup(__doc__)

body = Sphere(Radius=10.0, ThetaResolution=128, PhiResolution=64)
moon = Sphere(Radius=3.0, Center=[9.0, -12.0, 6.0], ThetaResolution=48, PhiResolution=24)
group = GroupDatasets(Input=[body, moon])
group.BlockNames = ["Body", "Moon"]

view = CreateView("ClusteredLightingView")
view.ViewSize = [320, 240]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.08, 0.08, 0.1]
view.CameraPosition = [28.0, -40.0, 22.0]
view.CameraFocalPoint = [2.0, -2.0, 1.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
view.UseLight = 0
view.Falloff = "Windowed"
view.AutomaticDepthPrepass = 0
view.DepthPrepass = 1
display = Show(group, view)
display.ColorArrayName = ["POINTS", ""]
display.DiffuseColor = [0.85, 0.85, 0.85]

light_sphere = Sphere(Radius=15.0, ThetaResolution=16, PhiResolution=16)
lights = Show(CellCenters(Input=light_sphere), view)
lights.Representation = "Clustered Lights"
lights.LightDefaultIntensity = 0.8
lights.LightDefaultAttenuation = [1.0, 0.0, 0.4]
lights.LightDefaultRadius = 4.0

Render(view)
Render(view)


def problem():
    view.UpdatePropertyInformation()
    return vtkSMPropertyHelper(view.SMProxy, "DepthPrepassReuseProblem").GetAsString(0)


def frame(what, reuse, change, render=Render):
    """Renders after change() and checks the reuse and the image against the reuse off."""
    change()
    render(view)
    used = t.info(view, "DepthPrepassUsed") == 1
    reused = t.info(view, "DepthPrepassReused") == 1
    kept = t.info(view, "DepthPrepassKept") == 1
    why = problem()
    image = t.save(view, t.output("reuse-depth"))
    view.ReuseDepthPrepass = 0
    reference = t.save(view, t.output("reuse-depth-off"))
    view.ReuseDepthPrepass = 1
    Render(view)  # draws and keeps the depths again
    t.check(used and reused == reuse,
            "%s: %s" % (what, "the last depths are copied back" if reuse
                        else "the prepass draws again"))
    t.check(kept and why == "",
            "%s: the depths are kept for the next frame%s" % (what, " (not: %s)" % why if why else ""))
    d = t.difference(image, reference)
    t.check(d["max"] == 0, "%s: the same image as without reuse (max difference %d, %d pixels "
            "differ)" % (what, d["max"], d["pixels_differing"]))
    return image


def turn():
    camera = GetActiveCamera()
    camera.Azimuth(6.0)


def still():
    pass


def set_body_radius():
    body.Radius = 9.0


def hide_moon():
    display.BlockSelectors = ["/Root/Body"]


def show_moon():
    display.BlockSelectors = ["/"]


def show_center_axes():
    view.CenterAxesVisibility = 1


def hide_center_axes():
    view.CenterAxesVisibility = 0


both = frame("still frame", True, still)
frame("second still frame", True, still)
frame("body's source changed", False, set_body_radius)
frame("still after the change", True, still)
without = frame("moon hidden by the block selectors", False, hide_moon)
d = t.difference(both, without)
t.check(d["pixels_differing"] > 100,
        "hiding the moon changes the image (%d pixels differ)" % d["pixels_differing"])
frame("still without the moon", True, still)
frame("moon shown again", False, show_moon)
frame("camera turned", False, turn)
frame("still after the turn", True, still)
frame("center axes shown", False, show_center_axes)
frame("still with the center axes", True, still)
frame("center axes hidden", False, hide_center_axes)
view.LODThreshold = 0.0  # interactive renders draw the decimated geometry
frame("level of detail on, still frame", True, still)
view.InteractiveRender()
t.check(t.info(view, "DepthPrepassUsed") == 1 and t.info(view, "DepthPrepassReused") == 0,
        "interactive render (the level-of-detail mapper): the prepass draws again")
frame("still render after it (the full mapper)", False, still, render=lambda v: v.StillRender())

t.finish()
