# SPDX-License-Identifier: BSD-3-Clause
"""help() of the wrapped classes reads well: no text mangled by VTK's wrapper (a class
comment's vtkNew<...> came out as "vtkNewpass", Markdown tables as jumbled lines), and
every method the classes declare has doc text (getters inside a //@{ group had none)."""
import re
import sys

from clusteredlighting import vtkClusteredLightingPass, vtkClusteredLightSet

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED: " + what)


# Patterns that only appear when the wrapper mangled a doc comment.
MANGLED = [
    (re.compile(r"vtkNew\w"), "a template argument dropped after vtkNew"),
    (re.compile(r"^\s*\|?\s*\|[-: |]+\|\s*$", re.M), "a Markdown table rule"),
    (re.compile(r"\|\s*---"), "a Markdown table cell"),
    (re.compile(r"@\{|@\}|///"), "a Doxygen group marker"),
    (re.compile(r"\\(brief|class|sa)\b"), "a raw Doxygen command"),
]

for cls, first in ((vtkClusteredLightingPass, "renderer.SetPass(pass)"),
                   (vtkClusteredLightSet, "AddLightSet")):
    name = cls.__name__
    # The text VTK's wrapper made: the class doc and every method's doc (pydoc's own
    # section rules are not ours).
    text = cls.__doc__ + "".join(
        getattr(cls, m).__doc__ or "" for m in vars(cls) if callable(getattr(cls, m)))
    for pattern, what in MANGLED:
        match = pattern.search(text)
        check(match is None, "%s help() has %s: %r" % (name, what, match.group(0) if match else ""))
    check(first in cls.__doc__, "%s class doc names %s" % (name, first))
    # Every method the class itself declares has doc text after its signature lines.
    undocumented = []
    for method in sorted(vars(cls)):
        # Enum constants and types are data; NewInstance and SafeDownCast are VTK's own.
        if method.startswith("_") or method in ("NewInstance", "SafeDownCast") or \
                not type(getattr(cls, method)).__name__.endswith("method_descriptor"):
            continue
        doc = getattr(cls, method).__doc__ or ""
        body = doc.split("\n\n", 1)[1].strip() if "\n\n" in doc else ""
        if not body:
            undocumented.append(method)
    check(not undocumented, "%s methods without doc text: %s" % (name, ", ".join(undocumented)))
    print("%s: %d attributes, %d lines of doc text" % (name, len(vars(cls)), text.count("\n")))

# Enumerated options have named setters and string getters (issue 14, item 6).
p = vtkClusteredLightingPass()
for option, values in (("ShadingMode", ("Clustered", "BruteForce")),
                       ("Falloff", ("HardCut", "Windowed")),
                       ("SlicingScheme", ("Auto", "Exponential", "Linear")),
                       ("DebugView", ("None", "ClusterIndex", "HeatMap", "EvaluatedCount",
                                      "ReachedCount", "NonFinite", "Normal")),
                       ("BoundsMethod", ("Tangent", "CenterDepthQuad"))):
    for index, value in enumerate(values):
        getattr(p, "Set%sTo%s" % (option, value))()
        check(getattr(p, "Get%s" % option)() == index, "Set%sTo%s sets %d" % (option, value, index))
        check(getattr(p, "Get%sAsString" % option)() == value,
              "Get%sAsString() is %r after Set%sTo%s" % (option, getattr(p, "Get%sAsString" % option)(),
                                                         option, value))

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("help() text and enumerated options: OK")
