#!/usr/bin/env python3
"""Silhouettes of kerf against OpenSCAD's own meshes (docs/openscad.md,
"Equivalence with OpenSCAD's own meshes").

For each example file of Debian's `openscad` package with a 3D result:
OpenSCAD exports its mesh (`openscad -o f.stl FILE`, run from the file's
folder); kerf renders the file itself (`--facets openscad --look plain`)
and a wrapper `import("f.stl");` from one camera framing the mesh, both as
the hit mask: the depth AOV (`--aov depth`, whose PGM is 0 exactly where
the ray misses the solid; `--aov hits` counts the spans the tracer found,
of primitives a CSG operation may remove, so it is no silhouette); the two masks'
IoU must be at least 0.98. The camera is given to both the same way, as
`-D '$vpr=..' -D '$vpt=..' -D '$vpd=..'` (kerf's default camera honours
them, docs/openscad.md "Viewport"), so only the geometry differs.

A file whose result is 2D or empty, an OpenSCAD failure or timeout is
"skipped: reason", never a pass. `%` parts are in neither (OpenSCAD leaves
them out of the STL, kerf out of the solid), `#` parts in both, `!` picks
the same root in both; `$t` is 0 in both; `rands` with a seed is the same
sequence in both (without one the file is listed as random and skipped).

usage: scripts/openscad_equivalence.py [--kerf build/kerf]
         [--examples /usr/share/openscad/examples] [--size 256]
         [--timeout 60] [--only Basics/CSG.scad,...] [--keep DIR]
exit: 0 all compared files pass, 1 an IoU below the threshold or a kerf
failure, 2 bad usage, 77 openscad or the examples missing (skipped).
"""
import argparse
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time

THRESHOLD = 0.98
VPR = (55.0, 0.0, 25.0)  # OpenSCAD's default view, from front right
VPF = 22.5  # OpenSCAD's default vertical field of view, degrees


def stl_bounds(path):
    """Bounds (lo, hi) and triangle count of an ASCII or binary STL."""
    data = open(path, "rb").read()
    points = []
    if data[:5] == b"solid" and b"facet" in data[:1000]:
        for m in re.finditer(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data):
            points.append(tuple(float(v) for v in m.groups()))
    else:
        n = struct.unpack_from("<I", data, 80)[0]
        for i in range(n):
            v = struct.unpack_from("<12f", data, 84 + 50 * i)
            points += [v[3:6], v[6:9], v[9:12]]
    if not points:
        return None, None, 0
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    return lo, hi, len(points) // 3


def read_pgm_mask(path):
    """The set of nonzero pixels of a binary PGM (P5, 8 or 16 bit)."""
    data = open(path, "rb").read()
    tokens, pos = [], 0
    while len(tokens) < 4:
        m = re.compile(rb"\s*(#[^\n]*\n\s*)*(\S+)").match(data, pos)
        tokens.append(m.group(2))
        pos = m.end()
    if tokens[0] != b"P5":
        raise ValueError(f"{path}: not a binary PGM")
    w, h, maxval = int(tokens[1]), int(tokens[2]), int(tokens[3])
    pixels = data[pos + 1:]
    step = 2 if maxval > 255 else 1
    mask = bytearray(w * h)
    for i in range(w * h):
        mask[i] = any(pixels[i * step:(i + 1) * step])
    return w, h, mask


def camera(lo, hi):
    """-D arguments for a camera at OpenSCAD's default angle that frames the
    box (its bounding sphere fills about 90 % of the square image)."""
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    radius = max(0.5 * math.dist(lo, hi), 1e-6)
    distance = 1.1 * radius / math.sin(math.radians(VPF / 2))
    vec = lambda v: "[" + ",".join(repr(round(x, 6)) for x in v) + "]"
    return ["-D", f"$vpr={vec(VPR)}", "-D", f"$vpt={vec(centre)}",
            "-D", f"$vpd={distance!r}", "-D", f"$vpf={VPF}"]


def kerf_mask(kerf, scene, folder, out, size, cam):
    cmd = [kerf, "render", scene, "-o", out, "--aov", "depth", "-W", str(size),
           "-H", str(size), "--facets", "openscad", "--look", "plain",
           "--no-progress"] + cam
    r = subprocess.run(cmd, cwd=folder, capture_output=True, text=True,
                       timeout=600)
    if r.returncode != 0:
        lines = r.stderr.strip().splitlines() or ["?"]
        first = next((l for l in lines if "error:" in l), lines[-1])
        raise RuntimeError(f"kerf exit {r.returncode}: {first}")
    return read_pgm_mask(out)[2]


def compare(path, args, work):
    """One file: ('pass'|'fail'|'skipped', IoU or None, detail, seconds)."""
    folder, name = os.path.split(path)
    text = open(path, encoding="utf-8", errors="replace").read()
    if re.search(r"\brands\s*\(", text) and not re.search(
            r"\brands\s*\([^;]*,[^;]*,[^;]*,", text):
        return "skipped", None, "random: rands() without a seed", None
    stl = os.path.join(work, "openscad.stl")
    if os.path.exists(stl):
        os.remove(stl)
    t0 = time.monotonic()
    try:
        r = subprocess.run([args.openscad, "-o", stl, name], cwd=folder,
                           capture_output=True, text=True,
                           timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return "skipped", None, f"openscad timed out after {args.timeout} s", None
    seconds = time.monotonic() - t0
    log = r.stderr
    if "not a 3D object" in log:
        return "skipped", None, "2D only: no 3D result", seconds
    if "top level object is empty" in log:
        return "skipped", None, "empty: no 3D result", seconds
    if r.returncode != 0 or not os.path.exists(stl):
        last = (log.strip().splitlines() or ["?"])[-1]
        return "skipped", None, f"openscad failed: {last}", seconds
    lo, hi, triangles = stl_bounds(stl)
    if not triangles:
        return "skipped", None, "empty: no triangles in the STL", seconds
    cam = camera(lo, hi)
    wrapper = os.path.join(work, "mesh.scad")
    with open(wrapper, "w") as f:
        f.write(f'import("{stl}");\n')
    try:
        a = kerf_mask(args.kerf, name, folder,
                      os.path.join(work, "kerf.pgm"), args.size, cam)
        b = kerf_mask(args.kerf, wrapper, work,
                      os.path.join(work, "mesh.pgm"), args.size, cam)
    except (RuntimeError, subprocess.TimeoutExpired) as e:
        return "fail", None, str(e), seconds
    inter = sum(1 for x, y in zip(a, b) if x and y)
    union = sum(1 for x, y in zip(a, b) if x or y)
    iou = inter / union if union else 0.0
    detail = f"kerf {sum(a)} px, OpenSCAD {sum(b)} px, differ {union - inter}"
    if args.keep:
        stem = os.path.join(args.keep, os.path.relpath(path, args.examples).replace(os.sep, "_"))
        for f in ("kerf.pgm", "mesh.pgm", "openscad.stl"):
            shutil.copy(os.path.join(work, f), f"{stem}.{f}")
    return ("pass" if iou >= THRESHOLD else "fail"), iou, detail, seconds


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--kerf", default="build/kerf")
    p.add_argument("--openscad", default="openscad")
    p.add_argument("--examples", default="/usr/share/openscad/examples")
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--timeout", type=float, default=60)
    p.add_argument("--only", default="",
                   help="comma-separated paths under --examples")
    p.add_argument("--keep", default="",
                   help="folder to keep each file's masks and STL in")
    args = p.parse_args()
    if not shutil.which(args.openscad):
        print(f"openscad equivalence: skipped (no '{args.openscad}' on the "
              "PATH; apt-get install openscad)")
        return 77
    if not os.path.isdir(args.examples):
        print(f"openscad equivalence: skipped (no {args.examples}; "
              "apt-get install openscad)")
        return 77
    if not os.access(args.kerf, os.X_OK):
        print(f"openscad equivalence: no kerf binary at {args.kerf}",
              file=sys.stderr)
        return 2
    args.kerf = os.path.abspath(args.kerf)
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
    if args.only:
        files = [os.path.join(args.examples, f) for f in args.only.split(",")]
    else:
        files = sorted(os.path.join(d, f)
                       for d, _, fs in os.walk(args.examples)
                       for f in fs if f.endswith(".scad"))
    counts = {"pass": 0, "fail": 0, "skipped": 0}
    print(f"{'file':34} {'IoU':>7} {'openscad s':>10}  result")
    with tempfile.TemporaryDirectory(prefix="kerf-equiv-") as work:
        for path in files:
            status, iou, detail, seconds = compare(path, args, work)
            counts[status] += 1
            rel = os.path.relpath(path, args.examples)
            shown = f"{iou:.4f}" if iou is not None else "-"
            secs = f"{seconds:.1f}" if seconds is not None else "-"
            word = "skipped: " + detail if status == "skipped" else \
                f"{status}: {detail}"
            print(f"{rel:34} {shown:>7} {secs:>10}  {word}", flush=True)
    print(f"{counts['pass']} passed, {counts['fail']} failed, "
          f"{counts['skipped']} skipped")
    return 1 if counts["fail"] else 0


if __name__ == "__main__":
    sys.exit(main())
