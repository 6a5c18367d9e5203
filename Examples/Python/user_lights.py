#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Lights as a new user writes them, clustered against brute force.

2,000 white point lights from a vtkPointSource (a ball of radius 3 around a sphere on
a floor), VTK's inverse-square attenuation (1, 0, 8), no radius, 400x300: the kind of
scene of issue 11 that the benchmark does not contain. At intensity 1 so many lights
saturate every pixel (both images are white, which shows nothing), so the default
intensity is 0.02 (--intensity): each light alone is still brighter than one 8-bit step
up to about 0.7 away, and their sum lights the scene without saturating it. Renders it with the
pass's defaults (far field on), with the far field off, and with brute force (every
light, exact); prints each frame time and the clustered images' error against brute
force in 8-bit steps and writes the three images. Exits with status 1 if the far field
does not bring the image closer to brute force. --pbr METALLIC (and --roughness) makes
both actors PBR. --budget STEPS (repeatable) also renders with that ErrorBudgetInSteps,
writes its image and prints the cutoffs and the far field's resolution it chose and its
stated bound. --spots FRACTION makes that fraction of the lights spot lights (split by
the far field like the others since 2026-11-30, at their cutoff radius, cones included;
--cone DEGREES sets their cone angle, 60 by default); --cone-culling-off also renders with
SpotConeCulling off (spot lights assigned by their spheres) and exits with status 1 if
its image is not the default's, bit for bit; --hidden-cost also renders with
AutomaticBackfaceCulling off (the pass culls the closed ball's back faces by default; off,
it draws them as VTK does) and prints what those hidden faces cost (llvmpipe runs the
fragment shader for fragments that fail the depth test) and how many pixels differ (at the
rim, where front and back faces meet at one depth, a drawn back face may win a sample);
it exits with status 1 unless the ball alone was culled and at most 0.1% of the pixels
differ;
--animate FRAMES then renders FRAMES frames in which every light moves (a small
translation each frame) and prints the median frame time, far-field build, light update
and assignment times (the first build of a still frame, which the default render's line
gives, also allocates the far field's buffers and textures);
--multisamples SAMPLES sets the window's MultiSamples (VTK's default, 8, when not given; in a
multisampled framebuffer the far field also sums the blocks that fragments shaded off their
surfaces read, FarFieldSkipEmptyBlocks: 0 shows what single-sampled builds cost);
--animate's line says how many blocks were summed.
--back-face-sums also renders with FarFieldExactSumsOnBackFaces on (the floor here is a
back face: vtkPlaneSource's normal points down). --specular-power POWER sets both actors'
specular power (20 by default; VTK's own default is 1) and --floor-specular SPECULAR the
floor's specular coefficient (0 by default; the sphere's is 0.5). --counts prints the
lights evaluated and reaching per pixel of each clustered render. The default render's
line also gives the far field's build time and how many lights it splits.

    PYTHONPATH=build/lib/python3/dist-packages \\
      scripts/with-display.sh /usr/bin/python3 Examples/Python/user_lights.py
"""

import argparse
import time

from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkPointSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import numpy


def add_actor(renderer, source, color, specular=0.0, pbr=None, power=20.0):
    """Adds an actor of source to renderer; returns it."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetSpecular(specular)
    actor.GetProperty().SetSpecularPower(power)
    if pbr is not None:  # (metallic, roughness)
        actor.GetProperty().SetInterpolationToPBR()
        actor.GetProperty().SetMetallic(pbr[0])
        actor.GetProperty().SetRoughness(pbr[1])
    renderer.AddActor(actor)
    return actor


def grab(window):
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.Update()
    data = image.GetOutput()
    w, h, _ = data.GetDimensions()
    pixels = vtk_to_numpy(data.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return image, pixels.astype(numpy.int32)


def write_png(image_filter, path):
    writer = vtkPNGWriter()
    writer.SetInputConnection(image_filter.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()


def light_counts(window, pass_):
    """Lights evaluated and reaching per pixel, from the pass's evaluated-count view."""
    pass_.SetDebugView(vtkClusteredLightingPass.DEBUG_EVALUATED_COUNT)
    window.Render()
    counts = (pass_.GetMeanLightsEvaluatedPerPixel(), pass_.GetMeanLightsReachingPerPixel())
    pass_.SetDebugView(vtkClusteredLightingPass.DEBUG_NONE)
    return counts


def timed_render(window, frames):
    window.Render()  # shaders, assignment, far field
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        times.append(1000.0 * (time.perf_counter() - start))
    return sorted(times)[len(times) // 2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lights", type=int, default=2000)
    parser.add_argument("--prefix", default="user-lights", help="prefix of the PNGs written")
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--intensity", type=float, default=0.02)
    parser.add_argument("--pbr", type=float, metavar="METALLIC",
                        help="PBR actors with this metallic factor (default: Phong)")
    parser.add_argument("--roughness", type=float, default=0.5, help="with --pbr")
    parser.add_argument("--budget", type=float, metavar="STEPS", action="append", default=[],
                        help="also render with ErrorBudgetInSteps STEPS (repeatable)")
    parser.add_argument("--spots", type=float, default=0.0, metavar="FRACTION",
                        help="make this fraction of the lights spot lights (cone 60 degrees, "
                        "pointing down; default: none)")
    parser.add_argument("--cone", type=float, default=60.0, metavar="DEGREES",
                        help="the spot lights' cone angle (VTK's ConeAngle; default 60)")
    parser.add_argument("--cone-culling-off", action="store_true",
                        help="also render with SpotConeCulling off; exit 1 if that image "
                        "differs from the default's")
    parser.add_argument("--back-face-sums", action="store_true",
                        help="also render with FarFieldExactSumsOnBackFaces on (the floor is a "
                        "back face, and so is the ball's hidden far side)")
    parser.add_argument("--hidden-cost", action="store_true",
                        help="also render with AutomaticBackfaceCulling off (the ball's "
                        "hidden back faces drawn) and print what they cost")
    parser.add_argument("--animate", type=int, default=0, metavar="FRAMES",
                        help="also render FRAMES frames in which every light moves and print "
                        "the median far-field build, light update and assignment times")
    parser.add_argument("--specular-power", type=float, default=20.0, metavar="POWER",
                        help="the specular power of both actors (VTK's default is 1; the "
                        "sphere's specular is 0.5, the floor's SPECULAR)")
    parser.add_argument("--floor-specular", type=float, default=0.0, metavar="SPECULAR",
                        help="the floor's specular coefficient")
    parser.add_argument("--no-refine", action="store_true",
                        help="FarFieldRefineStillLights off: still lights above 16,384 keep "
                        "the far field's own settings")
    parser.add_argument("--multisamples", type=int, default=None, metavar="SAMPLES",
                        help="the window's MultiSamples (default: VTK's, 8)")
    parser.add_argument("--counts", action="store_true",
                        help="also print the lights evaluated and reaching per pixel of each "
                        "clustered render (the pass's evaluated-count view, one more render)")
    args = parser.parse_args()
    pbr = None if args.pbr is None else (args.pbr, args.roughness)

    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    floor = vtkPlaneSource()
    floor.SetOrigin(-4, -1, -4)
    floor.SetPoint1(4, -1, -4)
    floor.SetPoint2(-4, -1, 4)
    floor.SetResolution(64, 64)
    add_actor(renderer, floor, (0.8, 0.8, 0.8), specular=args.floor_specular, pbr=pbr,
              power=args.specular_power)
    sphere = vtkSphereSource()
    sphere.SetRadius(0.6)
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(48)
    add_actor(renderer, sphere, (0.9, 0.85, 0.8), specular=0.5, pbr=pbr,
              power=args.specular_power)

    points = vtkPointSource()
    points.SetNumberOfPoints(args.lights)
    points.SetRadius(3.0)
    # Every point a white light (no arrays: the set's defaults), as a new user writes it.
    lights = vtkClusteredLightSet()
    if args.spots > 0.0:
        # Every k-th light a spot light pointing down (a ConeAngle array; 180: point light).
        points.Update()
        cloud = vtkPolyData()
        cloud.ShallowCopy(points.GetOutput())
        cones = numpy.full(args.lights, 180.0)
        cones[:: max(1, int(round(1.0 / args.spots)))] = args.cone
        array = numpy_to_vtk(cones, deep=True)
        array.SetName("ConeAngle")
        cloud.GetPointData().AddArray(array)
        mover_input = cloud
        lights.SetDefaultSpotDirection(0.0, -1.0, 0.0)
    else:
        points.Update()
        mover_input = points.GetOutput()
    # The lights through a transform (the identity unless --animate moves them).
    motion = vtkTransform()
    mover = vtkTransformFilter()
    mover.SetTransform(motion)
    mover.SetInputData(mover_input)
    lights.SetInputConnection(mover.GetOutputPort())
    lights.SetDefaultAttenuation(1.0, 0.0, 8.0)
    lights.SetDefaultIntensity(args.intensity)
    pass_ = vtkClusteredLightingPass()
    pass_.AddLightSet(lights)
    pass_.SetFarFieldRefineStillLights(not args.no_refine)
    renderer.SetPass(pass_)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(400, 300)
    if args.multisamples is not None:
        window.SetMultiSamples(args.multisamples)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 1.5, 6)
    camera.SetFocalPoint(0, -0.3, 0)
    renderer.ResetCameraClippingRange()

    results = {}
    counts = {}
    for name, setup in (
        ("brute", lambda: pass_.SetShadingMode(vtkClusteredLightingPass.SHADING_BRUTE_FORCE)),
        ("default", lambda: pass_.SetShadingMode(vtkClusteredLightingPass.SHADING_CLUSTERED)),
        ("farfield-off", lambda: pass_.SetFarField(False)),
    ):
        setup()
        ms = timed_render(window, args.frames)
        image, pixels = grab(window)
        write_png(image, "%s-%s.png" % (args.prefix, name))
        results[name] = (ms, pixels)
        if name == "default":
            default_build = (pass_.GetLastFarFieldBuildTime(), pass_.GetNumberOfFarFieldLights())
            culled_props = pass_.GetNumberOfBackfaceCulledProps()
        if args.counts and name != "brute":
            counts[name] = light_counts(window, pass_)
    pass_.SetFarField(True)

    def render_changed(name, change, restore):
        """Renders once more with change() applied (images, counts), then restore()."""
        change()
        ms = timed_render(window, args.frames)
        image, pixels = grab(window)
        write_png(image, "%s-%s.png" % (args.prefix, name))
        results[name] = (ms, pixels)
        if args.counts:
            counts[name] = light_counts(window, pass_)
        restore()

    if args.back_face_sums:
        render_changed("back-face-sums", lambda: pass_.SetFarFieldExactSumsOnBackFaces(True),
                       lambda: pass_.SetFarFieldExactSumsOnBackFaces(False))
    if args.hidden_cost:
        render_changed("back-faces-drawn", lambda: pass_.SetAutomaticBackfaceCulling(False),
                       lambda: pass_.SetAutomaticBackfaceCulling(True))
    if args.cone_culling_off:
        render_changed("cone-culling-off", lambda: pass_.SetSpotConeCulling(False),
                       lambda: pass_.SetSpotConeCulling(True))
    budgets = {}
    for steps in args.budget:
        pass_.SetErrorBudgetInSteps(steps)
        start = time.perf_counter()
        window.Render()  # the budget's choice of the far field's resolution
        choice_ms = 1000.0 * (time.perf_counter() - start)
        ms = timed_render(window, args.frames)
        image, pixels = grab(window)
        name = "budget-%g" % steps
        write_png(image, "%s-%s.png" % (args.prefix, name))
        results[name] = (ms, pixels)
        if args.counts:
            counts[name] = light_counts(window, pass_)
        budgets[name] = (choice_ms, pass_.GetEffectiveFarFieldCutoff(),
                         pass_.GetEffectiveCutoff(), pass_.GetFarFieldResolutionInUse(),
                         pass_.ComputeFarFieldErrorBound(), pass_.GetFarFieldErrorBudgetMet(),
                         pass_.GetLastFarFieldBuildTime())
    pass_.SetErrorBudgetInSteps(0)
    brute_ms, brute = results["brute"]
    rmse = {}
    print("%d lights (%d spot lights), %d clustered, attenuation (1, 0, 8), intensity %g"
          % (args.lights, pass_.GetNumberOfSpotLights(), pass_.GetNumberOfClusteredLights(),
             args.intensity))
    print("brute force: %.1f ms" % brute_ms)
    extra = ((["back-face-sums"] if args.back_face_sums else []) +
             (["back-faces-drawn"] if args.hidden_cost else []) +
             (["cone-culling-off"] if args.cone_culling_off else []))
    for name in ["default", "farfield-off"] + extra + list(budgets):
        ms, pixels = results[name]
        diff = numpy.abs(pixels - brute)
        rmse[name] = numpy.sqrt((diff.astype(float) ** 2).mean())
        print("%-12s %8.1f ms (%.1fx faster than brute force)  max err %d steps  RMSE %.2f"
              % (name, ms, brute_ms / ms, diff.max(), numpy.sqrt((diff.astype(float) ** 2).mean())))
        if name == "default":
            print("             far field build %.1f ms, %d lights split" % default_build)
        if name in counts:
            print("             %.2f lights evaluated, %.2f reaching per pixel" % counts[name])
        if name in budgets:
            choice_ms, cutoff, culled_cutoff, nodes, bound, met, build_ms = budgets[name]
            culled = (", culled lights' cutoff 1/%.0f" % (1.0 / culled_cutoff)
                      if culled_cutoff != pass_.GetContributionCutoff() else "")
            print("             cutoff 1/%.0f%s, far field %d nodes (build %.1f ms), stated "
                  "bound %.2f steps over probes, %s; first frame %.0f ms"
                  % (1.0 / cutoff, culled, nodes, build_ms, bound,
                     "met" if met else "NOT met", choice_ms))
    if not rmse["default"] < rmse["farfield-off"]:
        print("the far field did not bring the image closer to brute force")
        return 1
    if args.hidden_cost:
        differ = numpy.any(results["back-faces-drawn"][1] != results["default"][1], axis=2)
        print("the ball's hidden back faces, drawn: %.0f%% of that frame (%d props culled by "
              "default; %d pixels differ)"
              % (100.0 * (1.0 - results["default"][0] / results["back-faces-drawn"][0]),
                 culled_props, numpy.count_nonzero(differ)))
        # The ball is closed: culled, and the same image but for rim samples.
        if culled_props != 1 or numpy.count_nonzero(differ) > differ.size // 1000:
            print("the ball's back faces were not culled, or culling them changed the image")
            return 1
    if args.animate > 0:
        # Every light moves every frame (a small translation): each frame rebuilds the far
        # field and reassigns the lights, as animated lights do.
        times = []
        for frame in range(args.animate):
            motion.Translate(0.001, 0.0, 0.0)
            start = time.perf_counter()
            window.Render()
            times.append((1000.0 * (time.perf_counter() - start),
                          pass_.GetLastFarFieldBuildTime(), pass_.GetLastLightUpdateTime(),
                          pass_.GetLastAssignmentTime()))
        frame_ms, build_ms, update_ms, assign_ms = (numpy.median(column) for column in zip(*times))
        print("animated (%d frames, every light moving, medians): frame %.1f ms, far-field "
              "build %.1f ms (in the light update, %.1f ms), assignment %.1f ms; %d of %d "
              "blocks summed (%d samples)"
              % (args.animate, frame_ms, build_ms, update_ms, assign_ms,
                 pass_.GetNumberOfFarFieldBlocksRead(), pass_.GetNumberOfFarFieldBlocks(),
                 window.GetMultiSamples()))
    if args.cone_culling_off:
        same = numpy.array_equal(results["cone-culling-off"][1], results["default"][1])
        print("cone culling: the same image as without it: %s" % ("yes" if same else "NO"))
        if not same:
            return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
