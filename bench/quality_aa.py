"""The anti-aliasing trade, measured (docs/quality.md): for each scene,
render time (user+sys CPU, median of --runs) and error against a converged
reference (--spp 256) of 1 spp, 16 uniform spp and adaptive AA at several
thresholds. Error: RMSE over 8-bit display codes and the share of pixels
off by more than 1/255 in any channel.

    python3 bench/quality_aa.py --kerf build/kerf --size 384
"""
import argparse
import os
import resource
import subprocess
import statistics
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["lens", "grooved_sphere", "small_shell", "checkered_cube", "holes"]


def read_ppm(path):
    data = open(path, "rb").read()
    magic, w, h, maxval, rest = data.split(maxsplit=4)
    assert magic == b"P6" and maxval == b"255"
    return int(w), int(h), rest[: int(w) * int(h) * 3]


def render(kerf, scene, out, size, args):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([kerf, "render", scene, "-o", out, "-W", str(size), "-H", str(size), "--threads", "2"] + args,
                   check=True, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def error(a, b):
    n = len(a) // 3
    sq = sum((x - y) ** 2 for x, y in zip(a, b))
    off = sum(1 for i in range(0, len(a), 3) if max(abs(a[i + k] - b[i + k]) for k in range(3)) > 1)
    return (sq / len(a)) ** 0.5, off / n


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--kerf", default=os.path.join(ROOT, "build", "kerf"))
    p.add_argument("--size", type=int, default=384)
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--scenes", nargs="*", default=SCENES)
    a = p.parse_args()
    variants = [("1 spp", ["--spp", "1"]), ("16 spp", ["--spp", "16"]),
                ("aa 0.10", ["--aa-threshold", "0.10"]), ("aa 0.05 (default)", []),
                ("aa 0.02", ["--aa-threshold", "0.02"])]
    tmp = tempfile.mkdtemp()
    print(f"| scene | sampling | CPU s | × 1 spp | RMSE (codes) | pixels off > 1/255 |")
    print("|---|---|---|---|---|---|")
    for name in a.scenes:
        scene = os.path.join(ROOT, "examples", name + ".sdl")
        ref = os.path.join(tmp, name + "_ref.ppm")
        render(a.kerf, scene, ref, a.size, ["--spp", "256"])
        _, _, rb = read_ppm(ref)
        base = None
        for label, args in variants:
            out = os.path.join(tmp, name + ".ppm")
            times = []
            for _ in range(a.runs):  # alternating would need all variants per round; medians suffice here
                times.append(render(a.kerf, scene, out, a.size, args))
            t = statistics.median(times)
            base = base or t
            rmse, off = error(read_ppm(out)[2], rb)
            print(f"| {name} | {label} | {t:.3f} | {t / base:.2f} | {rmse:.2f} | {100 * off:.2f} % |", flush=True)


if __name__ == "__main__":
    main()
