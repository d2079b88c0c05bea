"""The speed/accuracy trade, knob by knob (docs/quality.md "The trade, knob
by knob" and "Presets"): for each knob, render time (user+sys CPU of kerf,
median of --runs) against error versus a converged reference of the same
scene at the same small size. Error: RMSE over 8-bit display codes and the
share of pixels off by more than 1/255 in any channel (quality_aa.error).
Writes a CSV and one gnuplot PNG per knob (error against CPU seconds).

    python3 bench/quality_curves.py --kerf build/kerf --csv docs/img/quality_curves.csv --img docs/img
"""
import argparse
import csv
import os
import resource
import statistics
import subprocess
import tempfile
import time

from quality_aa import error, read_ppm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
W, H = 200, 150
PATH = ["--integrator", "path"]
SOFT = "soft_light"

# knob -> (scenes, reference arguments, [(label, arguments)]). A reference
# converges only the knob under test: the soft-light rows keep --spp 4 so
# that only the light's samples vary.
KNOBS = {
    "uniform_spp": (["lens", "showcase"], ["--spp", "1024"],
                    [(f"spp {n}", ["--spp", str(n)]) for n in (1, 4, 16, 64)]),
    "aa_threshold": (["lens", "showcase"], ["--spp", "1024"],
                     [(f"aa {t}", ["--aa-threshold", t]) for t in ("0.2", "0.1", "0.05", "0.02")]),
    "light_samples": ([SOFT], ["--spp", "4", "-D", "light_samples=1024"],
                      [(f"light {n}", ["--spp", "4", "-D", f"light_samples={n}"]) for n in (1, 4, 16, 64)]),
    "path_spp": (["cornell"], PATH + ["--spp", "1024"],
                 [(f"path {n}", PATH + ["--spp", str(n)]) for n in (4, 16, 64)]),
    "precision": (["lens", "showcase"], ["--spp", "1024"],
                  [("double", ["--precision", "double"]), ("float", ["--precision", "float"])]),
    "presets": (["lens", "showcase"], ["--spp", "1024"],
                [(q, ["--quality", q]) for q in ("draft", "good", "final")]),
    "presets_path": (["cornell"], PATH + ["--spp", "1024"],
                     [(q, PATH + ["--quality", q]) for q in ("draft", "good", "final")]),
}


def render(kerf, scene, out, args):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([kerf, "render", os.path.join(ROOT, "examples", scene + ".sdl"), "-o", out, "-W", str(W),
                    "-H", str(H), "--threads", "2", "--no-progress"] + args, check=True, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def plot(knob, rows, img):
    """Error (RMSE, codes) against CPU seconds, one line per scene, log x."""
    data = os.path.join(tempfile.gettempdir(), f"kerf_quality_{knob}.dat")
    scenes = sorted({r[1] for r in rows})
    with open(data, "w") as f:
        for s in scenes:
            for r in rows:
                if r[1] == s:
                    f.write(f"{r[4]} {r[5]} \"{r[2]}\"\n")
            f.write("\n\n")
    lines = ", ".join(f"'{data}' index {i} using 1:2 with linespoints title '{s}', "
                      f"'' index {i} using 1:2:3 with labels offset 0,0.8 font ',8' notitle"
                      for i, s in enumerate(scenes))
    script = (f"set terminal pngcairo size 560,360 font ',9'; set output '{os.path.join(img, 'quality_' + knob + '.png')}';"
              f"set logscale x; set yrange [0:*]; set xlabel 'CPU seconds ({W}x{H})'; set ylabel 'RMSE (8-bit codes)';"
              f"set title '{knob.replace('_', ' ')}: error against a converged reference'; set grid; set key top right;"
              f"plot {lines}")
    subprocess.run(["gnuplot", "-e", script], check=True)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--kerf", default=os.path.join(ROOT, "build", "kerf"))
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--csv", default="quality_curves.csv")
    p.add_argument("--img", default=None, help="folder for the PNG plots (none if omitted)")
    p.add_argument("--knobs", nargs="*", default=list(KNOBS))
    a = p.parse_args()
    start = time.monotonic()
    tmp = tempfile.mkdtemp()
    refs = {}
    rows = []
    print("| knob | scene | setting | CPU s | RMSE (codes) | pixels off > 1/255 |")
    print("|---|---|---|---|---|---|")
    for knob in a.knobs:
        scenes, ref_args, variants = KNOBS[knob]
        knob_rows = []
        for scene in scenes:
            key = (scene, tuple(ref_args))
            if key not in refs:
                ref = os.path.join(tmp, f"ref{len(refs)}.ppm")
                render(a.kerf, scene, ref, ref_args)
                refs[key] = read_ppm(ref)[2]
            for label, args in variants:
                out = os.path.join(tmp, "out.ppm")
                t = statistics.median(render(a.kerf, scene, out, args) for _ in range(a.runs))
                rmse, off = error(read_ppm(out)[2], refs[key])
                row = (knob, scene, label, " ".join(ref_args), round(t, 3), round(rmse, 3), round(100 * off, 2))
                knob_rows.append(row)
                print(f"| {knob} | {scene} | {label} | {t:.3f} | {rmse:.2f} | {100 * off:.2f} % |", flush=True)
        rows += knob_rows
        if a.img:
            plot(knob, knob_rows, a.img)
    with open(a.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["knob", "scene", "setting", "reference", "cpu_s", "rmse_codes", "off_pct"])
        w.writerows(rows)
    print(f"wall {time.monotonic() - start:.0f} s, load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
