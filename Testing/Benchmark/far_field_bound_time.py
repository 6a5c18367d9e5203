#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What the far field's stated bound costs to compute, and what it says.

Renders N coloured inverse-square point lights (attenuation (0, 0, 50), intensity 0.3,
no radius: every one is split, so the far field holds them all) in a box around a sphere
on a floor, 320x240, once; then calls vtkClusteredLightingPass.ComputeFarFieldErrorBound()
twice and prints the bound (8-bit steps, the largest over the probe points) and each
call's wall time. The lights are placed by a seeded generator, so two builds of the
library given the same N must print the same bound: run it against two builds (their
Python packages on PYTHONPATH) to compare their cost side by side.

    PYTHONPATH=build/lib/python3/dist-packages scripts/with-display.sh \\
      /usr/bin/python3 Testing/Benchmark/far_field_bound_time.py 4096 65536 524288
"""

import random
import sys
import time

from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)


def measure(count):
    window = vtkRenderWindow()
    window.SetSize(320, 240)
    window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    floor = vtkPlaneSource()
    floor.SetOrigin(-4, -1, -4)
    floor.SetPoint1(4, -1, -4)
    floor.SetPoint2(-4, -1, 4)
    for source in (vtkSphereSource(), floor):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    lights = vtkClusteredLightSet()
    lights.SetNumberOfLights(count)
    rng = random.Random(3)
    for i in range(count):
        lights.SetPosition(i, rng.uniform(-4, 4), rng.uniform(-1, 3), rng.uniform(-4, 4))
        lights.SetColor(i, rng.random(), rng.random(), rng.random())
        lights.SetIntensity(i, 0.3)
        lights.SetAttenuation(i, 0, 0, 50)
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)
    renderer.SetPass(clustered)
    renderer.ResetCamera()
    window.Render()
    print(f"{count} lights, {clustered.GetNumberOfFarFieldLights()} in the far field")
    for _ in range(2):
        start = time.perf_counter()
        bound = clustered.ComputeFarFieldErrorBound()
        ms = 1000.0 * (time.perf_counter() - start)
        print(f"  bound {bound:.3f} steps, computed in {ms:.0f} ms")


if __name__ == "__main__":
    for arg in sys.argv[1:] or ["4096"]:
        measure(int(arg))
