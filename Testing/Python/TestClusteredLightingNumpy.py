#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Light sets from and to numpy (issue 14, item 7), with VTK's own Python.

Checks:
 1. round trip: random arrays of every parameter -> light_set_from_numpy ->
    light_set_to_numpy give the same arrays, bit for bit, and a second round trip too;
 2. the value getters (GetPosition(i), GetColor(i), ...) return tuples equal to the rows,
    and raise ValueError for an index out of range;
 3. one value (or one triple) for all lights, uint8 colors scaled from 0-255, RGBA colors
    (alpha dropped), intensity_scale, lights without a radius (-1);
 4. wrong shapes raise ValueError naming the parameter and change nothing;
 5. a set made from numpy renders exactly like the same lights fed as a vtkPolyData;
 6. light_set_to_numpy of a set with an input gives the input's lights.
Exits with status 1 at the first failed check.
"""

import sys

import numpy as np

from clusteredlighting import (
    light_set_from_numpy,
    light_set_to_numpy,
    vtkClusteredLightingPass,
    vtkClusteredLightSet,
)
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
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


def random_lights(count, seed):
    rng = np.random.default_rng(seed)
    radii = rng.uniform(0.1, 2.0, count)
    radii[::3] = -1.0  # no explicit radius
    cones = np.full(count, 180.0)
    cones[::4] = rng.uniform(5.0, 80.0, cones[::4].shape)
    return dict(
        positions=rng.uniform(-5.0, 5.0, (count, 3)),
        colors=rng.uniform(0.0, 1.0, (count, 3)),
        intensities=rng.uniform(0.0, 2.0, count),
        attenuations=np.column_stack(
            [np.ones(count), rng.uniform(0, 1, count), rng.uniform(0, 50, count)]),
        radii=radii,
        spot_directions=rng.normal(size=(count, 3)),
        cone_angles=cones,
        exponents=rng.uniform(1.0, 8.0, count),
    )


def same_arrays(a, b):
    return set(a) == set(b) and all(
        a[k].shape == b[k].shape and a[k].dtype == b[k].dtype and np.array_equal(a[k], b[k])
        for k in a)


def test_round_trip():
    given = random_lights(500, seed=3)
    lights = light_set_from_numpy(**given)
    check(lights.GetNumberOfLights() == 500, "500 lights from numpy")
    back = light_set_to_numpy(lights)
    check(same_arrays(given, back), "light_set_to_numpy gives back exactly the arrays given")
    again = light_set_to_numpy(light_set_from_numpy(**back))
    check(same_arrays(back, again), "a second round trip changes nothing")

    rows_match = all(
        lights.GetPosition(i) == tuple(given["positions"][i])
        and lights.GetColor(i) == tuple(given["colors"][i])
        and lights.GetAttenuation(i) == tuple(given["attenuations"][i])
        and lights.GetSpotDirection(i) == tuple(given["spot_directions"][i])
        and lights.GetIntensity(i) == given["intensities"][i]
        and lights.HasRadius(i) == (given["radii"][i] >= 0)
        for i in range(0, 500, 7))
    check(rows_match, "value getters return the rows as tuples; HasRadius follows the sign")
    try:
        lights.GetPosition(500)
        raised = False
    except ValueError:
        raised = True
    check(raised, "GetPosition(500) of 500 lights raises ValueError")


def test_conveniences():
    positions = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    colors = np.array([[255, 0, 51, 7], [0, 255, 102, 7], [10, 20, 30, 7]], dtype=np.uint8)
    lights = light_set_from_numpy(positions, colors=colors, intensities=0.5,
                                  attenuations=(1.0, 0.0, 60.0), radii=[[0.4], [-1], [0.2]],
                                  intensity_scale=0.25)
    out = light_set_to_numpy(lights)
    check(np.allclose(out["colors"], colors[:, :3] / 255.0, rtol=0, atol=1e-15),
          "uint8 RGBA colors are scaled from 0-255, alpha dropped")
    check(np.array_equal(out["intensities"], [0.5, 0.5, 0.5]) and
          np.array_equal(out["attenuations"], np.tile([1.0, 0.0, 60.0], (3, 1))),
          "one value and one triple are given to every light")
    check(np.array_equal(out["radii"], [0.4, -1.0, 0.2]) and not lights.HasRadius(1),
          "an (N, 1) radius column; -1 means no radius")
    check(lights.GetIntensityScale() == 0.25 and lights.GetScaledIntensity(0) == 0.125,
          "intensity_scale sets IntensityScale (intensities stay as given)")
    defaults = light_set_to_numpy(light_set_from_numpy(positions))
    check(np.array_equal(defaults["colors"], np.ones((3, 3))) and
          np.array_equal(defaults["attenuations"], np.tile([1.0, 0.0, 0.0], (3, 1))) and
          np.array_equal(defaults["radii"], [-1.0] * 3) and
          np.array_equal(defaults["cone_angles"], [180.0] * 3),
          "parameters not given keep vtkLight's defaults")
    empty = light_set_to_numpy(light_set_from_numpy(np.zeros((0, 3))))
    check(empty["positions"].shape == (0, 3) and empty["intensities"].shape == (0,),
          "an empty set gives empty arrays of the right shapes")


def test_bad_shapes():
    positions = np.zeros((4, 3))
    existing = light_set_from_numpy(positions, intensities=2.0)
    cases = [
        ("positions", dict(positions=np.zeros((4, 2)))),
        ("colors", dict(positions=positions, colors=np.zeros((3, 3)))),
        ("intensities", dict(positions=positions, intensities=np.zeros(5))),
        ("attenuations", dict(positions=positions, attenuations=(1.0, 0.0))),
        ("radii", dict(positions=positions, radii=np.array(["a", "b", "c", "d"]))),
        ("cone_angles", dict(positions=positions, cone_angles=np.zeros((4, 2)))),
    ]
    for name, kwargs in cases:
        try:
            light_set_from_numpy(light_set=existing, **kwargs)
            message = None
        except ValueError as error:
            message = str(error)
        check(message is not None and message.startswith(name),
              "a wrong %s raises ValueError naming it: %s" % (name, message))
    check(existing.GetNumberOfLights() == 4 and existing.GetIntensity(0) == 2.0,
          "and the set passed in is unchanged")


def make_window():
    window = vtkRenderWindow()
    window.SetSize(160, 120)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    window.AddRenderer(renderer)
    plane = vtkPlaneSource()
    plane.SetOrigin(-3, -3, 0)
    plane.SetPoint1(3, -3, 0)
    plane.SetPoint2(-3, 3, 0)
    sphere = vtkSphereSource()
    sphere.SetRadius(0.8)
    sphere.SetCenter(0, 0, 0.6)
    for source in (plane, sphere):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -5, 5)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    return window, renderer


def render(lights):
    window, renderer = make_window()
    clustered = vtkClusteredLightingPass()
    clustered.AddLightSet(lights)
    renderer.SetPass(clustered)
    window.Render()
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.SetInputBufferTypeToRGB()
    grabber.ReadFrontBufferOff()
    grabber.Update()
    image = numpy_support.vtk_to_numpy(grabber.GetOutput().GetPointData().GetScalars())
    return np.array(image), clustered.GetNumberOfClusteredLights()


def as_polydata(arrays):
    points = vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(arrays["positions"], deep=True))
    polydata = vtkPolyData()
    polydata.SetPoints(points)
    for key, name in (("colors", "Color"), ("intensities", "Intensity"),
                      ("attenuations", "Attenuation")):
        array = numpy_support.numpy_to_vtk(arrays[key], deep=True)
        array.SetName(name)
        polydata.GetPointData().AddArray(array)
    return polydata


def test_renders_like_polydata():
    rng = np.random.default_rng(9)
    count = 64
    arrays = dict(
        positions=np.column_stack([rng.uniform(-2.5, 2.5, count), rng.uniform(-2.5, 2.5, count),
                                   rng.uniform(0.2, 1.2, count)]),
        colors=rng.uniform(0.3, 1.0, (count, 3)),
        intensities=rng.uniform(0.5, 1.0, count),
        attenuations=np.tile([1.0, 0.0, 8.0], (count, 1)),
    )
    from_numpy, clustered_numpy = render(light_set_from_numpy(**arrays))
    fed = vtkClusteredLightSet()
    fed.SetInputData(as_polydata(arrays))
    from_polydata, clustered_polydata = render(fed)
    lit = np.mean(from_numpy > 40)
    check(clustered_numpy == count and clustered_polydata == count,
          "%d lights clustered both ways" % count)
    check(lit > 0.2, "the lights light the scene (%.0f%% of values over 40)" % (100 * lit))
    check(np.array_equal(from_numpy, from_polydata),
          "a set from numpy renders exactly like the same lights as a vtkPolyData")

    back = light_set_to_numpy(fed)  # reads the input first
    check(np.array_equal(back["positions"], arrays["positions"]) and
          np.array_equal(back["intensities"], arrays["intensities"]),
          "light_set_to_numpy of a set with an input gives the input's lights")


def main():
    test_round_trip()
    test_conveniences()
    test_bad_shapes()
    test_renders_like_polydata()
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
