#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Many point lights from Python with vtkClusteredLightingPass.

Renders a floor with a grid of spheres lit by 4,096 (or --lights N) colored point
lights, offscreen, and writes the image as a PNG. The lights are data: a vtkPolyData
whose points are the light positions and whose point-data arrays ("Color", "Intensity",
"Attenuation", "Radius") hold their parameters, fed to a vtkClusteredLightSet like any
VTK sink. Each light has an explicit radius and the windowed falloff, so it lights a
pool that fades to zero at its radius.

Run with VTK's Python (Debian: /usr/bin/python3) and the package on PYTHONPATH:

    PYTHONPATH=build/lib/python3/dist-packages \\
      scripts/with-display.sh /usr/bin/python3 Examples/Python/many_lights.py

Prints the number of clustered lights and the frame time; exits with status 1 if not
every light was clustered.
"""

import argparse
import math
import random
import sys
import time

# Importing clusteredlighting also loads vtkmodules.vtkRenderingOpenGL2 (the OpenGL
# render window and mappers).
from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkGlyph3DMapper,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)


def make_lights(count, half_size, radius, seed=1):
    """A polydata of `count` lights hovering over the floor, with their parameters as
    point-data arrays (the default array names of vtkClusteredLightSet)."""
    rng = random.Random(seed)
    points = vtkPoints()
    color = vtkUnsignedCharArray()  # scaled from [0, 255] to [0, 1] by the light set
    color.SetName("Color")
    color.SetNumberOfComponents(3)
    intensity = vtkFloatArray()
    intensity.SetName("Intensity")
    attenuation = vtkFloatArray()
    attenuation.SetName("Attenuation")
    attenuation.SetNumberOfComponents(3)
    radii = vtkFloatArray()
    radii.SetName("Radius")
    for _ in range(count):
        x = rng.uniform(-half_size, half_size)
        y = rng.uniform(0.05, 0.9)
        z = rng.uniform(-half_size, half_size)
        points.InsertNextPoint(x, y, z)
        hue = rng.random()
        rgb = [0.5 + 0.5 * math.cos(2.0 * math.pi * (hue + k / 3.0)) for k in range(3)]
        color.InsertNextTuple3(*[40 + 215 * c for c in rgb])
        intensity.InsertNextValue(0.8)
        attenuation.InsertNextTuple3(1.0, 0.0, 60.0)
        radii.InsertNextValue(radius)
    lights = vtkPolyData()
    lights.SetPoints(points)
    for array in (color, intensity, attenuation, radii):
        lights.GetPointData().AddArray(array)
    return lights


def build_scene(renderer, half_size):
    """A floor at y = 0 and a grid of spheres standing on it."""
    floor = vtkPlaneSource()
    floor.SetOrigin(-half_size, 0.0, -half_size)
    floor.SetPoint1(half_size, 0.0, -half_size)
    floor.SetPoint2(-half_size, 0.0, half_size)
    floor_mapper = vtkPolyDataMapper()
    floor_mapper.SetInputConnection(floor.GetOutputPort())
    floor_actor = vtkActor()
    floor_actor.SetMapper(floor_mapper)
    floor_actor.GetProperty().SetColor(0.75, 0.75, 0.75)
    renderer.AddActor(floor_actor)

    centers = vtkPoints()
    steps = 6
    for i in range(steps):
        for j in range(steps):
            x = -half_size + (i + 0.5) * 2.0 * half_size / steps
            z = -half_size + (j + 0.5) * 2.0 * half_size / steps
            centers.InsertNextPoint(x, 0.35, z)
    grid = vtkPolyData()
    grid.SetPoints(centers)
    sphere = vtkSphereSource()
    sphere.SetRadius(0.35)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(24)
    spheres = vtkGlyph3DMapper()
    spheres.SetInputData(grid)
    spheres.SetSourceConnection(sphere.GetOutputPort())
    spheres_actor = vtkActor()
    spheres_actor.SetMapper(spheres)
    spheres_actor.GetProperty().SetColor(0.9, 0.9, 0.85)
    spheres_actor.GetProperty().SetSpecular(0.4)
    spheres_actor.GetProperty().SetSpecularPower(30)
    renderer.AddActor(spheres_actor)


def write_png(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lights", type=int, default=4096, help="number of lights")
    parser.add_argument("--size", type=int, nargs=2, default=(1024, 768), metavar=("W", "H"))
    parser.add_argument("--output", default="many-lights-python.png", help="PNG to write")
    parser.add_argument("--heatmap", help="also write the lights-per-pixel heat map here")
    args = parser.parse_args(argv)

    half_size = 4.0
    window = vtkRenderWindow()
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    renderer.SetBackground(0.02, 0.02, 0.03)
    window.AddRenderer(renderer)
    headlight = vtkLight()  # a dim headlight keeps the shapes readable
    headlight.SetLightTypeToHeadlight()
    headlight.SetIntensity(0.1)
    renderer.AddLight(headlight)
    build_scene(renderer, half_size)

    lights = vtkClusteredLightSet()
    lights.SetInputData(make_lights(args.lights, half_size, radius=0.45))
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)
    clustered.SetFalloff(vtkClusteredLightingPass.FALLOFF_WINDOWED)
    renderer.SetPass(clustered)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 5.0, 7.5)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewAngle(40.0)
    renderer.ResetCameraClippingRange()

    window.Render()  # compiles the shaders
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    milliseconds = 1000.0 * (time.perf_counter() - start)
    write_png(window, args.output)
    if args.heatmap:
        clustered.SetDebugView(vtkClusteredLightingPass.DEBUG_HEAT_MAP)
        window.Render()
        write_png(window, args.heatmap)
        clustered.SetDebugView(vtkClusteredLightingPass.DEBUG_NONE)

    print(
        "%d lights clustered (%d assigned to visible clusters), %dx%d, %.1f ms/frame"
        % (
            clustered.GetNumberOfClusteredLights(),
            clustered.GetNumberOfAssignedLights(),
            args.size[0],
            args.size[1],
            milliseconds,
        )
    )
    print("image: %s" % args.output)
    if args.heatmap:
        print("heat map: %s" % args.heatmap)
    if clustered.GetNumberOfClusteredLights() != args.lights:
        print("expected %d clustered lights" % args.lights, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
