"""The Embree floor and the CSG tax over the benchmark scenes
(docs/performance.md, "Embree floor and the CSG tax").

For each scene, bench_floor (bench/bench_floor.cpp, built with
-DKERF_BUILD_BENCH=ON) lowers it with kerf's pipeline and alternates, in one
process, kerf's render() with a plain Embree nearest-hit trace of the same
leaves as one union (native spheres where they are round, else a user
geometry running kerf's primitive test) and with the user-geometry-only
variant; this script runs it per scene and prints a Markdown table.

  python3 bench/floor.py [--bench build/bench/bench_floor] [--size 1024] [--threads 1] [--runs 5] [--only REGEX]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = ["grooved_sphere", "checkered_cube", "small_shell", "large_shell", "fishbowl", "lens", "holes"]
SUMMARY = re.compile(r"summary: kerf ([\d.]+) floor ([\d.]+) user_floor ([\d.]+) tax ([\d.]+) user_tax ([\d.]+) "
                     r"time ([\d.]+)")
LEAVES = re.compile(r"floor leaves: (\d+) native spheres, (\d+) user geometry, (\d+) triangles, (\d+) skipped")
RAYS = re.compile(r"run 1: kerf [\d.]+ s (\d+)\+(\d+) rays .*?\| floor [\d.]+ s \(build [\d.]+\) (\d+)\+(\d+) rays")


def scene_files(folder):
    """(name, path): the examples' reference models, then bench/scenes.py's
    reference models and the cells and spheres families."""
    out = [(f"examples/{n}", os.path.join(ROOT, "examples", n + ".sdl")) for n in EXAMPLES]
    generated = scenes.reference_models() + [scenes.cells(n) for n in (100, 1000, 2000)]
    generated += [scenes.spheres(n) for n in (100, 1000, 10000, 100000)]
    for s in generated:
        path = os.path.join(folder, s.name + ".sdl")
        with open(path, "w") as f:
            f.write(scenes.sdl_text(s))
        out.append((s.name, path))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "bench_floor"))
    ap.add_argument("--size", type=int, default=1024)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    print(f"{a.size}², {a.threads} thread(s), {a.runs} alternating runs; MRay/s per core = (primary + shadow rays) "
          "/ (render or build + trace time) / threads; tax = median of per-run floor / kerf\n")
    print("| scene | leaves (native spheres / user / triangles) | kerf rays (primary + other) | floor rays "
          "(primary + shadow) | kerf MRay/s/core | floor MRay/s/core | **CSG tax** | user-geometry floor | "
          "tax vs. user floor | kerf time / floor time |")
    print("|---|---|---|---|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as folder:
        for name, path in scene_files(folder):
            if a.only and not re.search(a.only, name):
                continue
            p = subprocess.run([a.bench, path, str(a.size), str(a.threads), str(a.runs)], capture_output=True, text=True)
            if p.returncode != 0:
                print(f"| {name} | failed: {p.stderr.strip()[-200:]} |", flush=True)
                continue
            s, l, r = SUMMARY.search(p.stdout), LEAVES.search(p.stdout), RAYS.search(p.stdout)
            kerf, floor, user, tax, user_tax, time = (float(x) for x in s.groups())
            print(f"| {name} | {l[1]} / {l[2]} / {l[3]}{' (' + l[4] + ' skipped)' if l[4] != '0' else ''} | "
                  f"{r[1]} + {r[2]} | {r[3]} + {r[4]} | {kerf:.2f} | {floor:.2f} | **{tax:.2f}×** | {user:.2f} | "
                  f"{user_tax:.2f}× | {time:.2f}× |", flush=True)


if __name__ == "__main__":
    main()
