"""2D regions at 1024² (docs/performance.md, "2D regions"): the 1,000-vertex
involute gear (examples/gear_involute.sdl) against the 7-primitive grooved
sphere, and a 40-glyph line of text, rendered by two kerf binaries in one
alternating run (A, B, A, B, ...), whole-process wall and CPU time.

    python3 bench/regions_2d.py --a OLD/kerf --b build/kerf --pairs 7

Prints per scene and binary the median wall and CPU seconds, and the median
of the per-pair B/A ratios. Images are written to a temporary folder and
compared byte for byte between A and B (the speed-up must not change them).
"""
import argparse
import os
import resource
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEXT40 = 'linear_extrude(2) text("Jackdaws love my big sphinx of quartz, 12345678");\n'  # 40 glyphs


def run(kerf, scene, png, threads):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([kerf, "render", scene, "-o", png, "-W", "1024", "-H", "1024", "--threads", str(threads),
                    "--no-progress"], check=True, capture_output=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--a", required=True, help="kerf binary A (before)")
    p.add_argument("--b", required=True, help="kerf binary B (after)")
    p.add_argument("--pairs", type=int, default=7)
    p.add_argument("--threads", type=int, default=2)
    a = p.parse_args()
    tmp = tempfile.mkdtemp(prefix="regions_2d_")
    text = os.path.join(tmp, "text40.sdl")
    with open(text, "w") as f:
        f.write(TEXT40)
    scenes = [("gear_involute", os.path.join(ROOT, "examples", "gear_involute.sdl")),
              ("grooved_sphere", os.path.join(ROOT, "examples", "grooved_sphere.sdl")),
              ("text40", text)]
    print("load before:", os.getloadavg())
    res = {(s, k): [] for s, _ in scenes for k in "ab"}
    for _ in range(a.pairs):
        for name, path in scenes:
            for k, kerf in (("a", a.a), ("b", a.b)):
                res[(name, k)].append(run(kerf, path, os.path.join(tmp, f"{name}.{k}.png"), a.threads))
    print("load after:", os.getloadavg())
    for name, _ in scenes:
        ra, rb = res[(name, "a")], res[(name, "b")]
        same = open(os.path.join(tmp, f"{name}.a.png"), "rb").read() == open(os.path.join(tmp, f"{name}.b.png"), "rb").read()
        print(f"{name}: A wall {statistics.median(x[0] for x in ra):.3f} s cpu {statistics.median(x[1] for x in ra):.3f} s"
              f" | B wall {statistics.median(x[0] for x in rb):.3f} s cpu {statistics.median(x[1] for x in rb):.3f} s"
              f" | B/A wall {statistics.median(y[0] / x[0] for x, y in zip(ra, rb)):.3f}"
              f" cpu {statistics.median(y[1] / x[1] for x, y in zip(ra, rb)):.3f} | same image: {same}")


if __name__ == "__main__":
    main()
