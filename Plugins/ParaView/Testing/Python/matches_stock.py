"""The Clustered Lighting view matches the stock RenderView for a few positional lights.

Scene, the same in both views: a distributed Sphere source (specular 0.5), a translucent
sphere in front of it (opacity 0.4: depth peeling), FXAA on, and three lights added with
ParaView's AddLight() (what the Light Inspector does), in scene coordinates: two
positional point lights and one spot light (cone angle 25 degrees), in three colors.
ParaView's lights have VTK's default attenuation (1, 0, 0): they never fall off, so the
pass shades them exactly as VTK does, with no cutoff.

Checks, on every rank count:
 - the pass clustered the 3 lights, 1 of them a spot light (so the comparison compares
   clustered shading with VTK's, not VTK's with itself);
 - the clustered image equals the stock image within one 8-bit step (the README's bound
   for clustered shading against stock VTK; float sums in another order), with the light
   kit off and with it on (its lights stay with VTK's lighting code in both views);
 - the images are lit: the three lights light more than 20% of the frame.
 - with the small sphere drawn as an opaque wireframe in front of the large one, and the
   views' HiddenLineRemoval on, then their UseAmbientOcclusion (UseSSAO) on (ParaView's
   renderer applies both, through its own delegate; hidden-line removal on 1 rank only):
   each changes the stock image, and the clustered image equals the stock one within one
   step.
   The pass draws its depth prepass in every frame here (AutomaticDepthPrepass off), and
   must draw none under either option: with one, hidden-line removal hid the large
   sphere behind the wireframe's back lines.
 - a shaded volume (the Wavelet source) in a new pair of views lit by the light kit only
   (its lights stay with VTK): it covers the image and the clustered view equals the
   stock one within one step (the ray caster's shaders did not compile under the pass
   before 2026-11-28, and the volume vanished); then with two positional lights added
   (AddLight, as the Light Inspector does), which change the stock image: the clustered
   view leaves them to VTK while the shaded volume is shown (RendererLightsLeftToVTK;
   ParaView's delegate renders the volume with the surfaces, and VTK lights a volume
   only with the lights the renderer holds) and equals the stock one within one step
   (until 2026-11-29 the volume missed them).
"""

from paraview.simple import *  # noqa: F401,F403

import numpy

import clustered_test as t

t.setup(__doc__)

body = Sphere(Radius=10.0, ThetaResolution=128, PhiResolution=64)
glass = Sphere(Radius=5.0, Center=[6.0, -9.0, 4.0], ThetaResolution=64, PhiResolution=32)

LIGHTS = (
    # position, focal point, color, cone angle (>= 90: point light)
    ([-14.0, -12.0, 10.0], [0.0, 0.0, 0.0], [1.0, 0.85, 0.7], 180.0),
    ([15.0, -6.0, -8.0], [0.0, 0.0, 0.0], [0.5, 0.7, 1.0], 180.0),
    ([0.0, -20.0, 2.0], [0.0, 0.0, 0.0], [0.6, 1.0, 0.6], 25.0),
)


def new_view(kind, size):
    """A view of the given kind and size on the tests' dark background, without axes."""
    view = CreateView(kind)
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.12]
    return view


def add_light(view, position, focal, color, cone):
    """A positional light of the view, as the Light Inspector adds it, in scene coordinates."""
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Positional"
    light.Position = position
    light.FocalPoint = focal
    light.DiffuseColor = color
    light.ConeAngle = cone


def make_view(kind):
    view = new_view(kind, [480, 360])
    view.UseFXAA = 1
    view.UseLight = 0
    body_display = Show(body, view)
    body_display.ColorArrayName = ["POINTS", ""]
    body_display.DiffuseColor = [0.9, 0.9, 0.9]
    body_display.Specular = 0.5
    glass_display = Show(glass, view)
    glass_display.ColorArrayName = ["POINTS", ""]
    glass_display.DiffuseColor = [0.9, 0.5, 0.3]
    glass_display.Opacity = 0.4
    for position, focal, color, cone in LIGHTS:
        add_light(view, position, focal, color, cone)
    view.CameraPosition = [10.0, -45.0, 18.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    return view


stock = make_view("RenderView")
clustered = make_view("ClusteredLightingView")

for kit in (0, 1):
    stock.UseLight = kit
    clustered.UseLight = kit
    name = "matches-stock-kit%d" % kit
    a = t.save(clustered, t.output(name))
    b = t.save(stock, t.output(name + "-stock"))
    lights = t.info(clustered, "NumberOfClusteredLights")
    spots = t.info(clustered, "NumberOfSpotLights")
    t.check(lights == 3 and spots == 1,
            "light kit %s: the pass clustered %d lights, %d spot (3 and 1 expected)"
            % ("on" if kit else "off", lights, spots))
    d = t.difference(a, b)
    t.check(d["max"] <= 1,
            "light kit %s: clustered against stock: max difference %d step(s) (tolerance 1), "
            "%d of %d pixels differ" % ("on" if kit else "off", d["max"], d["pixels_differing"],
                                       d["pixels"]))
    if not kit:
        lit = int((a.max(axis=2) > 40).sum())
        t.check(lit > 0.2 * d["pixels"], "lit pixels: %d of %d (more than 20%% expected)"
                % (lit, d["pixels"]))

# Hidden-line removal, then SSAO: the small sphere as an opaque wireframe in front of the
# large one, the light kit off; the prepass in every frame unless an option forbids it.
clustered.AutomaticDepthPrepass = 0
clustered.DepthPrepass = 1
for view in (stock, clustered):
    view.UseLight = 0
    display = GetDisplayProperties(glass, view=view)
    display.Representation = "Wireframe"
    display.Opacity = 1.0
plain = t.save(stock, t.output("matches-stock-wireframe-stock"))
for option in ("HiddenLineRemoval", "UseAmbientOcclusion"):
    for view in (stock, clustered):
        setattr(view, option, 1)
    name = "matches-stock-%s" % option.lower()
    a = t.save(clustered, t.output(name))
    b = t.save(stock, t.output(name + "-stock"))
    # ParaView turns hidden-line removal off for distributed geometry (more than 1 rank).
    if option != "HiddenLineRemoval" or t.ranks() == 1:
        changed = t.difference(b, plain)["pixels_differing"]
        t.check(changed > 100, "%s changes %d pixels of the stock image" % (option, changed))
    d = t.difference(a, b)
    t.check(d["max"] <= 1,
            "%s: clustered against stock: max difference %d step(s) (tolerance 1), "
            "%d of %d pixels differ" % (option, d["max"], d["pixels_differing"], d["pixels"]))
    for view in (stock, clustered):
        setattr(view, option, 0)

# A shaded volume, light kit only.
wavelet = Wavelet()
volume_views = []
for kind in ("ClusteredLightingView", "RenderView"):
    view = new_view(kind, [320, 240])
    view.UseLight = 1
    display = Show(wavelet, view)
    display.SetRepresentationType("Volume")
    ColorBy(display, ("POINTS", "RTData"))
    display.Shade = 1
    view.CameraPosition = [30.0, -60.0, 40.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    volume_views.append(view)
a = t.save(volume_views[0], t.output("matches-stock-volume"))
b = t.save(volume_views[1], t.output("matches-stock-volume-stock"))
covered = int((numpy.abs(b.astype(int) - [26, 26, 31]).max(axis=2) > 2).sum())
t.check(covered > 0.2 * a.shape[0] * a.shape[1],
        "volume: the stock view shows it on %d of %d pixels" % (covered, a.shape[0] * a.shape[1]))
d = t.difference(a, b)
t.check(d["max"] <= 1,
        "volume: clustered against stock: max difference %d step(s) (tolerance 1), "
        "%d of %d pixels differ" % (d["max"], d["pixels_differing"], d["pixels"]))

# The same volume lit by two positional lights too.
for view in volume_views:
    for position, color in (([-30.0, -40.0, 30.0], [1.0, 0.4, 0.3]),
                            ([30.0, -30.0, -20.0], [0.3, 0.5, 1.0])):
        add_light(view, position, [0.0, 0.0, 0.0], color, 180.0)
lit = t.save(volume_views[0], t.output("matches-stock-volume-lights"))
lit_stock = t.save(volume_views[1], t.output("matches-stock-volume-lights-stock"))
d = t.difference(lit_stock, b)
t.check(d["max"] > 20,
        "volume with 2 positional lights: they change the stock image (max %d steps at %d "
        "pixels)" % (d["max"], d["pixels_differing"]))
left = t.info(volume_views[0], "RendererLightsLeftToVTK")
clustered_lights = t.info(volume_views[0], "NumberOfClusteredLights")
t.check(left == 1 and clustered_lights == 0,
        "volume with 2 positional lights: left to VTK (%d), %d clustered (0 expected)"
        % (left, clustered_lights))
d = t.difference(lit, lit_stock)
t.check(d["max"] <= 1,
        "volume with 2 positional lights: clustered against stock: max difference %d step(s) "
        "(tolerance 1), %d of %d pixels differ" % (d["max"], d["pixels_differing"], d["pixels"]))

t.finish()
