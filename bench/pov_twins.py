#!/usr/bin/env python3
"""A glass lens, an area-lit open shell and a checker-textured cube rendered by
kerf and by POV-Ray 3.7 from one description each (docs/quality.md, "Side by
side with POV-Ray"): same camera, same lights, same solids
(bench/checker_twin.py checks the checker's cells themselves).

For each scene:
- silhouettes: the object alone (no backdrop, no ground), kerf's depth AOV
  against POV-Ray's white-on-black Mask variant; IoU >= 0.97 or exit 1;
- a ladder of quality settings per renderer, each timed (median of 3, wall
  and CPU of the whole process, 2 threads), each scored by its RMS error
  (8-bit sRGB codes, whole image) against that renderer's own high-quality
  reference. Each renderer is its own oracle: the two shade differently
  (kerf's Blinn-Phong vs POV-Ray's finish), so no cross-renderer error is
  meaningful; "equal error" is the cheapest setting of each whose error is
  at most the larger of the two defaults' errors (a level both reach).

Coordinates as bench/scenes.py: POV-Ray gets kerf's world through
(x, y, z) -> (x, z, y), the swap matrix on each object.

    python3 bench/pov_twins.py --kerf build/kerf --out /tmp/twins [--size 320x240] [--only lens,shell,checker]
"""
import argparse
import math
import os
import resource
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import masks  # noqa: E402

SWAP = "matrix <1, 0, 0,  0, 0, 1,  0, 1, 0,  0, 0, 0>"


def sw(v):
    return f"<{v[0]}, {v[2]}, {v[1]}>"


class Lens:
    """Biconvex glass lens (examples/lens.sdl's two spheres, axis toward the
    camera) before a checkered wall, so the refraction shows."""
    name, cam, at, fov, light = "lens", (0.5, -3.4, 0.7), (0, 0, 0), 40, (3, -4, 5)

    def sdl(self, mask):
        wall = "" if mask else (
            'material(color = "white", color2 = "black", pattern = "checker", pattern_scale = 0.5, diffuse = 0.8, specular = 0)\n'
            "    translate([-4, 2.05, -3]) cube([8, 0.2, 6]);\n")
        return ("material(color = \"white\", transparency = 0.9, ior = 1.5, diffuse = 0.8, specular = 0.6, shininess = 120)\n"
                "intersection() { translate([0, -0.6, 0]) sphere(1); translate([0, 0.6, 0]) sphere(1); }\n" + wall)

    def pov(self, mask):
        look = ("texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } }" if mask else
                "texture { pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0.1 diffuse 0.8 specular 0.6 roughness 0.005\n"
                "          reflection { 0 1 fresnel on } conserve_energy } }\n  interior { ior 1.5 }")
        wall = "" if mask else (
            "box { <-4, 2.05, -3>, <4, 2.25, 3>\n"
            "  texture { pigment { checker color rgb 1 color rgb 0 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }\n"
            f"  {SWAP} }}\n")
        return (f"intersection {{ sphere {{ <0, -0.6, 0>, 1 }} sphere {{ <0, 0.6, 0>, 1 }}\n  {look}\n  {SWAP} }}\n" + wall)


class Shell:
    """A hollow sphere cut open (a bowl, tilted) above a ground slab, lit by
    a spherical light of radius 0.4: soft shadows inside and on the ground."""
    name, cam, at, fov, light = "shell", (3.5, -5, 3), (0, 0, -0.4), 40, (2.5, -1, 4)
    radius = 0.4

    def sdl(self, mask):
        ground = "" if mask else (
            'material(color = [0.8, 0.8, 0.8], diffuse = 0.8, specular = 0) translate([-5, -5, -1.6]) cube([10, 10, 0.3]);\n')
        return ('material(color = [0.95, 0.8, 0.6], diffuse = 0.8, specular = 0)\n'
                "rotate([25, 0, 0]) difference() { sphere(1); sphere(0.9); translate([-2, -2, 0.3]) cube([4, 4, 2]); }\n"
                + ground)

    def pov(self, mask):
        look = ("texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } }" if mask else
                "texture { pigment { srgb <0.95, 0.8, 0.6> } finish { ambient 0.1 diffuse 0.8 } }")
        ground = "" if mask else (
            "box { <-5, -5, -1.6>, <5, 5, -1.3>\n"
            "  texture { pigment { srgb 0.8 } finish { ambient 0.1 diffuse 0.8 } }\n"
            f"  {SWAP} }}\n")
        return ("difference { sphere { 0, 1 } sphere { 0, 0.9 } box { <-2, -2, 0.3>, <2, 2, 2.3> }\n"
                f"  rotate <25, 0, 0>\n  {look}\n  {SWAP} }}\n" + ground)


class Checker:
    """bench/checker_twin.py's cube: red and blue cells of size 1 on a 4-unit
    cube, kerf's `pattern = "checker"` against POV-Ray's `pigment { checker }`."""
    name, cam, at, fov, light = "checker", (9, -7, 8), (2, 2, 2), 40, (10, -4, 12)

    def sdl(self, mask):
        look = ('material(color = "white")' if mask else
                'material(color = "red", color2 = "blue", pattern = "checker", pattern_scale = 1, diffuse = 0.8, specular = 0)')
        return look + "\n    translate([0.001, 0.001, 0.001]) cube(4);  // off the cell boundaries\n"

    def pov(self, mask):
        look = ("texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } }" if mask else
                "texture { pigment { checker color rgb <1, 0, 0> color rgb <0, 0, 1> scale 1 }\n"
                "            finish { ambient 0.1 diffuse 0.8 } }")
        return f"box {{ <0.001, 0.001, 0.001>, <4.001, 4.001, 4.001>\n  {look}\n  {SWAP} }}\n"


def kerf_text(s, mask, samples):
    r = f", radius = {s.radius}, samples = {samples}" if getattr(s, "radius", 0) else ""
    return (f"camera(position = [{s.cam[0]}, {s.cam[1]}, {s.cam[2]}], look_at = [{s.at[0]}, {s.at[1]}, {s.at[2]}], fov = {s.fov});\n"
            f"light(position = [{s.light[0]}, {s.light[1]}, {s.light[2]}], intensity = 1{r});\n"
            "background([0.2, 0.2, 0.2]);\n" + s.sdl(mask))


def pov_text(s, w, h, mask, n):
    hfov = math.degrees(2 * math.atan(math.tan(math.radians(s.fov / 2)) * w / h))
    d = 2 * getattr(s, "radius", 0)  # POV-Ray's area light axes span the disk's diameter
    area = f" area_light <{d}, 0, 0>, <0, 0, {d}>, {n}, {n} circular orient adaptive 1 jitter" if d else ""
    return ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 5 }\n"
            f"camera {{ perspective location {sw(s.cam)} right x*{w / h} up y sky <0, 1, 0> angle {hfov!r} look_at {sw(s.at)} }}\n"
            + ("background { rgb 0 }\n" if mask else
               f"background {{ srgb 0.2 }}\nlight_source {{ {sw(s.light)} color rgb 1{area} }}\n")
            + s.pov(mask))


def timed(cmd):
    """(wall s, CPU s of the child) of one whole process."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def rms(a, b):
    _, _, _, pa = masks.read_pnm(a)
    _, _, _, pb = masks.read_pnm(b)
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(pa, pb)) / len(pa))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kerf", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--only", default="lens,shell,checker", help="comma-separated scene names")
    a = ap.parse_args()
    w, h = (int(v) for v in a.size.split("x"))
    os.makedirs(a.out, exist_ok=True)
    ok = True
    for s in (x for x in (Lens(), Shell(), Checker()) if x.name in a.only.split(",")):
        base = os.path.join(a.out, s.name)
        kerf = lambda src, out, extra: [a.kerf, "render", src, "-o", out, "-W", str(w), "-H", str(h),  # noqa: E731
                                        "--threads", "2", "--no-progress"] + extra
        pov = lambda src, out, extra: ["povray", "+I" + src, "+O" + out, f"+W{w}", f"+H{h}", "-D", "-V", "-GA",  # noqa: E731
                                       "+FP", "+WT2"] + extra
        # Silhouettes of the object alone.
        open(base + ".mask.sdl", "w").write(kerf_text(s, True, 16))
        open(base + ".mask.pov", "w").write(pov_text(s, w, h, True, 5))
        subprocess.run(kerf(base + ".mask.sdl", base + ".kerf.mask.pgm", ["--aov", "depth", "--aa", "off"]), check=True)
        subprocess.run(pov(base + ".mask.pov", base + ".pov.mask.ppm", ["-A"]), check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        iou, nk, np_ = masks.iou(base + ".kerf.mask.pgm", base + ".pov.mask.ppm")
        print(f"{s.name}: silhouette IoU {iou:.4f} (kerf {nk} px, POV-Ray {np_} px)")
        ok &= iou >= 0.97
        # Quality ladders: (label, scene samples, extra args); the last is the reference.
        kl = [("--aa off", 16, ["--aa", "off"]), ("default", 16, []),
              ("--spp 16, samples 64", 64, ["--spp", "16"]),
              ("reference --spp 64, samples 256", 256, ["--spp", "64"])]
        pl = [("-A", 5, ["-A"]), ("+A0.3 (default AA)", 5, ["+A0.3"]), ("+A0.1 +R3, 9x9", 9, ["+A0.1", "+R3"]),
              ("reference +A0.0 +AM2 +R4, 17x17", 17, ["+A0.0", "+AM2", "+R4"])]
        rows = []
        for who, ladder, text, cmd, ext in (("kerf", kl, lambda n: kerf_text(s, False, n), kerf, "sdl"),
                                            ("POV-Ray", pl, lambda n: pov_text(s, w, h, False, n), pov, "pov")):
            ref = None
            for i, (label, n, extra) in enumerate(reversed(ladder)):
                src = f"{base}.{who}.{i}.{ext}"
                out = f"{base}.{who}.{i}.ppm"
                open(src, "w").write(text(n))
                runs = [timed(cmd(src, out, extra)) for _ in range(1 if i == 0 else a.runs)]
                wall = statistics.median(r[0] for r in runs)
                cpu = statistics.median(r[1] for r in runs)
                err = 0.0 if ref is None else rms(out, ref)
                ref = ref or out
                rows.append((who, label, wall, cpu, err, out))
        for who, label, wall, cpu, err, _ in rows:
            print(f"| {s.name} | {who} | {label} | {wall:.2f} | {cpu:.2f} | {err:.2f} |")
        default = {r[0]: r for r in rows if r[1] == "default" or r[1].startswith("+A0.3")}
        target = max(r[4] for r in default.values())
        for who in ("kerf", "POV-Ray"):
            fits = [r for r in rows if r[0] == who and r[4] <= target]
            best = min(fits, key=lambda r: r[2])
            print(f"{s.name}: {who} at RMS <= {target:.2f}: {best[1]}, {best[2]:.2f} s wall, {best[3]:.2f} s CPU")
        # Side by side: each renderer's default setting, kerf left.
        subprocess.run(["convert", default["kerf"][5], default["POV-Ray"][5], "+append", "-strip", base + "_twin.png"], check=True)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
