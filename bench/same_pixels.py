"""Same pixels before and after a change that should not change pictures
(a refactoring, a speed-up): renders every example and every benchmark scene
with one kerf binary, in colour and in the three AOVs, and records the SHA-256 of each PNG and
of each `kerf dump`; with --compare, checks them against an earlier run.

    python3 bench/same_pixels.py --kerf OLD/kerf --out /tmp/before
    python3 bench/same_pixels.py --kerf build/kerf --out /tmp/after --compare /tmp/before

Exit status 1 when any image differs or fails to render.
"""
import argparse
import hashlib
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Small images keep the run to a couple of minutes; 4 spp and a crop exercise
# the jittered and cropped paths too.
VARIANTS = [("color", ["-W", "160", "-H", "120"]),
            ("spp4", ["-W", "96", "-H", "72", "--spp", "4", "--seed", "7"]),
            ("depth", ["-W", "96", "-H", "72", "--aov", "depth"]),
            ("normal", ["-W", "96", "-H", "72", "--aov", "normal"]),
            ("hits", ["-W", "96", "-H", "72", "--aov", "hits"])]
LIMITS = ["--max-primitives", "2000000"]


def scene_files(out):
    files = []
    for name in sorted(os.listdir(os.path.join(ROOT, "examples"))):
        if name.endswith(".sdl"):
            files.append((name[:-4], os.path.join(ROOT, "examples", name)))
    d = os.path.join(out, "scenes")
    os.makedirs(d, exist_ok=True)
    for s in scenes.reference_models() + scenes.families():
        path = os.path.join(d, s.name + ".sdl")
        with open(path, "w") as f:
            f.write(scenes.sdl_text(s))
        files.append(("bench_" + s.name, path))
    return files


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--kerf", default=os.path.join(ROOT, "build", "kerf"))
    p.add_argument("--out", required=True)
    p.add_argument("--compare", help="folder of an earlier run (its sha256.txt)")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    sums, failed = {}, []
    for name, path in scene_files(a.out):
        for variant, args in VARIANTS:
            png = os.path.join(os.path.abspath(a.out), f"{name}.{variant}.png")
            r = subprocess.run([a.kerf, "render", os.path.basename(path), "-o", png, "--threads", "2"] + args + LIMITS,
                               capture_output=True, text=True, cwd=os.path.dirname(path))
            key = f"{name}.{variant}"
            if r.returncode != 0:
                failed.append(f"{key}: exit {r.returncode}: {r.stderr.strip()[:200]}")
                continue
            sums[key] = hashlib.sha256(open(png, "rb").read()).hexdigest()
        # The lowered tree itself (kerf dump), so a change that keeps the
        # pixels of these small images but alters the scene shows too.
        # (Relative paths: the dump names the scene file.)
        r = subprocess.run([a.kerf, "dump", os.path.basename(path)] + LIMITS, capture_output=True,
                           cwd=os.path.dirname(path))
        if r.returncode != 0:
            failed.append(f"{name}.dump: exit {r.returncode}")
        else:
            sums[f"{name}.dump"] = hashlib.sha256(r.stdout).hexdigest()
    with open(os.path.join(a.out, "sha256.txt"), "w") as f:
        for k in sorted(sums):
            f.write(f"{sums[k]}  {k}\n")
    print(f"{len(sums)} images rendered into {a.out}")
    if a.compare:
        before = {}
        for line in open(os.path.join(a.compare, "sha256.txt")):
            h, k = line.split()
            before[k] = h
        for k in sorted(set(before) | set(sums)):
            if before.get(k) != sums.get(k):
                failed.append(f"{k}: differs" if k in before and k in sums else f"{k}: only in one run")
        print(f"compared with {a.compare}: {len(before)} images before")
    for f in failed:
        print("FAIL", f)
    if not failed:
        print("same pixels" if a.compare else "ok")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
