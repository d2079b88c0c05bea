#!/usr/bin/env python3
"""A checker-textured cube rendered by kerf and by POV-Ray 3.7 from the same
description (docs/quality.md, "Patterns"): same camera, light and cells.

Colours: `color` red and `color2` blue, so a pixel's cell is read from its
hue (red > blue or blue > red) whatever the lighting; the grey background
has neither. Reported: the silhouettes' IoU and, over the pixels both
renderers see the cube in, the share whose cell agrees. POV-Ray's checker
is the oracle: it is POV-Ray's own pattern, not kerf's code.

Coordinates as bench/scenes.py: POV-Ray gets kerf's world through
(x, y, z) -> (x, z, y); the checker's sum of floors does not change.

    python3 bench/checker_twin.py --kerf build/kerf --out /tmp/twin [--size 400]
"""
import argparse
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import masks  # noqa: E402

CAM, AT, FOV, LIGHT = (9, -7, 8), (2, 2, 2), 40, (10, -4, 12)
SCALE = 1.0  # cell size; the cube is 4 units, so 4 × 4 cells per face


def sdl():
    return (f"camera(position = [{CAM[0]}, {CAM[1]}, {CAM[2]}], look_at = [{AT[0]}, {AT[1]}, {AT[2]}], fov = {FOV});\n"
            f"light(position = [{LIGHT[0]}, {LIGHT[1]}, {LIGHT[2]}], intensity = 1);\n"
            "background([0.2, 0.2, 0.2]);\n"
            'material(color = "red", color2 = "blue", pattern = "checker", '
            f"pattern_scale = {SCALE}, diffuse = 0.8, specular = 0)\n"
            "    translate([0.001, 0.001, 0.001]) cube(4);  // off the cell boundaries: no tie for either renderer\n")


def pov(w, h):
    sw = lambda v: f"<{v[0]}, {v[2]}, {v[1]}>"  # noqa: E731
    hfov = math.degrees(2 * math.atan(math.tan(math.radians(FOV / 2)) * w / h))
    return ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
            f"camera {{ perspective location {sw(CAM)} right x*{w / h} up y sky <0, 1, 0> angle {hfov!r} look_at {sw(AT)} }}\n"
            "background { srgb 0.2 }\n"
            f"light_source {{ {sw(LIGHT)} color rgb 1 }}\n"
            "box { <0.001, 0.001, 0.001>, <4.001, 4.001, 4.001>\n"
            f"  texture {{ pigment {{ checker color rgb <1, 0, 0> color rgb <0, 0, 1> scale {SCALE} }}\n"
            "            finish { ambient 0.1 diffuse 0.8 } }\n"
            "  matrix <1, 0, 0,  0, 0, 1,  0, 1, 0,  0, 0, 0> }\n")


def classes(path):
    """Per pixel: 0 background (no hue), 1 red cell, 2 blue cell."""
    w, h, ch, px = masks.read_pnm(path)
    out = bytearray(w * h)
    for i in range(w * h):
        r, b = px[i * ch], px[i * ch + 2]
        out[i] = 0 if abs(r - b) < 12 else (1 if r > b else 2)
    return w, h, out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kerf", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--size", type=int, default=400)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    n = a.size
    base = os.path.join(a.out, "checker_cube")
    open(base + ".sdl", "w").write(sdl())
    open(base + ".pov", "w").write(pov(n, n))
    t0 = time.time()
    subprocess.run([a.kerf, "render", base + ".sdl", "-o", base + ".kerf.ppm", "-W", str(n), "-H", str(n), "--aa", "off"],
                   check=True)
    t1 = time.time()
    subprocess.run(["povray", "+I" + base + ".pov", "+O" + base + ".pov.ppm", f"+W{n}", f"+H{n}", "-A", "-D", "-V",
                    "-GA", "+FP"], check=True)
    t2 = time.time()
    _, _, k = classes(base + ".kerf.ppm")
    _, _, p = classes(base + ".pov.ppm")
    both = sum(1 for x, y in zip(k, p) if x and y)
    either = sum(1 for x, y in zip(k, p) if x or y)
    agree = sum(1 for x, y in zip(k, p) if x and x == y)
    print(f"size {n}x{n}: kerf {t1 - t0:.2f} s, povray {t2 - t1:.2f} s (wall, whole process)")
    print(f"silhouette IoU {both / either:.4f}; cells agree on {agree}/{both} = {agree / both:.4f} of shared pixels")
    return 0 if both / either >= 0.97 and agree / both >= 0.97 else 1


if __name__ == "__main__":
    sys.exit(main())
