"""The plugin in client-server mode: pvpython connected to pvserver on N MPI ranks.

Run by client-server-test.sh, which starts the server. The client loads the plugin on
the server and on itself (the plugin is required on both), builds the scene of
lights_across_ranks.py (8 lights from a Line source, whose data is on server rank 0,
next to another rank's piece of a distributed sphere) and renders it twice:
 - remote rendering (RemoteRenderThreshold 0): the server ranks render with the pass and
   IceT composites; the client receives the image;
 - local rendering (a large threshold): the geometry and the lights' data are delivered
   to the client, whose own view and pass render them.

With --render-server, the client connects to a separate data server and render server
(pvdataserver, pvrenderserver: one process each); the render server renders with remote
rendering, and its statistics are the ones read.

Checks: the lights' data is on server rank 0 only; the client's view used the mode asked
for (vtkPVRenderView::GetUseDistributedRenderingForRender); the pass that rendered clustered
the 8 lights; both images are lit (more than 1,500 pixels brighter than 40 of 255), and
equal each other within one 8-bit step (see distributed.py for the step); with --reference
(the pvbatch tests' output folder), both also equal lights_across_ranks.py's 1-rank image
within one step.

Statistics: the view's information properties come from the process that rendered
(vtkSMClusteredLightingPassProxy): the server's rank 0 with remote rendering, the client
with local rendering. Each mode renders the heat map with the prepass forced on and reads
the lights evaluated and reaching per pixel and whether a prepass was drawn: with remote
rendering the client draws no geometry, so only the server's rank 0 can report a prepass
and, with one server rank, lit pixels (ParaView alone reads the client's pass: no prepass,
0 lights per pixel). With one server rank, which renders the whole scene as the client
does, the two modes' counts agree within 1%; with several, rank 0's piece of the sphere is
away from the lights, and its counts are only checked to be consistent. Last, an
interactive render with level of detail that renders locally while a still render goes
remote: its counts are the client's (over the coarser geometry), not the server's last.

pvpython, unlike pvbatch, puts Debian's VTK 9.1 Python package (/lib/python3/dist-packages)
first on sys.path and crashes on importing it: the entry is removed before anything else.
"""

import sys

sys.path = [p for p in sys.path if p.strip("/") != "lib/python3/dist-packages"]

import argparse  # noqa: E402
import os  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403

import clustered_test as t  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--plugin", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--server", required=True, help="host:port of pvserver (or pvdataserver)")
parser.add_argument("--render-server", help="host:port of pvrenderserver, if separate")
parser.add_argument("--reference", help="output folder of lights_across_ranks.py on 1 rank")
args = parser.parse_args()
os.makedirs(args.output, exist_ok=True)
t.args = args

host, port = args.server.rsplit(":", 1)
if args.render_server:
    render_host, render_port = args.render_server.rsplit(":", 1)
    connection = Connect(host, int(port), render_host, int(render_port))
else:
    connection = Connect(host, int(port))
t.check(connection is not None, "connected to %s at %s" % (
    "pvdataserver and pvrenderserver" if args.render_server else "pvserver",
    args.server + (" and " + args.render_server if args.render_server else "")))
LoadPlugin(args.plugin, remote=True, ns=globals())
LoadPlugin(args.plugin, remote=False, ns=globals())
servers = servermanager.ActiveConnection.GetNumberOfDataPartitions()
print("server ranks: %d" % servers)
label = "split" if args.render_server else "np%d" % servers

view = CreateView("ClusteredLightingView")
view.ViewSize = [400, 400]
view.UseLight = 0
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.Falloff = "Windowed"
body = Sphere(Radius=10.0, ThetaResolution=256, PhiResolution=128)
body_display = Show(body, view)
body_display.ColorArrayName = ["POINTS", ""]
body_display.DiffuseColor = [0.9, 0.9, 0.9]
line = Line(Point1=[-8.5, -8.5, -3.5], Point2=[-8.5, -8.5, 3.5], Resolution=7)
lights = Show(line, view)
lights.Representation = "Clustered Lights"
lights.LightDefaultColor = [1.0, 0.75, 0.4]
lights.LightDefaultAttenuation = [1.0, 0.0, 0.3]
lights.LightDefaultRadius = 4.0
view.CameraPosition = [-30.0, -30.0, 10.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0

ids = ProcessIdScalars(Input=line)
ids.UpdatePipeline()
low, high = ids.PointData["ProcessId"].GetRange()
t.check(low == 0 and high == 0, "the lights' data is on server rank 0 only (process ids %g .. %g)"
        % (low, high))

images = {}
for mode, threshold in (("remote", 0.0), ("local", 1e6)):
    view.RemoteRenderThreshold = threshold
    path = os.path.join(args.output, "client-server-%s-%s.png" % (mode, label))
    images[mode] = t.save(view, path)
    distributed = view.GetClientSideObject().GetUseDistributedRenderingForRender()
    t.check(distributed == (mode == "remote"),
            "%s rendering: the client's view %s (distributed rendering: %s)"
            % (mode, "received the server's image" if distributed else "rendered itself",
               distributed))
    lit = int((images[mode].max(axis=2) > 40).sum())
    t.check(lit > 1500, "%s rendering: %d lit pixels (more than 1,500 expected)" % (mode, lit))
    clustered = t.info(view, "NumberOfClusteredLights")
    t.check(clustered == 8, "%s rendering: the pass that rendered clustered %d lights (8 "
            "expected)" % (mode, clustered))

d = t.difference(images["remote"], images["local"])
t.check(d["max"] <= 1, "remote against local rendering: max difference %d step(s) (tolerance 1), "
        "%d pixels differ" % (d["max"], d["pixels_differing"]))
# The statistics of the pass that rendered, in each mode.
view.AutomaticDepthPrepass = 0
view.DebugView = "Heat map"
counts = {}
for mode, threshold in (("remote", 0.0), ("local", 1e6)):
    view.RemoteRenderThreshold = threshold
    Render(view)
    counts[mode] = t.light_counts(view)
    prepass = t.info(view, "DepthPrepassUsed")
    evaluated, reaching = counts[mode]
    # With several server ranks, rank 0's piece of the sphere is away from the lights.
    lowest = 0.0 if mode == "remote" and servers > 1 else 1e-3
    t.check(lowest <= reaching <= evaluated,
            "%s rendering, heat map: %s counted %.3f lights evaluated and %.3f reaching per "
            "pixel (reaching at least %g and at most evaluated)"
            % (mode, "the server's rank 0" if mode == "remote" else "the client", evaluated,
               reaching, lowest))
    t.check(prepass == 1, "%s rendering, prepass forced on: %s drew a depth prepass (%d)"
            % (mode, "the server's rank 0" if mode == "remote" else "the client", prepass))
if servers == 1:
    for i, name in enumerate(("evaluated", "reaching")):
        remote, local = counts["remote"][i], counts["local"][i]
        t.check(abs(remote - local) <= 0.01 * local,
                "one server rank: lights %s per pixel %.3f (server) against %.3f (client), "
                "within 1%%" % (name, remote, local))

# An interactive render with level of detail, rendered locally while a still render goes
# remote (a threshold between the two geometries' sizes: about 1.3 and 3.2 MB here): the
# statistics then come from the client, which rendered the coarser geometry, not from the
# server's last still render.
lod_threshold = view.LODThreshold
view.LODThreshold = 0.0
view.RemoteRenderThreshold = 2.2
Render(view)
still = t.light_counts(view)
view.SMProxy.InteractiveRender()
client_view = view.GetClientSideObject()
t.check(client_view.GetUsedLODForLastRender() and
        client_view.GetUseDistributedRenderingForRender() and
        not client_view.GetUseDistributedRenderingForLODRender(),
        "level of detail: the still render goes remote, the interactive one local")
lod = t.light_counts(view)
t.check(0.0 < lod[1] <= lod[0] and lod != still,
        "level of detail: the client counted %.3f lights evaluated and %.3f reaching per pixel "
        "over its coarser geometry (the server's still render: %.3f and %.3f)"
        % (lod[0], lod[1], still[0], still[1]))
view.LODThreshold = lod_threshold
view.DebugView = "None"
view.AutomaticDepthPrepass = 1

if args.reference:
    reference = t.read(os.path.join(args.reference, "lights-across-ranks-np1.png"))
    for mode in ("remote", "local"):
        d = t.difference(images[mode], reference)
        t.check(d["max"] <= 1, "%s rendering against pvbatch on 1 rank: max difference %d "
                "step(s) (tolerance 1), %d pixels differ" % (mode, d["max"], d["pixels_differing"]))

t.finish()
