#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The props VTK apps show besides plain surfaces, under the pass.

Each scene is rendered by stock VTK and under the pass, with the headlight alone and with
two positional vtkLights (which the pass clusters): points drawn as spheres and lines as
tubes (impostors that write their own depth), point Gaussian splats, an image actor,
texture-mapped and colour-mapped surfaces, text, a scalar bar and cube axes. Checks:
 1. the pass's image equals stock VTK's within one 8-bit step (clustered shading against
    VTK's own, float sums in another order), and the two positional lights change the
    image of every lit scene (image actors and Gaussian splats are unlit in VTK), so the
    comparison compares clustered shading;
 2. the pass clusters the 2 positional lights;
 3. nothing reaches VTK's output window as an error (a shader that fails to build there
    would; VTK's GPU volume ray caster did until 2026-11-28, see
    TestClusteredLightingVolumes);
 4. the third, still frame copies the depth prepass back (ReuseDepthPrepass) where every
    prop allows it: plain surfaces, textured or colour-mapped, and beside them overlays
    that write no depth (text, a scalar bar, a corner annotation, a 2D actor), the image
    the same as with the reuse off; the second frame too, but where a mapper made its
    default lookup table in the first; cube axes make the frame draw and are named.
Exits with status 1 when a check failed.
"""

import sys

from clusteredlighting import vtkClusteredLightingPass
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkMath, vtkOutputWindow
from vtkmodules.vtkCommonCore import vtkStringOutputWindow
from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersExtraction import vtkExtractEdges
from vtkmodules.vtkFiltersSources import (
    vtkPlaneSource,
    vtkPointSource,
    vtkSphereSource,
    vtkTexturedSphereSource,
)
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkImagingSources import vtkImageCanvasSource2D
from vtkmodules.vtkRenderingAnnotation import (
    vtkCornerAnnotation,
    vtkCubeAxesActor,
    vtkScalarBarActor,
)
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkActor2D,
    vtkImageActor,
    vtkLight,
    vtkPointGaussianMapper,
    vtkPolyDataMapper,
    vtkPolyDataMapper2D,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkTexture,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL classes)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)

WIDTH, HEIGHT = 200, 150
FAILURES = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        FAILURES.append(what)


def surface(ren, source, configure=None):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    if configure:
        configure(actor, mapper)
    ren.AddActor(actor)
    return actor


def sphere(radius=3.0):
    s = vtkSphereSource()
    s.SetRadius(radius)
    s.SetThetaResolution(24)
    s.SetPhiResolution(16)
    return s


def points():
    s = vtkPointSource()
    s.SetNumberOfPoints(200)
    s.SetRadius(3.0)
    return s


def points_as_spheres(ren):
    def configure(actor, mapper):
        actor.GetProperty().SetRenderPointsAsSpheres(True)
        actor.GetProperty().SetPointSize(12)
    surface(ren, points(), configure)


def lines_as_tubes(ren):
    source = sphere()  # held here: a port of a source nobody holds would dangle
    edges = vtkExtractEdges()
    edges.SetInputConnection(source.GetOutputPort())

    def configure(actor, mapper):
        actor.GetProperty().SetRenderLinesAsTubes(True)
        actor.GetProperty().SetLineWidth(6)
    surface(ren, edges, configure)


def point_gaussian(ren):
    source = points()
    mapper = vtkPointGaussianMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.SetScaleFactor(0.3)
    actor = vtkActor()
    actor.SetMapper(mapper)
    ren.AddActor(actor)


def image_actor(ren):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, 0, 0)
    actor = vtkImageActor()
    actor.GetMapper().SetInputConnection(source.GetOutputPort())
    ren.AddActor(actor)


def textured(ren):
    source = vtkTexturedSphereSource()
    source.SetRadius(3.0)
    image = vtkImageCanvasSource2D()
    image.SetExtent(0, 63, 0, 63, 0, 0)
    image.SetScalarTypeToUnsignedChar()
    image.SetNumberOfScalarComponents(3)
    image.SetDrawColor(200, 100, 50)
    image.FillBox(0, 63, 0, 63)
    image.SetDrawColor(50, 200, 100)
    image.FillBox(0, 31, 0, 31)
    texture = vtkTexture()
    texture.SetInputConnection(image.GetOutputPort())
    surface(ren, source, lambda actor, mapper: actor.SetTexture(texture))


def colour_mapped(ren):
    source = sphere()
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(source.GetOutputPort())
    surface(ren, elevation, lambda actor, mapper: mapper.InterpolateScalarsBeforeMappingOn())


def text_and_scalar_bar(ren):
    text = vtkTextActor()
    text.SetInput("clustered")
    ren.AddActor2D(text)
    lut = vtkLookupTable()
    lut.Build()
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    ren.AddActor2D(bar)


def annotations(ren):
    actor = surface(ren, sphere())
    text_and_scalar_bar(ren)
    axes = vtkCubeAxesActor()
    axes.SetBounds(actor.GetBounds())
    axes.SetCamera(ren.GetActiveCamera())
    ren.AddActor(axes)


def overlays(ren):
    surface(ren, sphere())
    text_and_scalar_bar(ren)
    corner = vtkCornerAnnotation()
    corner.SetText(2, "still")
    ren.AddViewProp(corner)
    rectangle = vtkPlaneSource()  # in viewport pixels (no transform coordinate)
    rectangle.SetOrigin(10, 10, 0)
    rectangle.SetPoint1(50, 10, 0)
    rectangle.SetPoint2(10, 30, 0)
    mapper = vtkPolyDataMapper2D()
    mapper.SetInputConnection(rectangle.GetOutputPort())
    box = vtkActor2D()
    box.SetMapper(mapper)
    ren.AddActor2D(box)


def render(build, use_pass, positional, reuse=True):
    """The scene's pixels (rows x columns x RGB), the pass's clustered light count, and
    whether its second and third frames reused the depth prepass, each with the reason
    if not."""
    vtkMath.RandomSeed(7)  # the same random points in every window
    window = vtkRenderWindow()
    window.SetSize(WIDTH, HEIGHT)
    window.SetMultiSamples(0)
    ren = vtkRenderer()
    ren.SetBackground(0.05, 0.05, 0.08)
    window.AddRenderer(ren)
    build(ren)
    ren.ResetCamera()
    if positional:
        for position in ((-6.0, 4.0, 6.0), (6.0, -3.0, 6.0)):
            light = vtkLight()
            light.SetLightTypeToSceneLight()
            light.SetPositional(True)
            light.SetConeAngle(180.0)
            light.SetPosition(position)
            light.SetFocalPoint(0.0, 0.0, 0.0)
            ren.AddLight(light)
    clustered_pass = vtkClusteredLightingPass() if use_pass else None
    if clustered_pass:
        clustered_pass.SetReuseDepthPrepass(reuse)
        ren.SetPass(clustered_pass)
    # Three frames; whether the second and the third reused (read before the grab, which
    # renders again).
    reused = []
    for _ in range(3):
        window.Render()
        if clustered_pass:
            reused.append((clustered_pass.GetDepthPrepassReused(),
                           clustered_pass.GetDepthPrepassReuseProblem()))
    reused = reused[1:] if clustered_pass else None
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    pixels = pixels.reshape(HEIGHT, WIDTH, -1)[:, :, :3].astype(int)
    count = clustered_pass.GetNumberOfClusteredLights() if clustered_pass else None
    if clustered_pass:
        clustered_pass.ReleaseGraphicsResources(window)
    return pixels, count, reused


def main():
    output = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(output)
    scenes = [points_as_spheres, lines_as_tubes, point_gaussian, image_actor, textured,
              colour_mapped, annotations, overlays]
    for build in scenes:
        name = build.__name__
        stock_head, _, _ = render(build, False, False)
        for positional in (False, True):
            stock, _, _ = render(build, False, positional)
            clustered, count, ((second, _), (reused, problem)) = render(build, True, positional)
            worst = int(abs(stock - clustered).max())
            lights = "two positional lights" if positional else "headlight"
            check(worst <= 1, "%s, %s: within 1 step of stock VTK (max %d)" % (name, lights, worst))
            if positional:
                check(count == 2, "%s: the pass clusters the 2 positional lights (%d)" % (name, count))
                lit = int((abs(stock - stock_head).max(axis=2) > 8).sum())
                if name not in ("image_actor", "point_gaussian"):  # unlit in VTK too
                    check(lit > 500, "%s: the positional lights change %d pixels" % (name, lit))
                if name in ("textured", "colour_mapped", "overlays"):
                    check(reused, "%s: the third, still frame reuses the depth prepass (%s)"
                          % (name, problem))
                    # The first frame makes the property (and keys) every actor gets then,
                    # which the signature makes beforehand, so the second reuses; not so
                    # a mapper's default lookup table, made when it first maps scalars.
                    check(second == (name != "colour_mapped"),
                          "%s: the second frame %s" % (name, "draws (the mapper's lookup "
                          "table is new)" if name == "colour_mapped" else "reuses too"))
                    drawn, _, (_, (again, _)) = render(build, True, positional, reuse=False)
                    same = int(abs(clustered - drawn).max())
                    check(not again and same == 0,
                          "%s: the same image with the prepass drawn (max %d)" % (name, same))
                if name == "annotations":
                    check(not reused and "vtkCubeAxesActor" in problem,
                          "%s: cube axes make the frame draw its prepass (%s)" % (name, problem))
    errors = [line for line in output.GetOutput().splitlines() if "ERROR" in line]
    check(not errors, "no error in VTK's output window: %s" % (errors[:3],))
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        sys.exit(1)


if __name__ == "__main__":
    main()
