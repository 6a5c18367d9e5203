#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Lights read from a CSV file with a VTK pipeline, and exposure.

The file has one light per row and the columns x,y,z,r,g,b,intensity (lights.csv next to
this script, written by make_lights_csv.py). The pipeline

    vtkDelimitedTextReader          the CSV file -> a vtkTable, numeric columns
    -> vtkTableToPolyData           x, y, z -> points; the other columns -> point data
    -> vtkArrayCalculator           r, g, b -> one 3-component "Color" array
    -> vtkClusteredLightSet         every point a light (IntensityArrayName "intensity")

feeds a vtkClusteredLightingPass that lights a floor and a grid of spheres; the image is
written as a PNG.

Exposure: hundreds of lights add up, and a surface lit by many of them clips to white.
Two remedies, both here:
 - --intensity-scale S sets the light set's IntensityScale: every light's intensity is
   multiplied by S (the CSV is left alone). The default, 0.3, keeps the rings' colors;
   at 1 a quarter of the channels clip;
 - --tone-mapping reinhard|filmic puts a vtkToneMappingPass around the clustered pass:

       tone = vtkToneMappingPass()
       tone.SetToneMappingType(vtkToneMappingPass.GenericFilmic)
       tone.SetExposure(1.0)
       tone.SetDelegatePass(clustered)   # the clustered pass renders into its float buffer
       renderer.SetPass(tone)

   which compresses the bright range instead of clipping it (--exposure sets Exposure).

Run with VTK's Python (Debian: /usr/bin/python3) and the package on PYTHONPATH:

    PYTHONPATH=build/lib/python3/dist-packages scripts/with-display.sh \\
      /usr/bin/python3 Examples/Python/lights_from_csv.py --tone-mapping filmic

Prints the number of lights read and clustered; exits with status 1 if they differ.
"""

import argparse
import os
import sys

# Importing clusteredlighting also loads vtkmodules.vtkRenderingOpenGL2.
from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkArrayCalculator
from vtkmodules.vtkFiltersGeneral import vtkTableToPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOInfovis import vtkDelimitedTextReader
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkGlyph3DMapper,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingOpenGL2 import vtkToneMappingPass

HERE = os.path.dirname(os.path.abspath(__file__))


def lights_pipeline(csv_path):
    """The CSV file as a light set: reader -> table to points -> r,g,b merged to "Color"."""
    reader = vtkDelimitedTextReader()
    reader.SetFileName(csv_path)
    reader.SetFieldDelimiterCharacters(",")
    reader.SetHaveHeaders(True)
    reader.SetDetectNumericColumns(True)

    points = vtkTableToPolyData()
    points.SetInputConnection(reader.GetOutputPort())
    points.SetXColumn("x")
    points.SetYColumn("y")
    points.SetZColumn("z")

    color = vtkArrayCalculator()
    color.SetInputConnection(points.GetOutputPort())
    color.SetAttributeTypeToPointData()
    for name in ("r", "g", "b"):
        color.AddScalarArrayName(name)
    color.SetFunction("r*iHat + g*jHat + b*kHat")
    color.SetResultArrayName("Color")  # the light set's default ColorArrayName

    lights = vtkClusteredLightSet()
    lights.SetInputConnection(color.GetOutputPort())
    lights.SetIntensityArrayName("intensity")  # the CSV's column name
    lights.SetDefaultAttenuation(1.0, 0.0, 4.0)  # no attenuation column: one for all
    lights.SetDefaultRadius(1.8)
    return lights, reader


def build_scene(renderer, half_size=4.0):
    floor = vtkPlaneSource()
    floor.SetOrigin(-half_size, 0.0, -half_size)
    floor.SetPoint1(half_size, 0.0, -half_size)
    floor.SetPoint2(-half_size, 0.0, half_size)
    floor.SetResolution(16, 16)
    floor_mapper = vtkPolyDataMapper()
    floor_mapper.SetInputConnection(floor.GetOutputPort())
    floor_actor = vtkActor()
    floor_actor.SetMapper(floor_mapper)
    floor_actor.GetProperty().SetColor(0.8, 0.8, 0.8)
    renderer.AddActor(floor_actor)

    centers = vtkPoints()
    for i in range(5):
        for j in range(5):
            centers.InsertNextPoint(-3.2 + 1.6 * i, 0.3, -3.2 + 1.6 * j)
    grid = vtkPolyData()
    grid.SetPoints(centers)
    sphere = vtkSphereSource()
    sphere.SetRadius(0.3)
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(16)
    spheres = vtkGlyph3DMapper()
    spheres.SetInputData(grid)
    spheres.SetSourceConnection(sphere.GetOutputPort())
    spheres_actor = vtkActor()
    spheres_actor.SetMapper(spheres)
    spheres_actor.GetProperty().SetColor(0.95, 0.95, 0.9)
    spheres_actor.GetProperty().SetSpecular(0.3)
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
    parser.add_argument("--csv", default=os.path.join(HERE, "lights.csv"),
                        help="CSV file with columns x,y,z,r,g,b,intensity")
    parser.add_argument("--size", type=int, nargs=2, default=(800, 600), metavar=("W", "H"))
    parser.add_argument("--output", default="lights-from-csv.png", help="PNG to write")
    parser.add_argument("--intensity-scale", type=float, default=0.3,
                        help="the light set's IntensityScale (exposure of these lights; at "
                             "1 the 320 lights of lights.csv clip to white where they overlap)")
    parser.add_argument("--tone-mapping", choices=("none", "reinhard", "filmic"),
                        default="none", help="wrap the clustered pass in a vtkToneMappingPass")
    parser.add_argument("--exposure", type=float, default=1.0,
                        help="vtkToneMappingPass exposure (with --tone-mapping)")
    args = parser.parse_args(argv)

    window = vtkRenderWindow()
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    renderer.SetBackground(0.02, 0.02, 0.03)
    window.AddRenderer(renderer)
    headlight = vtkLight()  # a dim headlight keeps the shapes readable
    headlight.SetLightTypeToHeadlight()
    headlight.SetIntensity(0.08)
    renderer.AddLight(headlight)
    build_scene(renderer)

    lights, reader = lights_pipeline(args.csv)
    lights.SetIntensityScale(args.intensity_scale)
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)
    clustered.SetFalloff(vtkClusteredLightingPass.FALLOFF_WINDOWED)
    if args.tone_mapping == "none":
        renderer.SetPass(clustered)
    else:
        tone = vtkToneMappingPass()
        if args.tone_mapping == "reinhard":
            tone.SetToneMappingType(vtkToneMappingPass.Reinhard)
        else:
            tone.SetToneMappingType(vtkToneMappingPass.GenericFilmic)
        tone.SetExposure(args.exposure)
        tone.SetDelegatePass(clustered)
        renderer.SetPass(tone)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 6.0, 8.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewAngle(40.0)
    renderer.ResetCameraClippingRange()

    window.Render()
    write_png(window, args.output)
    rows = reader.GetOutput().GetNumberOfRows()
    print("%d lights read from %s, %d clustered; intensity scale %g, tone mapping %s"
          % (rows, args.csv, clustered.GetNumberOfClusteredLights(), args.intensity_scale,
             args.tone_mapping))
    print("image: %s" % args.output)
    if rows == 0 or clustered.GetNumberOfClusteredLights() != rows:
        print("expected %d clustered lights" % rows, file=sys.stderr)
        return 1
    # The last light has the last row's color and intensity (not the defaults).
    table = reader.GetOutput()
    last = rows - 1
    row = [table.GetValueByName(last, name).ToDouble() for name in ("r", "g", "b", "intensity")]
    got = list(lights.GetColor(last)) + [lights.GetIntensity(last)]
    if max(abs(a - b) for a, b in zip(row, got)) > 1e-6:
        print("light %d: color and intensity %s, the CSV says %s" % (last, got, row),
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
