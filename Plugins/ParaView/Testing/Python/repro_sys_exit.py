"""Not a test: shows that ParaView 5.11's pvbatch (Debian) crashes at exit when a script
that rendered a view calls sys.exit(), with the stock RenderView and no plugin:
    Plugins/ParaView/Testing/pvbatch-test.sh 1 Plugins/ParaView/Testing/Python/repro_sys_exit.py
ends with "Loguru caught a signal: SIGSEGV" and exit code 139. Without the sys.exit()
call it exits with 0. The plugin's tests therefore fail by raising an
exception (clustered_test.finish()).
"""
import sys

from paraview.simple import CreateView, Render, Show, Sphere

view = CreateView("RenderView")
Show(Sphere(), view)
Render(view)
sys.exit(0)
