"""Thread scaling of kerf renders (docs/performance.md, "Thread scaling").

Scaling (default): each reference model of bench/scenes.py at each size,
rendered with --threads 1 and --threads 2 alternately (1, 2, 1, 2, ...),
`runs` pairs; whole-process wall and the --stats render time; efficiency =
T(1) / (2 T(2)), the median of the per-pair values; the CPU time (user +
system) of 2 threads over 1 thread, which measures the work parallelism
adds even where other processes take the second core (a loaded machine
shows a poor wall efficiency whatever kerf does); and whether the two
images are byte-identical.

A/B (--against KERF_B): the same scenes rendered at --threads 2 by two
binaries alternately (a tile size or TBB grain built into each); the median
of the per-pair ratios B/A of the render time and of the CPU time, the
medians of both binaries' CPU times, and whether their images are
byte-identical.

  python3 bench/threads.py [--kerf build/kerf] [--against OTHER_KERF] [--sizes 1024,2048] [--runs 5] [--only REGEX]
"""
import argparse
import filecmp
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RENDER = re.compile(r"stats: render ([\d.]+) s")


def cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def render(kerf, scene, size, threads, out):
    """(wall s, render s, CPU s) of one whole kerf process."""
    c0 = cpu_children()
    t0 = time.perf_counter()
    p = subprocess.run([kerf, "render", scene, "-o", out, "-W", str(size), "-H", str(size), "--aa", "off",
                        "--threads", str(threads), "--stats", "--no-progress"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    return wall, float(RENDER.search(p.stderr).group(1)), cpu_children() - c0


def med(xs):
    return statistics.median(xs)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kerf", default=os.path.join(ROOT, "build", "kerf"))
    ap.add_argument("--against", help="a second kerf binary: A/B at --threads 2 instead of 1 vs 2 threads")
    ap.add_argument("--sizes", default="1024,2048")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    sizes = [int(s) for s in a.sizes.split(",")]
    with open("/proc/loadavg") as f:
        print(f"load average at the start: {f.read().split()[0]}\n")
    if a.against:
        print("| scene | size² | A render ms | B render ms | **B / A** (min–max) | A wall ms | B wall ms | "
              "A CPU ms | B CPU ms | B / A CPU (min–max) | same bytes |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    else:
        print("| scene | size² | 1 thread render ms | 2 threads render ms | **render efficiency** (min–max) | "
              "1 thread wall ms | 2 threads wall ms | wall efficiency | CPU 2 threads / 1 thread | same bytes |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    with tempfile.TemporaryDirectory() as d:
        for s in scenes.reference_models():
            if a.only and not re.search(a.only, s.name):
                continue
            path = os.path.join(d, s.name + ".sdl")
            with open(path, "w") as f:
                f.write(scenes.sdl_text(s))
            for size in sizes:
                outs = [os.path.join(d, f"{s.name}_{size}_{k}.png") for k in "ab"]
                # A: (kerf, 1 thread) or (kerf, 2 threads); B: (kerf, 2) or (against, 2).
                runs = [(a.kerf, 2 if a.against else 1), (a.against or a.kerf, 2)]
                times = [[], []]
                for _ in range(a.runs):
                    for k, (binary, threads) in enumerate(runs):
                        times[k].append(render(binary, path, size, threads, outs[k]))
                same = filecmp.cmp(outs[0], outs[1], shallow=False)
                wa, ra = [t[0] for t in times[0]], [t[1] for t in times[0]]
                wb, rb = [t[0] for t in times[1]], [t[1] for t in times[1]]
                cpu = [y[2] / x[2] for x, y in zip(times[0], times[1])]
                if a.against:
                    ratios = [y / x for x, y in zip(ra, rb)]
                    ca, cb = [t[2] for t in times[0]], [t[2] for t in times[1]]
                    print(f"| {s.name} | {size} | {med(ra)*1000:.0f} | {med(rb)*1000:.0f} | **{med(ratios):.3f}** "
                          f"({min(ratios):.3f}–{max(ratios):.3f}) | {med(wa)*1000:.0f} | {med(wb)*1000:.0f} | "
                          f"{med(ca)*1000:.0f} | {med(cb)*1000:.0f} | {med(cpu):.3f} ({min(cpu):.3f}–{max(cpu):.3f}) | "
                          f"{'yes' if same else '**no**'} |", flush=True)
                else:
                    eff = [x / (2 * y) for x, y in zip(ra, rb)]
                    weff = [x / (2 * y) for x, y in zip(wa, wb)]
                    print(f"| {s.name} | {size} | {med(ra)*1000:.0f} | {med(rb)*1000:.0f} | **{med(eff):.2f}** "
                          f"({min(eff):.2f}–{max(eff):.2f}) | {med(wa)*1000:.0f} | {med(wb)*1000:.0f} | "
                          f"{med(weff):.2f} | {med(cpu):.3f} | {'yes' if same else '**no**'} |", flush=True)
    with open("/proc/loadavg") as f:
        print(f"\nload average at the end: {f.read().split()[0]}")


if __name__ == "__main__":
    main()
