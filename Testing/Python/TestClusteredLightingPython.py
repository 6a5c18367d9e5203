#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The Python package: wrapped classes, lights as data, and images.

Checks, with VTK's own Python:
 1. clustered lights fed from a polydata built in Python match stock VTK lighting of the
    same lights given as vtkLight objects, pixel by pixel, within the bound the cutoff
    implies (each light is ignored only where its contribution is below Cutoff);
 2. 2,048 lights from an animated vtkProgrammableSource: all clustered every frame, the
    image follows them, the shaders are built in the first frame only, and the lit
    image is much brighter than the same scene with the light set switched off;
 3. a bad array is reported through an ErrorEvent observer and gives no lights.
Exits with status 1 at the first failed check.
"""

import math
import random
import sys

from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkProgrammableSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)

FAILURES = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        FAILURES.append(what)


def make_window(headlight=True):
    """A floor and a sphere; a dim headlight, or no light at all (not even VTK's automatic
    one) when `headlight` is false."""
    window = vtkRenderWindow()
    window.SetSize(200, 150)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    plane = vtkPlaneSource()
    plane.SetOrigin(-3, -3, 0)
    plane.SetPoint1(3, -3, 0)
    plane.SetPoint2(-3, 3, 0)
    plane.SetResolution(4, 4)
    sphere = vtkSphereSource()
    sphere.SetRadius(0.8)
    sphere.SetCenter(0, 0, 0.6)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(32)
    for source, specular in ((plane, 0.0), (sphere, 0.4)):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetSpecular(specular)
        actor.GetProperty().SetSpecularPower(20)
        renderer.AddActor(actor)
    renderer.AutomaticLightCreationOff()
    if headlight:
        light = vtkLight()
        light.SetLightTypeToHeadlight()
        light.SetIntensity(0.1)
        renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -5, 5)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    return window, renderer


def grab(window):
    """RGB values of the back buffer, 0-255."""
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.SetInputBufferTypeToRGB()
    grabber.ReadFrontBufferOff()
    grabber.Update()
    scalars = grabber.GetOutput().GetPointData().GetScalars()
    return [scalars.GetValue(i) for i in range(scalars.GetNumberOfValues())]


def light_records(count, seed):
    """(position, color, intensity, attenuation) of `count` lights over the floor."""
    rng = random.Random(seed)
    records = []
    for _ in range(count):
        position = (rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5), rng.uniform(0.2, 1.2))
        color = (rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0))
        records.append((position, color, 0.8, (1.0, 0.0, 8.0)))
    return records


def records_to_polydata(records):
    points = vtkPoints()
    arrays = {}
    for name, components in (("Color", 3), ("Intensity", 1), ("Attenuation", 3)):
        array = vtkFloatArray()
        array.SetName(name)
        array.SetNumberOfComponents(components)
        arrays[name] = array
    for position, color, intensity, attenuation in records:
        points.InsertNextPoint(position)
        arrays["Color"].InsertNextTuple(color)
        arrays["Intensity"].InsertNextTuple1(intensity)
        arrays["Attenuation"].InsertNextTuple(attenuation)
    polydata = vtkPolyData()
    polydata.SetPoints(points)
    for array in arrays.values():
        polydata.GetPointData().AddArray(array)
    return polydata


def test_matches_stock_vtk():
    records = light_records(16, seed=5)
    # Stock VTK: the same lights as vtkLight objects, no pass. No headlight: with
    # positional lights VTK shades it with other formulas than when it is alone.
    window, renderer = make_window(headlight=False)
    for position, color, intensity, attenuation in records:
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPositional(True)
        light.SetConeAngle(180.0)
        light.SetPosition(position)
        light.SetFocalPoint(position[0], position[1], 0.0)
        light.SetColor(color)
        light.SetIntensity(intensity)
        light.SetAttenuationValues(attenuation)
        renderer.AddLight(light)
    window.Render()
    stock = grab(window)

    # Clustered: the lights as data (point-data arrays), no renderer light.
    window, renderer = make_window(headlight=False)
    lights = vtkClusteredLightSet()
    lights.SetInputData(records_to_polydata(records))
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)
    renderer.SetPass(clustered)
    window.Render()
    image = grab(window)
    check(clustered.GetNumberOfClusteredLights() == len(records),
          "16 lights from a polydata clustered")

    # Each light is cut where color * intensity * attenuation < Cutoff (white material);
    # with diffuse 1 and specular <= 0.4 of white, a pixel can lose at most
    # lights * Cutoff * 1.4, plus 1.5 steps of rounding.
    bound = 255.0 * len(records) * clustered.GetCutoff() * 1.4 + 1.5
    worst = max(abs(a - b) for a, b in zip(stock, image))
    differing = sum(1 for a, b in zip(stock, image) if a != b) / float(len(image))
    print("clustered vs stock VTK: max difference %d steps (bound %.1f), %.2f%% of values differ"
          % (worst, bound, 100.0 * differing))
    lit = sum(1 for v in stock if v > 40) / float(len(stock))
    check(lit > 0.2, "the stock image is lit (%.0f%% of values over 40)" % (100.0 * lit))
    check(worst <= bound, "clustered pipeline lights match stock VTK lighting")


def test_animated_many_lights():
    count = 2048
    rng = random.Random(11)
    base = [(rng.uniform(0.0, 2.0 * math.pi), rng.uniform(0.5, 2.8), rng.uniform(0.1, 1.0))
            for _ in range(count)]
    state = {"frame": 0}
    source = vtkProgrammableSource()

    def make_lights():
        points = vtkPoints()
        color = vtkFloatArray()
        color.SetName("Color")
        color.SetNumberOfComponents(3)
        for i, (angle, radius, height) in enumerate(base):
            a = angle + 0.3 * state["frame"]
            points.InsertNextPoint(radius * math.cos(a), radius * math.sin(a), height)
            color.InsertNextTuple3(*[0.4 + 0.6 * (i % 3 == k) for k in range(3)])
        output = source.GetPolyDataOutput()
        output.SetPoints(points)
        output.GetPointData().AddArray(color)

    source.SetExecuteMethod(make_lights)
    window, renderer = make_window()
    lights = vtkClusteredLightSet()
    lights.SetInputConnection(source.GetOutputPort())
    lights.SetDefaultIntensity(0.5)
    lights.SetDefaultAttenuation(1.0, 0.0, 30.0)
    lights.SetDefaultRadius(0.4)
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)
    clustered.SetFalloff(vtkClusteredLightingPass.FALLOFF_WINDOWED)
    renderer.SetPass(clustered)

    builds = None
    previous = None
    for frame in range(3):
        state["frame"] = frame
        source.Modified()
        window.Render()
        image = grab(window)
        check(clustered.GetNumberOfClusteredLights() == count,
              "frame %d: %d lights clustered" % (frame, count))
        check(lights.GetNumberOfLights() == source.GetPolyDataOutput().GetNumberOfPoints(),
              "frame %d: the light set follows the source" % frame)
        if builds is None:
            builds = clustered.GetNumberOfShaderBuilds()
        else:
            check(clustered.GetNumberOfShaderBuilds() == builds,
                  "frame %d: no shader rebuild" % frame)
            changed = sum(1 for a, b in zip(previous, image) if abs(a - b) > 2) / float(len(image))
            check(changed > 0.05,
                  "frame %d: the image follows the lights (%.0f%% changed)"
                  % (frame, 100 * changed))
        previous = image

    lit = previous
    lights.EnabledOff()
    window.Render()
    dark = grab(window)
    brighter = sum(1 for a, b in zip(lit, dark) if a > b + 10) / float(len(lit))
    print("lit vs lights off: %.0f%% of values brighter by more than 10 steps" % (100.0 * brighter))
    check(brighter > 0.3, "the lights light the scene")


def test_bad_array_reported():
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        errors.append(message)

    polydata = records_to_polydata(light_records(4, seed=2))
    wrong = vtkFloatArray()
    wrong.SetName("Intensity")
    wrong.SetNumberOfComponents(2)
    wrong.SetNumberOfTuples(4)
    wrong.Fill(1.0)
    polydata.GetPointData().RemoveArray("Intensity")
    polydata.GetPointData().AddArray(wrong)
    lights = vtkClusteredLightSet()
    lights.AddObserver("ErrorEvent", on_error)
    lights.SetInputData(polydata)
    lights.UpdateLights()
    check(len(errors) == 1 and "'Intensity'" in errors[0] and "2 components" in errors[0],
          "a 2-component intensity array is reported: %s"
          % (errors[0].strip().splitlines()[-1] if errors else "nothing"))
    check(lights.GetNumberOfLights() == 0, "and gives no lights")


def main():
    test_matches_stock_vtk()
    test_animated_many_lights()
    test_bad_array_reported()
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
