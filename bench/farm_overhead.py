"""What splitting a render costs (docs/farm.md): a single `kerf render
--threads 2` against the same image as 16 bands (`--tile K/16`), run as
separate 1-thread processes two at a time on the 2 cores (as a 2-CPU node
runs a job array) and joined by `kerf assemble`; and an animation as one
`--frames N --threads 2` process against N `--frame I` processes two at a
time. Runs alternate, `--runs` of each; medians of wall clock and of CPU
(user + sys) time. The assembled image is checked byte-identical to the
single render every time.

    python3 bench/farm_overhead.py --kerf build/kerf
"""
import argparse
import os
import resource
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(commands, jobs):
    """(wall s, CPU s) of running `commands`, `jobs` at a time, each checked."""
    t0, c0 = time.perf_counter(), cpu()
    pending, running = list(commands), []
    while pending or running:
        while pending and len(running) < jobs:
            running.append(subprocess.Popen(pending.pop(0), stderr=subprocess.DEVNULL))
        # A slot is free as soon as any job ends, as in a job array.
        pid, status = os.wait()
        p = next(q for q in running if q.pid == pid)
        running.remove(p)
        p.returncode = os.waitstatus_to_exitcode(status)
        if p.returncode != 0:
            raise RuntimeError(f"{' '.join(p.args)} exited {p.returncode}")
    return time.perf_counter() - t0, cpu() - c0


def median_pair(rows):
    return statistics.median(r[0] for r in rows), statistics.median(r[1] for r in rows)


def pair_ratios(a, b):
    """Medians of the per-run ratios b/a (wall, CPU): each pair ran back to
    back, so a drifting load cancels out of each ratio."""
    return (statistics.median(y[0] / x[0] for x, y in zip(a, b)),
            statistics.median(y[1] / x[1] for x, y in zip(a, b)))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--kerf", default=os.path.join(ROOT, "build", "kerf"))
    p.add_argument("--scene", default=os.path.join(ROOT, "examples", "showcase.sdl"))
    p.add_argument("--size", default="1920x1080")
    p.add_argument("--tiles", type=int, default=16)
    p.add_argument("--frames", type=int, default=16)
    p.add_argument("--frame-size", default="480x270")
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--args", default="", help="further kerf render flags, e.g. '--aa-samples 64'")
    p.add_argument("--skip-frames", action="store_true")
    a = p.parse_args()
    tmp = tempfile.mkdtemp()
    w, h = a.size.split("x")
    size = ["-W", w, "-H", h] + a.args.split()
    single = os.path.join(tmp, "single.png")
    band = os.path.join(tmp, "band.png")
    joined = os.path.join(tmp, "joined.png")
    digits = len(str(a.tiles - 1))
    bands = [os.path.join(tmp, f"band_tile{k:0{digits}d}of{a.tiles}.png") for k in range(a.tiles)]
    one = [[a.kerf, "render", a.scene, "-o", single, "--threads", "2"] + size]
    split = [[a.kerf, "render", a.scene, "-o", band, "--threads", "1", "--tile", f"{k}/{a.tiles}"] + size
             for k in range(a.tiles)]
    fw, fh = a.frame_size.split("x")
    fsize = ["-W", fw, "-H", fh] + a.args.split()
    anim = os.path.join(tmp, "anim.png")
    frames_one = [[a.kerf, "render", a.scene, "-o", anim, "--threads", "2", "--frames", str(a.frames)] + fsize]
    frames_split = [[a.kerf, "render", a.scene, "-o", anim, "--threads", "1", "--frames", str(a.frames),
                     "--frame", str(i)] + fsize for i in range(1, a.frames + 1)]
    rows = {"single": [], "tiles": [], "frames_one": [], "frames_split": []}
    assembly = []
    load_before = os.getloadavg()[0]
    for _ in range(a.runs):  # alternating, so drifting load hits both sides alike
        rows["single"].append(timed(one, 1))
        wall, c = timed(split, 2)
        w2, c2 = timed([[a.kerf, "assemble", joined] + bands], 1)
        assembly.append(w2)
        rows["tiles"].append((wall + w2, c + c2))
        if open(joined, "rb").read() != open(single, "rb").read():
            raise RuntimeError("the assembled image differs from the single render")
        if not a.skip_frames:
            rows["frames_one"].append(timed(frames_one, 1))
            rows["frames_split"].append(timed(frames_split, 2))
    load_after = os.getloadavg()[0]
    s, t = median_pair(rows["single"]), median_pair(rows["tiles"])
    scene = os.path.relpath(a.scene, ROOT)
    print(f"{scene} {a.args}, {a.runs} alternating runs, medians, 2 cores, "
          f"load average {load_before:.1f} -> {load_after:.1f}\n")
    print("| render | wall s | CPU s | wall overhead | CPU overhead |")
    print("|---|---|---|---|---|")
    print(f"| {a.size}, one process, --threads 2 | {s[0]:.2f} | {s[1]:.2f} | | |")
    print(f"| {a.size}, {a.tiles} bands, 2 at a time + assemble | {t[0]:.2f} | {t[1]:.2f} | "
          f"{100 * (t[0] / s[0] - 1):+.1f} % | {100 * (t[1] / s[1] - 1):+.1f} % |")
    r = pair_ratios(rows["single"], rows["tiles"])
    print(f"\nmedian of per-run ratios, bands / one process: wall {100 * (r[0] - 1):+.1f} %, "
          f"CPU {100 * (r[1] - 1):+.1f} %; assemble alone: median {statistics.median(assembly):.3f} s wall")
    print(f"\nthroughput: {int(w) * int(h) / t[0] / 1e6:.2f} Mpixel/s as bands")
    if a.skip_frames:
        return
    fo, fs = median_pair(rows["frames_one"]), median_pair(rows["frames_split"])
    print(f"| {a.frames} frames {a.frame_size}, one process, --threads 2 | {fo[0]:.2f} | {fo[1]:.2f} | | |")
    print(f"| {a.frames} frames {a.frame_size}, one process each, 2 at a time | {fs[0]:.2f} | {fs[1]:.2f} | "
          f"{100 * (fs[0] / fo[0] - 1):+.1f} % | {100 * (fs[1] / fo[1] - 1):+.1f} % |")
    r = pair_ratios(rows["frames_one"], rows["frames_split"])
    print(f"\nmedian of per-run ratios, frame jobs / one process: wall {100 * (r[0] - 1):+.1f} %, "
          f"CPU {100 * (r[1] - 1):+.1f} %")
    print(f"throughput: {a.frames / fs[0]:.2f} frames/s as frame jobs, {a.frames / fo[0]:.2f} in one process")


if __name__ == "__main__":
    main()
