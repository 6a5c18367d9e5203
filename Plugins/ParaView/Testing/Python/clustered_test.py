"""Shared code of the ClusteredLighting plugin's pvbatch tests.

Each test script calls setup() first (arguments, plugin, rank count), checks numbers with
check(), which prints every value it tests, and ends with finish(), whose exit code fails
the CTest test when a check failed.
"""

import argparse
import os
import sys  # noqa: F401

from paraview import servermanager
from paraview.simple import LoadPlugin, SaveScreenshot
from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

import numpy

_failures = []
args = None


def setup(description, reference=False):
    """Parses the arguments and loads the plugin on every rank."""
    global args
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--plugin", required=True, help="ClusteredLighting.so")
    parser.add_argument("--output", required=True, help="folder for the images")
    if reference:
        parser.add_argument(
            "--reference", help="output folder of the same test run on 1 rank, to compare with")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    LoadPlugin(args.plugin, ns=globals())
    print("ranks: %d" % ranks())
    return args


def ranks():
    """Number of MPI ranks pvbatch runs on."""
    return servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def output(name):
    """Path of an image in the output folder; the name gets the rank count."""
    return os.path.join(args.output, "%s-np%d.png" % (name, ranks()))


def save(view, path):
    """Renders the view and saves it at its own size; returns the image (H x W x 3)."""
    SaveScreenshot(path, view, ImageResolution=list(view.ViewSize), TransparentBackground=0)
    return read(path)


def read(path):
    """Reads a PNG into a uint8 array of shape (height, width, 3), top row first."""
    if not os.path.exists(path):
        raise RuntimeError("no image at %s" % path)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    pixels = pixels.reshape(height, width, -1)[::-1, :, :3]
    return numpy.ascontiguousarray(pixels)


def pixel_difference(a, b):
    """Largest channel difference of each pixel, in 8-bit steps (height x width)."""
    if a.shape != b.shape:
        raise RuntimeError("image sizes differ: %s and %s" % (a.shape, b.shape))
    return numpy.abs(a.astype(numpy.int32) - b.astype(numpy.int32)).max(axis=2)


def difference(a, b):
    """Largest channel difference and counts of pixels that differ (in 8-bit steps)."""
    d = pixel_difference(a, b)
    return {
        "max": int(d.max()),
        "pixels_differing": int((d > 0).sum()),
        "pixels_over_1": int((d > 1).sum()),
        "pixels": int(d.size),
    }


def info(proxy, name):
    """Value of an information property of a proxy (e.g. a statistic of the pass)."""
    proxy.UpdatePropertyInformation()
    return vtkSMPropertyHelper(proxy.SMProxy, name).GetAsDouble(0)


def light_counts(view):
    """(lights evaluated, lights reaching) per pixel of the view's last counting render."""
    return (info(view, "MeanLightsEvaluatedPerPixel"), info(view, "MeanLightsReachingPerPixel"))


def check(condition, message):
    """Records and prints one check."""
    print("%s: %s" % ("ok  " if condition else "FAIL", message))
    sys.stdout.flush()
    if not condition:
        _failures.append(message)
    return condition


def finish():
    """Fails the script (exit code 1) if a check failed.

    It raises instead of calling sys.exit(): ParaView 5.11's pvbatch crashes at exit
    (SIGSEGV in X's error handler while views release their OpenGL objects) when a script
    that rendered calls sys.exit(), with the stock RenderView too; an uncaught exception
    ends it cleanly with exit code 1.
    """
    if _failures:
        raise AssertionError("%d check(s) failed:\n  %s" % (len(_failures), "\n  ".join(_failures)))
    print("all checks passed")
