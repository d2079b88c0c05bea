"""Process start-up of kerf (docs/performance.md, "Start-up").

Renders a tiny scene (one sphere, 16x16, so nearly all of the run is
loading the program, parsing and writing the PNG) with two kerf binaries
alternately (A, B, A, B, ...), `runs` pairs, and prints the medians of the
whole-process wall time and CPU time (user + system) of each, the median
of the per-pair ratios B / A, and the shared libraries each loads
(`ldd`). With one binary it times only that one.

  python3 bench/startup.py [--runs 21] [--against OTHER_KERF] [KERF]
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = """camera(position = [3, 3, 2], look_at = [0, 0, 0]);
light(position = [5, -5, 10]);
sphere(1);
"""


def cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(kerf, scene, out):
    """(wall s, CPU s) of one whole kerf process."""
    c0 = cpu_children()
    t0 = time.perf_counter()
    p = subprocess.run([kerf, "render", scene, "-o", out, "-W", "16", "-H", "16", "--no-progress"],
                       capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    return wall, cpu_children() - c0


def libraries(kerf):
    lines = subprocess.run(["ldd", kerf], capture_output=True, text=True, check=True).stdout.splitlines()
    return [ln.split()[0] for ln in lines if ln.strip() and "vdso" not in ln]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kerf", nargs="?", default=os.path.join(ROOT, "build", "kerf"))
    ap.add_argument("--against", help="a second kerf binary, timed alternately with the first")
    ap.add_argument("--runs", type=int, default=21)
    a = ap.parse_args()
    kerfs = [a.kerf] + ([a.against] if a.against else [])
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, "tiny.sdl")
        with open(scene, "w") as f:
            f.write(SCENE)
        for k in kerfs:  # one untimed run each: the page cache, not the first run, is measured
            run(k, scene, os.path.join(tmp, "warm.png"))
        times = {k: [] for k in kerfs}
        for _ in range(a.runs):
            for i, k in enumerate(kerfs):
                times[k].append(run(k, scene, os.path.join(tmp, f"{i}.png")))
    print(f"16x16 render, {a.runs} alternating runs, medians (load average {os.getloadavg()[0]:.2f})")
    for k in kerfs:
        libs = libraries(k)
        wall = statistics.median(t[0] for t in times[k]) * 1e3
        cpu = statistics.median(t[1] for t in times[k]) * 1e3
        print(f"  {k}: wall {wall:.1f} ms, CPU {cpu:.1f} ms, {len(libs)} libraries by ldd")
    if a.against:
        A, B = times[kerfs[0]], times[kerfs[1]]
        rw = statistics.median(b[0] / x[0] for x, b in zip(A, B))
        rc = statistics.median(b[1] / x[1] for x, b in zip(A, B) if x[1] > 0)
        print(f"  second / first, median of pairs: wall {rw:.3f}, CPU {rc:.3f}")
        gone = sorted(set(libraries(kerfs[0])) - set(libraries(kerfs[1])))
        if gone:
            print("  libraries the second no longer loads: " + " ".join(gone))
    return 0


if __name__ == "__main__":
    sys.exit(main())
