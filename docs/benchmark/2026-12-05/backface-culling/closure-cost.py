#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What AutomaticBackfaceCulling's closure test costs on the benchmark's bunny (1.1 M
triangles, 1024x768, 256 lights): frames with the option off, then the first frame with it
on (the test of the mesh), the next ones (cached), and a frame after the polydata is
modified, with the option on and off (VTK's own rebuild of the mesh's buffers included).

    PYTHONPATH=build/lib/python3/dist-packages scripts/with-display.sh /usr/bin/python3 \
      docs/benchmark/2026-12-05/backface-culling/closure-cost.py
"""
import time
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkPolyDataNormals
from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkActor, vtkPolyDataMapper
import vtkmodules.vtkRenderingOpenGL2
from vtkmodules.vtkFiltersSources import vtkPointSource
from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet
r = vtkOBJReader(); r.SetFileName("/usr/share/glmark2/models/bunny.obj")
c = vtkCleanPolyData(); c.SetInputConnection(r.GetOutputPort())
l = vtkLoopSubdivisionFilter(); l.SetNumberOfSubdivisions(2); l.SetInputConnection(c.GetOutputPort())
n = vtkPolyDataNormals(); n.SetInputConnection(l.GetOutputPort()); n.SplittingOff(); n.Update()
print("triangles", n.GetOutput().GetNumberOfPolys())
ren = vtkRenderer(); m = vtkPolyDataMapper(); m.SetInputData(n.GetOutput()); a = vtkActor(); a.SetMapper(m); ren.AddActor(a)
ps = vtkPointSource(); ps.SetNumberOfPoints(256); ps.SetRadius(2)
ls = vtkClusteredLightSet(); ls.SetInputConnection(ps.GetOutputPort()); ls.SetDefaultAttenuation(1,0,8); ls.SetDefaultIntensity(0.05)
p = vtkClusteredLightingPass(); p.AddLightSet(ls); ren.SetPass(p)
rw = vtkRenderWindow(); rw.SetOffScreenRendering(True); rw.SetSize(1024, 768); rw.AddRenderer(ren); ren.ResetCamera()
p.SetAutomaticBackfaceCulling(False)
def t():
    s = time.perf_counter(); rw.Render(); return 1000 * (time.perf_counter() - s)
print("off: first %.0f, then %.0f %.0f" % (t(), t(), t()))
p.SetAutomaticBackfaceCulling(True)
print("on: first (closure) %.0f, then %.0f %.0f; culled %d" % (t(), t(), t(), p.GetNumberOfBackfaceCulledProps()))
n.GetOutput().Modified()
print("polydata modified: %.0f, then %.0f" % (t(), t()))
p.SetAutomaticBackfaceCulling(False)
print("off, steady %.0f %.0f" % (t(), t()))
n.GetOutput().Modified()
print("off, polydata modified: %.0f, then %.0f" % (t(), t()))
