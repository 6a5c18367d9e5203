#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes lights.csv, the input of lights_from_csv.py: one light per row, columns
x,y,z,r,g,b,intensity (colors in [0, 1]). 320 lights on four rings over a 8 x 8 floor
at y = 0, each ring a band of hues. Deterministic: running it again writes the same file.

    /usr/bin/python3 Examples/Python/make_lights_csv.py > Examples/Python/lights.csv
"""

import math
import sys


def main():
    out = sys.stdout
    out.write("x,y,z,r,g,b,intensity\n")
    rings = ((1.2, 0.35, 48), (2.1, 0.55, 72), (2.9, 0.3, 88), (3.6, 0.7, 112))
    for ring, (radius, height, count) in enumerate(rings):
        for i in range(count):
            angle = 2.0 * math.pi * (i + 0.5 * ring) / count
            hue = (ring / len(rings) + 0.25 * i / count) % 1.0
            rgb = [0.5 + 0.5 * math.cos(2.0 * math.pi * (hue + k / 3.0)) for k in range(3)]
            intensity = 0.6 + 0.4 * ((i * 7 + ring) % 5) / 4.0
            out.write("%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%.3f\n" % (
                radius * math.cos(angle), height, radius * math.sin(angle),
                rgb[0], rgb[1], rgb[2], intensity))
    return 0


if __name__ == "__main__":
    sys.exit(main())
