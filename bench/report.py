"""Markdown tables and gnuplot scaling plots from bench.py's results.json.

    python3 bench/report.py [OUT_DIR] [--img DIR]

Writes OUT_DIR/tables.md (pasted into docs/performance.md) and one log-log
PNG per scene family (time vs primitives, kerf and POV-Ray) into --img.
"""
import argparse
import json
import os
import subprocess

TARGET_RATIO = {"holes_40": 50.0}  # the speed targets: every reference model >= 5x, holes n = 40 >= 50x
GROWTH = [("shell_100", "shell_10000"), ("spiral_100", "spiral_10000"), ("holes_n10", "holes_n100")]  # the growth target: each <= 2x apart


def f(x, fmt="{:.0f}"):
    return "–" if x is None else fmt.format(x)


def spread(r):
    p = r.get("pair_ratios") or []
    return f"{r['ratio']:.1f} ({min(p):.1f}–{max(p):.1f})" if p else "–"


def scene_table(rows):
    out = ["| scene | size² | prims | build ms | #OR/ray | #SUB/ray | #AND/ray | tests/ray | render ms | MRay/s "
           "| kerf MB | kerf wall ms | POV wall ms | POV/kerf (min–max) | POV MB | IoU |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        pov = f(r["pov_ms"])
        if r.get("pov_skipped"):
            pov = "not run¹"
        elif r.get("pov_timeout_s"):
            pov = f"> {r['pov_timeout_s']:.0f} s (killed)"
        elif r["pov_wall_ms"] and len(r["pov_wall_ms"]) < len(r["kerf_wall_ms"]):
            pov += f" (1 run)" if len(r["pov_wall_ms"]) == 1 else f" ({len(r['pov_wall_ms'])} runs)"
        out.append(f"| {r['name']} | {r['size']} | {r['prims']} | {r['build_ms']:.1f} | {r['or']:.2f} | "
                   f"{r['sub']:.2f} | {r['and']:.2f} | {r['tests']:.2f} | {r['render_ms']:.0f} | {r['mrays']:.2f} | "
                   f"{r['kerf_mb']:.0f} | {r['kerf_ms']:.0f} | {pov} | {spread(r)} | {f(r['pov_mb'])} | "
                   f"{f(r['iou'], '{:.4f}')}{' **FAIL**' if r['iou'] is not None and r['iou'] < 0.97 else ''} |")
    skipped = [f"{r['name']}: {r['pov_skipped']}" for r in rows if r.get("pov_skipped")]
    if skipped:
        out.append("\n¹ POV-Ray not timed — " + "; ".join(skipped) + ".")
    return "\n".join(out)


def headline(rows):
    out = ["| reference model | kerf wall ms | kerf render ms | POV-Ray wall ms | POV/kerf | target | met? |",
           "|---|---:|---:|---:|---:|---:|---|"]
    for r in rows:
        if r["group"] != "ref":
            continue
        need = TARGET_RATIO.get(r["name"], 5.0)
        met = "–" if r["ratio"] is None else ("yes" if r["ratio"] >= need else "**no**")
        out.append(f"| {r['name']} | {r['kerf_ms']:.0f} | {r['render_ms']:.0f} | {f(r['pov_ms'])} | "
                   f"{f(r['ratio'], '{:.1f}')}× | ≥ {need:.0f}× | {met} |")
    return "\n".join(out)


def growth(rows):
    by = {r["name"]: r for r in rows}
    out = ["| pair | size² | kerf render ms | kerf wall ms | growth (render) | growth (wall) | POV wall ms | "
           "POV growth | target | met? |", "|---|---:|---|---|---:|---:|---|---:|---:|---|"]
    for a, b in GROWTH:
        if a not in by or b not in by:
            continue
        ra, rb = by[a], by[b]
        g, gw = rb["render_ms"] / ra["render_ms"], rb["kerf_ms"] / ra["kerf_ms"]
        pg = rb["pov_ms"] / ra["pov_ms"] if ra["pov_ms"] and rb["pov_ms"] else None
        out.append(f"| {a} → {b} | {ra['size']} | {ra['render_ms']:.0f} → {rb['render_ms']:.0f} | "
                   f"{ra['kerf_ms']:.0f} → {rb['kerf_ms']:.0f} | {g:.2f}× | {gw:.2f}× | "
                   f"{f(ra['pov_ms'])} → {f(rb['pov_ms'])} | {f(pg, '{:.1f}')}× | ≤ 2× | "
                   f"{'yes' if g <= 2 else '**no**'} |")
    return "\n".join(out)


def tax_table(tax):
    out = ["| reference model | size² | CSG render ms | union render ms | CSG / union | tests/ray CSG | tests/ray union |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for t in tax:
        out.append(f"| {t['name']} | {t['size']} | {t['csg']['render_ms']:.0f} | {t['union']['render_ms']:.0f} | "
                   f"{t['tax']:.2f}× | {t['csg']['tests']:.2f} | {t['union']['tests']:.2f} |")
    return "\n".join(out)


def plots(rows, img, tag):
    os.makedirs(img, exist_ok=True)
    made = []
    for fam, title in (("shell", "large shell, N segments (same size)"),
                       ("spiral", "large shell, N segments (spec recurrence continued)"), ("holes", "holes, n x n cylinders"),
                       ("checkered", "checkered cube, k x k per face"), ("spheres", "union of N spheres (no CSG)")):
        fr = sorted((r for r in rows if r["group"] == fam), key=lambda r: r["prims"])
        if len(fr) < 2:
            continue
        dat = os.path.join(img, f".{fam}.dat")
        with open(dat, "w") as d:
            for r in fr:
                d.write(f"{r['prims']} {r['kerf_ms']} {r['render_ms']} {r['pov_ms'] or 'NaN'}\n")
        png = os.path.join(img, f"scaling_{fam}{tag}.png")
        script = (f"set terminal pngcairo size 720,480 font 'sans,10'; set output '{png}';"
                  f"set logscale xy; set grid; set key top left;"
                  f"set title '{title}: time vs primitives ({fr[0]['size']}^2, 1 spp, 1 shadowed light)';"
                  f"set xlabel 'primitives'; set ylabel 'ms (median)';"
                  f"plot '{dat}' u 1:4 w lp pt 7 t 'POV-Ray 3.7, wall', "
                  f"'{dat}' u 1:2 w lp pt 5 t 'kerf, wall', '{dat}' u 1:3 w lp pt 9 t 'kerf, render (--stats)'")
        subprocess.run(["gnuplot", "-e", script], check=True)
        os.remove(dat)
        made.append(png)
    return made


def write(out, img=None, tag=""):
    """OUT/tables.md and the plots; returns the tables' text."""
    res = json.load(open(os.path.join(out, "results.json")))
    rows, m = res["rows"], res["meta"]
    text = (f"Run {m['started']} – {m.get('finished', '(unfinished)')}; {m['nproc']} CPUs ({m['cpu']}); "
            f"{m['pov']}; threads {m['threads']}; {m['runs']} runs each, alternating; load average at start "
            f"{' '.join(m['loadavg_start'])}, at end {' '.join(m.get('loadavg_now', []))}. "
            f"Process start-up alone: `kerf --version` {f(m.get('kerf_version_ms'))} ms, "
            f"POV-Ray 1×1 lens {f(m.get('pov_1x1_ms'))} ms (medians of 3).\n\n"
            "### Reference models vs. the speed targets\n\n" + headline(rows) +
            "\n\n### Cost growth\n\n" + growth(rows) +
            "\n\n### All scenes\n\n" + scene_table(rows) +
            ("\n\n### The CSG tax\n\n" + tax_table(res["tax"]) if res["tax"] else "") + "\n")
    open(os.path.join(out, "tables.md"), "w").write(text)
    made = plots(rows, img or out, tag)
    return text + "\nplots: " + " ".join(made) + "\n"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out", nargs="?", default="bench/out")
    p.add_argument("--img", help="where the plots go (default: OUT)")
    p.add_argument("--tag", default="", help="suffix for the plot names")
    a = p.parse_args()
    print(write(a.out, a.img, a.tag))


if __name__ == "__main__":
    main()
