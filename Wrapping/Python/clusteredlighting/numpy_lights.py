"""numpy arrays in and out of a vtkClusteredLightSet.

    import numpy as np
    from clusteredlighting import light_set_from_numpy, light_set_to_numpy

    lights = light_set_from_numpy(
        positions,                    # (N, 3)
        colors=rgb,                   # (N, 3) or (N, 4) floats in [0, 1], or uint8 in [0, 255]
        intensities=0.8,              # one value for all, or (N,)
        attenuations=(1.0, 0.0, 60.0),  # one (a0, a1, a2) for all, or (N, 3)
        radii=0.45)                   # one value for all, or (N,); negative: no radius
    arrays = light_set_to_numpy(lights)  # {"positions": (N, 3), "colors": (N, 3), ...}
    same = light_set_from_numpy(**arrays)

The arrays go through vtkmodules.util.numpy_support and the set's bulk methods
(SetPositions(), SetColors(), ... and GetPositions(), GetColors(), ...), one copy each way.
Parameters not given keep vtkLight's defaults (white, intensity 1, attenuation (1, 0, 0),
no radius, point light). Shapes are checked before anything is set: a wrong one raises
ValueError naming the parameter.
"""

import numpy as np
from vtkmodules.util import numpy_support

from .vtkRenderingClustered import vtkClusteredLightSet

__all__ = ["PARAMETERS", "light_set_from_numpy", "light_set_to_numpy"]

#: (keyword, setter, getter, components) of each parameter, in the order they are set.
PARAMETERS = (
    ("positions", "SetPositions", "GetPositions", 3),
    ("colors", "SetColors", "GetColors", 3),
    ("intensities", "SetIntensities", "GetIntensities", 1),
    ("attenuations", "SetAttenuations", "GetAttenuations", 3),
    ("radii", "SetRadii", "GetRadii", 1),
    ("spot_directions", "SetSpotDirections", "GetSpotDirections", 3),
    ("cone_angles", "SetConeAngles", "GetConeAngles", 1),
    ("exponents", "SetExponents", "GetExponents", 1),
)


def _prepare(name, values, count, components):
    """`values` as a C-contiguous numeric array of `count` tuples of `components` (colors
    may have 4); one tuple (or a scalar for one component) is repeated for every light."""
    array = np.asarray(values)
    if array.dtype == np.bool_ or not np.issubdtype(array.dtype, np.number):
        raise ValueError("%s: numbers expected, got an array of %s" % (name, array.dtype))
    if np.issubdtype(array.dtype, np.complexfloating):
        raise ValueError("%s: complex numbers are not light parameters" % name)
    allowed = (3, 4) if name == "colors" else (components,)
    if components == 1:
        if array.ndim == 2 and array.shape[1] == 1:
            array = array[:, 0]
        if array.ndim == 0:
            array = np.broadcast_to(array, (count,))
        if array.ndim != 1 or array.shape[0] != count:
            raise ValueError("%s: expected one value or %d values, got shape %s"
                             % (name, count, array.shape))
    else:
        if array.ndim == 1 and array.shape[0] in allowed:
            array = np.broadcast_to(array, (count, array.shape[0]))
        if array.ndim != 2 or array.shape[0] != count or array.shape[1] not in allowed:
            raise ValueError("%s: expected shape (%d, %s) or one tuple of %s, got shape %s"
                             % (name, count, " or ".join(map(str, allowed)),
                                " or ".join(map(str, allowed)), array.shape))
    if array.dtype != np.uint8:  # uint8 colors stay bytes: the set scales them from 0-255
        array = array.astype(np.float64, copy=False)
    return np.ascontiguousarray(array)


def light_set_from_numpy(positions, colors=None, intensities=None, attenuations=None,
                         radii=None, spot_directions=None, cone_angles=None, exponents=None,
                         intensity_scale=None, light_set=None):
    """A vtkClusteredLightSet holding one light per row of `positions` (shape (N, 3)).

    colors: (N, 3) or (N, 4) (alpha ignored), floats in [0, 1] or uint8 in [0, 255];
    intensities, radii, cone_angles (degrees, >= 90: point light), exponents: (N,) or one
    value; attenuations (a0, a1, a2) and spot_directions: (N, 3) or one triple. A negative
    radius means "no explicit radius". intensity_scale sets the set's IntensityScale.
    light_set: fill this set (it must have no input) instead of a new one.
    Returns the set.
    """
    given = dict(positions=positions, colors=colors, intensities=intensities,
                 attenuations=attenuations, radii=radii, spot_directions=spot_directions,
                 cone_angles=cone_angles, exponents=exponents)
    points = np.asarray(positions)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError("positions: expected shape (N, 3), got shape %s" % (points.shape,))
    count = points.shape[0]
    # Check everything before the set changes.
    prepared = [(setter, _prepare(name, given[name], count, components))
                for name, setter, _, components in PARAMETERS if given[name] is not None]
    lights = vtkClusteredLightSet() if light_set is None else light_set
    if light_set is None:
        lights.SetNumberOfLights(count)  # new lights get vtkLight's defaults
    for setter, array in prepared:
        # deep=True: the set copies anyway, and the VTK array must not outlive `array`.
        if not getattr(lights, setter)(numpy_support.numpy_to_vtk(array, deep=True)):
            raise ValueError("%s() rejected the array (see the error above)" % setter)
    if intensity_scale is not None:
        lights.SetIntensityScale(float(intensity_scale))
    return lights


def light_set_to_numpy(light_set):
    """Every parameter of every light of `light_set` as numpy arrays (copies), in a dict
    keyed like the arguments of light_set_from_numpy(): positions (N, 3), colors (N, 3),
    intensities (N,) (without IntensityScale), attenuations (N, 3), radii (N,) (-1: no
    explicit radius), spot_directions (N, 3), cone_angles (N,), exponents (N,).
    A set with an input reads it first (UpdateLights())."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray

    light_set.UpdateLights()
    arrays = {}
    for name, _, getter, components in PARAMETERS:
        out = vtkDoubleArray()
        getattr(light_set, getter)(out)
        values = np.array(numpy_support.vtk_to_numpy(out), dtype=np.float64, copy=True)
        arrays[name] = values.reshape(-1, components) if components > 1 else values.reshape(-1)
    return arrays
