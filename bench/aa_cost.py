"""Adaptive AA's cost against a 1 spp render (docs/quality.md, "Adaptive
AA's cost"), for one or two builds, on the reference models of scenes.py:

- CPU (user + system) of whole `kerf render` runs, --aa off and the default
  alternating (per build: off, auto; --pairs rounds), medians and the
  median of the per-round auto/off ratios;
- --callgrind: instructions of one run of each on 1 thread (valgrind's
  callgrind), which a loaded machine does not change;
- --error SIZE: RMSE in display codes (and pixels off by more than 1/255)
  of the default and of --spp 16 against --spp 256, as quality_aa.py.

    python3 bench/aa_cost.py --kerf before/kerf after/kerf --sizes 1024,2048 --pairs 5
"""
import argparse
import os
import re
import resource
import statistics
import subprocess
import tempfile

import quality_aa
import scenes


def cpu_run(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def instructions(cmd):
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + cmd,
                       capture_output=True, text=True, check=True)
    return int(re.search(r"Collected : (\d+)", r.stderr).group(1))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--kerf", nargs="+", required=True, help="one or two builds")
    p.add_argument("--sizes", default="1024,2048", help="sizes for the cost, comma-separated; 0: no cost, only --error")
    p.add_argument("--pairs", type=int, default=5)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--only", nargs="*", help="model names (default: all 7)")
    p.add_argument("--callgrind", action="store_true")
    p.add_argument("--error", type=int, default=0, help="image size for the error, 0: none")
    a = p.parse_args()
    tmp = tempfile.mkdtemp()
    models = [s for s in scenes.reference_models() if not a.only or s.name in a.only]
    print("load at start:", open("/proc/loadavg").read().split()[:3], flush=True)
    for s in models:
        path = os.path.join(tmp, s.name + ".sdl")
        open(path, "w").write(scenes.sdl_text(s))
        out = os.path.join(tmp, "out.png")

        def cmd(k, size, args, threads=a.threads):
            return [k, "render", path, "-o", out, "-W", str(size), "-H", str(size), "--threads", str(threads),
                    "--no-progress"] + args

        for size in [int(x) for x in a.sizes.split(",") if int(x) > 0]:
            t = {(k, aa): [] for k in a.kerf for aa in ("off", "auto")}
            for _ in range(a.pairs):
                for k in a.kerf:
                    for aa in ("off", "auto"):
                        t[(k, aa)].append(cpu_run(cmd(k, size, ["--aa", aa])))
            row = [s.name, str(size)]
            for k in a.kerf:
                off, auto = t[(k, "off")], t[(k, "auto")]
                ratio = statistics.median(x / o for x, o in zip(auto, off))
                row.append(f"{statistics.median(off):.2f} / {statistics.median(auto):.2f} s ×{ratio:.2f}")
                if a.callgrind:
                    i_off, i_auto = (instructions(cmd(k, size, ["--aa", aa], 1)) for aa in ("off", "auto"))
                    row.append(f"{i_off / 1e9:.2f} / {i_auto / 1e9:.2f} G ×{i_auto / i_off:.2f}")
            print("| " + " | ".join(row) + " |", flush=True)
        if a.error:
            ref = os.path.join(tmp, "ref.ppm")
            quality_aa.render(a.kerf[0], path, ref, a.error, ["--spp", "256"])
            rb = quality_aa.read_ppm(ref)[2]
            row = [s.name, f"error at {a.error}"]
            for label, k, args in [("16 spp", a.kerf[0], ["--spp", "16"])] + [("default", k, []) for k in a.kerf]:
                img = os.path.join(tmp, "img.ppm")
                quality_aa.render(k, path, img, a.error, args)
                rmse, off = quality_aa.error(quality_aa.read_ppm(img)[2], rb)
                row.append(f"{label} {rmse:.2f} ({100 * off:.2f} %)")
            print("| " + " | ".join(row) + " |", flush=True)
    print("load at end:", open("/proc/loadavg").read().split()[:3], flush=True)


if __name__ == "__main__":
    main()
