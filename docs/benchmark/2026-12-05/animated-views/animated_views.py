#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""An animated closed mesh shown in several views a frame, with the pass's defaults.

A sphere of about a million triangles (vtkSphereSource, resolution 750) whose radius
changes before every frame, lit by 1,000 lights as a new user writes them, rendered
--frames times in one of three ways: one renderer (--views one), two renderers side by
side sharing one pass (--views two) or one renderer in split-viewport stereo
(--views stereo). Prints the median frame time and the props culled in the last view
rendered (AutomaticBackfaceCulling: a mesh modified before every frame must not be
culled, and must not be tested for closure, about 0.2 s per million triangles), then the
same after the mesh stops changing.

    PYTHONPATH=build/lib/python3/dist-packages scripts/with-display.sh /usr/bin/python3 \\
      docs/benchmark/2026-12-05/animated-views/animated_views.py --views two
"""

import argparse
import statistics
import time

from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
from vtkmodules.vtkFiltersSources import vtkPointSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL classes)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--views", choices=["one", "two", "stereo"], default="two")
    parser.add_argument("--frames", type=int, default=8)
    args = parser.parse_args()

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(750)
    sphere.SetPhiResolution(750)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)

    points = vtkPointSource()
    points.SetNumberOfPoints(1000)
    points.SetRadius(3.0)
    lights = vtkClusteredLightSet()
    lights.SetInputConnection(points.GetOutputPort())
    lights.SetDefaultAttenuation(1.0, 0.0, 8.0)
    lights.SetDefaultIntensity(0.02)
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(400, 300)
    window.SetMultiSamples(0)
    renderers = [vtkRenderer()]
    if args.views == "two":
        renderers.append(vtkRenderer())
        renderers[0].SetViewport(0.0, 0.0, 0.5, 1.0)
        renderers[1].SetViewport(0.5, 0.0, 1.0, 1.0)
    if args.views == "stereo":
        window.SetStereoTypeToSplitViewportHorizontal()
        window.StereoRenderOn()
    for ren in renderers:
        ren.AddActor(actor)
        ren.SetPass(clustered)
        window.AddRenderer(ren)
    renderers[0].GetActiveCamera().SetPosition(0.0, 0.5, 4.0)
    renderers[0].ResetCameraClippingRange()
    for ren in renderers[1:]:
        ren.SetActiveCamera(renderers[0].GetActiveCamera())
    window.Render()

    def timed(animate):
        times = []
        for frame in range(args.frames):
            if animate:
                sphere.SetRadius(0.5 + 0.001 * (frame + 1))
            start = time.perf_counter()
            window.Render()
            times.append(1000.0 * (time.perf_counter() - start))
        return statistics.median(times)

    animated = timed(True)
    print(f"views {args.views}: animated mesh {animated:.1f} ms per frame (median of "
          f"{args.frames}), culled props {clustered.GetNumberOfBackfaceCulledProps()}")
    timed(False)  # the first unchanged frame tests the mesh
    still = timed(False)
    print(f"views {args.views}: still mesh {still:.1f} ms per frame, culled props "
          f"{clustered.GetNumberOfBackfaceCulledProps()}")


if __name__ == "__main__":
    main()
