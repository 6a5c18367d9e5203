"""The view's properties are the pass's options; the Clustered Lights representation's
properties and domains behave.

Checks:
 - XML against the C++ header: every option of vtkClusteredLightingPass (each vtkSetMacro
   and vtkSetClampMacro of Rendering/vtkClusteredLightingPass.h) is a property of the
   ClusteredLightingPass proxy whose command is its setter, whose default is the
   header's default, whose domain is the header's (boolean; enumeration values = the
   clamp range; range min and max = the clamp bounds), with documentation, and which the
   Clustered Lighting view exposes; there is no property for an option the header does
   not have; every statistic's getter exists. Adding an option to the pass without its
   property (or changing a default in one place only) fails here.
 - The properties reach every rank's pass: Tiles X/Y and Slices change the list
   texture's size (X * Y * Z * ceil(N / 32) * 4 bytes), ContributionCutoff the effective cutoff, an
   error budget picks another cutoff, Measure Timings records times, Cluster Renderer
   Lights hands a renderer light back to VTK, the heat-map debug view changes the image
   and rank 0 reports the lights evaluated and reaching per pixel it counted for it (with
   an outline and a text in the view too).
 - Representation: it is offered for polygonal data and multiblock data sets (their
   blocks' points are lights), not for an unstructured grid; its array lists hold the
   point arrays with the right number of components and "(none)"; defaults pick the arrays named like the light set's defaults
   and "(none)" otherwise, never another array (e.g. the active scalars); an array with
   the wrong number of components is an error that leaves no lights, and fixing it brings
   them back; deleting the source removes its lights; shown in a stock RenderView it
   warns and lights nothing, without failing.
"""

import math
import os
import re
import sys
import xml.etree.ElementTree as ET

from paraview.simple import *  # noqa: F401,F403

import clustered_test as t

t.setup(__doc__)
here = os.path.dirname(os.path.abspath(sys.argv[0]))
root = os.path.normpath(os.path.join(here, "..", "..", "..", ".."))
header = open(os.path.join(root, "Rendering", "vtkClusteredLightingPass.h")).read()
xml = ET.parse(os.path.join(root, "Plugins", "ParaView", "ClusteredLighting",
                            "ClusteredLighting.xml")).getroot()

# ------------------------------------------------------------------ the header's options
constants = {"true": 1, "false": 0, "VTK_INT_MAX": 2 ** 31 - 1, "VTK_INT_MIN": -2 ** 31,
             "VTK_FLOAT_MAX": 3.4028234663852886e38, "VTK_DOUBLE_MAX": 1.7976931348623157e308}
for body in re.findall(r"enum\s+\w+\s*\{([^}]*)\}", header):
    for name, value in re.findall(r"(\w+)\s*=\s*(-?\d+)", body):
        constants[name] = int(value)


def evaluate(expression):
    """Value of a C++ default or clamp bound: numbers, enum constants, + - * /."""
    def value(match):
        if match.group(0) not in constants:
            raise ValueError("unknown name %s in %r" % (match.group(0), expression))
        return str(constants[match.group(0)])

    text = re.sub(r"\b[A-Za-z_]\w*\b", value, expression.strip())
    text = re.sub(r"(?<=[0-9.])[fF]\b", "", text)  # 1.0f
    if not re.fullmatch(r"[0-9eE.+\-*/() ]+", text):
        raise ValueError("cannot evaluate %r" % expression)
    return float(eval(text, {"__builtins__": {}}))  # only numbers and operators


def value_of(expression):
    """evaluate(), or a failed check and NaN."""
    try:
        return evaluate(expression)
    except ValueError as error:
        t.check(False, "header: %s" % error)
        return float("nan")


options = {}
for name, ctype in re.findall(r"vtkSetMacro\((\w+),\s*(\w+)\)", header):
    options[name] = {"type": ctype, "range": None}
for name, ctype, low, high in re.findall(
        r"vtkSetClampMacro\((\w+),\s*(\w+),\s*([^,]+),\s*([^)]+)\)", header):
    options[name] = {"type": ctype, "range": (value_of(low), value_of(high))}
# Enumerated options have setters that reject other values (not vtkSetClampMacro); their
# range is that of the constants their SetXToY methods set.
for name in re.findall(r"virtual void Set(\w+)\(int \w+\);", header):
    values = [value_of(c) for c in re.findall(
        r"void Set%sTo\w+\(\) \{ this->Set%s\((\w+)\); \}" % (name, name), header)]
    if t.check(len(values) >= 2, "%s: an enumerated option with SetXToY methods" % name):
        options[name] = {"type": "int", "range": (min(values), max(values))}
# A diagnostic whose setter does not modify the pass (it changes what is measured, not
# what is drawn): MeasureTimings.
for name in re.findall(r"void Set(\w+)\(bool \w+\) \{", header):
    options[name] = {"type": "bool", "range": None}
defaults = {name: value_of(value) for _, name, value in re.findall(
    r"^\s*(bool|int|double|float)\s+(\w+)\s*=\s*([^;]+);", header, re.M)}
t.check(len(options) >= 15, "%d options in vtkClusteredLightingPass.h: %s"
        % (len(options), ", ".join(sorted(options))))

# ----------------------------------------------------------------- the XML's properties
pass_proxy = xml.find(".//ProxyGroup[@name='clustered_lighting']/ClusteredLightingPassProxy[@name='ClusteredLightingPass']")
view_proxy = xml.find(".//RenderViewProxy[@name='ClusteredLightingView']")
exposed = {p.get("name") for p in view_proxy.iter("Property")}
properties = {}
statistics = {}
for element in pass_proxy:
    if not element.tag.endswith("VectorProperty"):
        continue
    if element.get("information_only") == "1":
        statistics[element.get("name")] = element.get("command")
    else:
        properties[element.get("name")] = element

view = CreateView("ClusteredLightingView")
view_properties = set(view.ListProperties())

for name in sorted(options):
    option = options[name]
    element = properties.get(name)
    if not t.check(element is not None, "%s: a property of the pass proxy" % name):
        continue
    problems = []
    if element.get("command") != "Set" + name:
        problems.append("command %s" % element.get("command"))
    xml_default = float(element.get("default_values"))
    if name not in defaults:
        problems.append("no default member initializer in the header")
    elif not math.isclose(xml_default, defaults[name], rel_tol=1e-12, abs_tol=0.0):
        problems.append("default %r, header %r" % (xml_default, defaults[name]))
    if option["type"] == "bool":
        if element.find("BooleanDomain") is None:
            problems.append("no BooleanDomain")
    else:
        low, high = option["range"] if option["range"] else (None, None)
        enum = element.find("EnumerationDomain")
        numbers = element.find("IntRangeDomain")
        if numbers is None:
            numbers = element.find("DoubleRangeDomain")
        if enum is not None:
            values = sorted(int(e.get("value")) for e in enum.iter("Entry"))
            if values != list(range(int(low), int(high) + 1)):
                problems.append("enumeration %s, clamp range %s .. %s" % (values, low, high))
        elif numbers is not None:
            xml_low = float(numbers.get("min")) if numbers.get("min") else None
            xml_high = float(numbers.get("max")) if numbers.get("max") else None
            if xml_low != low:
                problems.append("min %s, header %s" % (xml_low, low))
            if xml_high != high and not (xml_high is None and high == 2 ** 31 - 1):
                problems.append("max %s, header %s" % (xml_high, high))
        else:
            problems.append("no domain")
    documentation = element.find("Documentation")
    if documentation is None or not (documentation.text or "").strip():
        problems.append("no documentation")
    if name not in exposed or name not in view_properties:
        problems.append("not exposed by the view")
    t.check(not problems, "%s: %s" % (name, "; ".join(problems) if problems else
                                      "setter, default %g, domain and documentation match, "
                                      "exposed" % xml_default))

stale = sorted(set(properties) - set(options))
t.check(not stale, "pass properties without an option in the header: %s" % (stale or "none"))
missing = sorted(n for n, command in statistics.items()
                 if not re.search(r"vtkGetMacro\(%s,|\b%s\(" % (command[3:], command), header))
t.check(not missing, "statistics whose getter the header lacks: %s (of %d)"
        % (missing or "none", len(statistics)))
unexposed = sorted(set(statistics) - exposed)
t.check(not unexposed, "statistics the view does not expose: %s" % (unexposed or "none"))

# --------------------------------------------------- the properties reach the pass
view.ViewSize = [320, 240]
view.UseLight = 0
view.OrientationAxesVisibility = 0
body = Sphere(Radius=10.0, ThetaResolution=64, PhiResolution=32)
Show(body, view)
# 72 lights on a line above the sphere. A Line source is not split over ranks (its points
# are on rank 0), so the counts below hold on any number of ranks.
line = Line(Point1=[-5.0, -5.0, 10.5], Point2=[5.0, 5.0, 10.5], Resolution=71)
transform = Calculator(Input=line, ResultArrayName="Color",
                       Function="(0.5+coordsX/10)*iHat+(0.5+coordsY/10)*jHat+kHat")
lights = Show(transform, view)
lights.Representation = "Clustered Lights"
lights.LightDefaultAttenuation = [1.0, 0.0, 0.5]
positional = AddLight(view=view)
positional.Coords = "Scene"
positional.Type = "Positional"
positional.Position = [0.0, -15.0, 0.0]
view.CameraPosition = [0.0, -40.0, 30.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
Render(view)
n_set = int(t.info(lights, "NumberOfLights"))
t.check(n_set == 72, "the light set holds the 72 points of the line (%d)" % n_set)
t.check(t.info(view, "NumberOfClusteredLights") == 73,
        "73 clustered lights (72 + 1 renderer light): %d" % t.info(view, "NumberOfClusteredLights"))


def list_bytes():
    return int(t.info(view, "ListTextureBytes"))


batches = (73 + 31) // 32
t.check(list_bytes() == 32 * 16 * 32 * batches * 4,
        "default grid: list texture %d bytes (32 x 16 x 32 x %d batches x 4)" % (list_bytes(), batches))
view.TilesX, view.TilesY, view.Slices = 4, 2, 3
Render(view)
t.check(list_bytes() == 4 * 2 * 3 * batches * 4,
        "Tiles X 4, Tiles Y 2, Slices 3: list texture %d bytes (4 x 2 x 3 x %d x 4)"
        % (list_bytes(), batches))
view.TilesX, view.TilesY, view.Slices = 32, 16, 32

view.ContributionCutoff = 1.0 / 64.0
Render(view)
t.check(t.info(view, "EffectiveCutoff") == 1.0 / 64.0,
        "ContributionCutoff 1/64: effective cutoff %g" % t.info(view, "EffectiveCutoff"))
view.ErrorBudget = 4.0 / 255.0
Render(view)
# The renderer light ParaView adds is a spot light. Since 2026-11-30 spot lights are split
# like the others (this one, always on, is shaded whole everywhere), so no light is culled:
# the culled lights' cutoff stays Contribution Cutoff and the far field of the 72 split
# lights takes the whole budget (their cutoff from Contribution Cutoff outwards).
t.check(t.info(view, "NumberOfSpotLights") == 1,
        "one spot light (the renderer's): %d" % t.info(view, "NumberOfSpotLights"))
t.check(t.info(view, "EffectiveCutoff") == 1.0 / 64.0,
        "Error Budget 4/255, no culled light: cutoff %g is Contribution Cutoff"
        % t.info(view, "EffectiveCutoff"))
split = t.info(view, "EffectiveFarFieldCutoff")
t.check(split >= 1.0 / 64.0,
        "Error Budget 4/255: the split lights' cutoff %g is Contribution Cutoff or looser" % split)
# An explicit radius past their cutoff radius makes the 72 lights culled (a tail the far
# field does not hold): the budget now chooses their cutoff.
lights.LightDefaultRadius = 100.0
Render(view)
chosen = t.info(view, "EffectiveCutoff")
t.check(chosen != 1.0 / 64.0 and chosen > 0.0,
        "Error Budget 4/255, lights with a radius: the pass chose cutoff %g for their tails "
        "instead of Contribution Cutoff" % chosen)
lights.LightDefaultRadius = -1.0
view.ErrorBudget = 0.0
view.ContributionCutoff = 1.0 / 1024.0

view.MeasureTimings = 1
view.CameraPosition = [0.0, -41.0, 30.0]  # a new view: the lights are assigned again
Render(view)
t.check(t.info(view, "LastAssignmentTime") > 0.0,
        "Measure Timings: last assignment %.3f ms" % t.info(view, "LastAssignmentTime"))
view.MeasureTimings = 0

view.ClusterRendererLights = 0
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 72,
        "Cluster Renderer Lights off: %d clustered lights (72: the renderer light is VTK's)"
        % t.info(view, "NumberOfClusteredLights"))
view.ClusterRendererLights = 1

shaded = t.save(view, t.output("properties-shaded"))
view.DebugView = "Heat map"
heat = t.save(view, t.output("properties-heat-map"))
d = t.difference(shaded, heat)
t.check(d["pixels_differing"] > 0.1 * d["pixels"],
        "Debug View heat map: %d of %d pixels change" % (d["pixels_differing"], d["pixels"]))
evaluated, reaching = t.light_counts(view)
clustered = t.info(view, "NumberOfClusteredLights")
t.check(0.0 < reaching <= evaluated <= clustered,
        "Debug View heat map: rank 0 counted %.3f lights evaluated and %.3f reaching per pixel "
        "(reaching above 0, at most evaluated, at most the %d clustered lights)"
        % (evaluated, reaching, clustered))
# ParaView's default FXAA (on, from its settings) and background (the palette's, not black):
# the counting render must leave FXAA out, which blends a silhouette's encoded counts with
# the background (before 2026-11-29: 76.991 lights evaluated per pixel of 73).
fxaa = view.UseFXAA
view.UseFXAA = 1 - fxaa
Render(view)
other = t.light_counts(view)
t.check(fxaa == 1 and other == (evaluated, reaching),
        "Debug View heat map: the same counts with FXAA %s (%.3f / %.3f) as with ParaView's "
        "default, FXAA %s" % ("off" if fxaa else "on", other[0], other[1], "on" if fxaa else "off"))
view.UseFXAA = fxaa
view.DebugView = "None"
again = t.save(view, t.output("properties-shaded-again"))
t.check(t.difference(shaded, again)["max"] == 0, "Debug View None: the shaded frame again")
# An outline around the sphere (lines without normals, which VTK does not light: ParaView's
# default representation of image data) and a text: the counts take the outline's pixels
# as 0 lights and leave the text out (before 2026-11-29 each of those pixels read as its
# colour, up to 65,535 lights).
box = Box(XLength=24.0, YLength=24.0, ZLength=24.0)
outline = Show(box, view)
outline.Representation = "Outline"
caption = Text(Text="COUNTS")
Show(caption, view)
view.DebugView = "Heat map"
Render(view)
with_outline = t.light_counts(view)
t.check(0.0 < with_outline[1] <= with_outline[0] <= clustered,
        "Debug View heat map with an outline and a text: %.3f lights evaluated and %.3f "
        "reaching per pixel (at most the %d clustered lights)"
        % (with_outline[0], with_outline[1], clustered))
Delete(caption)
Delete(box)
view.DebugView = "None"

# ------------------------------------------------------------------ the representation
arrays = Calculator(Input=transform, ResultArrayName="Intensity", Function="0.5")
arrays = Calculator(Input=arrays, ResultArrayName="Unrelated", Function="coordsX")
Hide(transform, view)
rep = Show(arrays, view)
rep.Representation = "Clustered Lights"
t.check(rep.LightColorArray == "Color" and rep.LightIntensityArray == "Intensity",
        "defaults pick the arrays named Color and Intensity: %s, %s"
        % (rep.LightColorArray, rep.LightIntensityArray))
t.check(rep.LightRadiusArray == "(none)" and rep.LightConeAngleArray == "(none)",
        "defaults without such arrays: radius %s, cone angle %s ((none), not another array)"
        % (rep.LightRadiusArray, rep.LightConeAngleArray))
intensity_list = list(rep.GetProperty("LightIntensityArray").Available)
color_list = list(rep.GetProperty("LightColorArray").Available)
t.check(intensity_list[0] == "(none)" and "Intensity" in intensity_list
        and "Unrelated" in intensity_list and "Color" not in intensity_list,
        "intensity choices (1 component): %s" % intensity_list)
t.check(color_list[0] == "(none)" and "Color" in color_list and "Intensity" not in color_list,
        "color choices (3 or 4 components): %s" % color_list)
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 73,
        "lights from the arrays: %d clustered (73)" % t.info(view, "NumberOfClusteredLights"))

print("expect an error: an intensity array with 3 components")
sys.stdout.flush()
rep.LightIntensityArray = "Color"
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 1,
        "3-component intensity array: %d clustered lights (the renderer's 1 only)"
        % t.info(view, "NumberOfClusteredLights"))
rep.LightIntensityArray = "Intensity"
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 73,
        "fixed: %d clustered lights (73)" % t.info(view, "NumberOfClusteredLights"))

short_line = Line(Point1=[-5.0, 5.0, 10.5], Point2=[5.0, -5.0, 10.5], Resolution=9)
blocks = GroupDatasets(Input=[transform, short_line])
block_lights = Show(blocks, view)
t.check("Clustered Lights" in list(block_lights.GetProperty("Representation").Available),
        "offered for a multiblock data set of polygonal data")
block_lights.Representation = "Clustered Lights"
block_lights.LightDefaultAttenuation = [1.0, 0.0, 0.5]
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 73 + 72 + 10,
        "multiblock: %d clustered lights (73 + the blocks' 72 + 10 points)"
        % t.info(view, "NumberOfClusteredLights"))
Delete(blocks)
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 73,
        "multiblock deleted: %d clustered lights (73)" % t.info(view, "NumberOfClusteredLights"))
grid_display = Show(Tetrahedralize(Input=body), view)
available = list(grid_display.GetProperty("Representation").Available)
t.check("Clustered Lights" not in available and "Surface" in available,
        "not offered for an unstructured grid: %s" % available)

Delete(arrays)
Render(view)
t.check(t.info(view, "NumberOfClusteredLights") == 1,
        "source deleted: %d clustered lights (the renderer's 1)"
        % t.info(view, "NumberOfClusteredLights"))

print("expect a warning: Clustered Lights in a stock RenderView")
sys.stdout.flush()
stock = CreateView("RenderView")
stock.ViewSize = [160, 120]
stock_lights = Show(transform, stock)
stock_lights.Representation = "Clustered Lights"
Render(stock)
t.check(True, "a stock RenderView with Clustered Lights rendered")

t.finish()
