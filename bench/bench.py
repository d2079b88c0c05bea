"""Measures kerf against POV-Ray on the benchmark scenes (bench/run.sh runs it).

Per scene: write the .sdl and .pov twins (scenes.py); render both once as
silhouettes and compare the object masks (IoU, fails below 0.97); then run
kerf and POV-Ray alternately, `runs` times each, timing the whole process
(wall clock) and its peak memory (wait4's resource usage). kerf's own --stats give
the per-ray operation counts, render time and MRay/s. A 1x1 kerf render gives
the build time (evaluation and lowering excluded: parse + evaluate + lower is
the `kerf check` time, reported separately). For each reference model the
same leaves as a plain union (no CSG work) are rendered too: the CSG tax.
Rows go to OUT/results.json as they finish, so a partial run keeps its rows.
"""
import argparse
import json
import os
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import masks  # noqa: E402
import report  # noqa: E402
import scenes  # noqa: E402

IOU_MIN = 0.97
KERF_LIMITS = ["--max-primitives", "2000000"]  # the 10^6-sphere control is at the default limit


def run(cmd, timeout=None):
    """(wall s, peak RSS MB, stderr) of one process; raises on failure.

    The process is reaped with wait4(2), whose resource usage gives the
    peak memory: no /usr/bin/time between us and it, whose own exec (about
    5 ms) was counted in the wall of both renderers before 2026-12-06.
    Output goes to files, not pipes: wait4 blocks, so a pipe nobody reads
    could fill and stall the child."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        t0 = time.perf_counter()
        # Own process group: on a timeout everything the renderer started dies too.
        p = subprocess.Popen(cmd, stdout=out, stderr=err, start_new_session=True)
        expired = threading.Event()

        def kill():
            expired.set()
            os.killpg(p.pid, signal.SIGKILL)

        timer = threading.Timer(timeout, kill) if timeout else None
        if timer:
            timer.start()
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t0
        if timer:
            timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)  # reaped here, not by Popen
        err.seek(0)
        text = err.read().decode(errors="replace")
    if expired.is_set():
        raise subprocess.TimeoutExpired(cmd, timeout)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {p.returncode}:\n{text[-2000:]}")
    return wall, usage.ru_maxrss / 1024.0, text  # ru_maxrss: kilobytes on Linux


STATS = re.compile(r"stats: (\d+)x(\d+), (\d+) rays \((\d+) primary, (\d+) shadow, (\d+) reflect(?:, \d+ refract)?\)\s*"
                   r"stats: render ([\d.]+) s, ([\d.]+) MRay/s\s*"
                   r"stats: per ray: ([\d.]+) union, ([\d.]+) difference, ([\d.]+) intersection ops, "
                   r"([\d.]+) primitive interval tests")


def kerf_stats(stderr):
    m = STATS.search(stderr)
    if not m:
        raise RuntimeError("no --stats block in kerf's output:\n" + stderr[-1000:])
    g = m.groups()
    return {"rays": int(g[2]), "primary": int(g[3]), "shadow": int(g[4]), "render_s": float(g[6]),
            "mrays": float(g[7]), "or": float(g[8]), "sub": float(g[9]), "and": float(g[10]),
            "tests": float(g[11])}


class Bench:
    def __init__(self, a):
        self.a = a
        self.kerf = os.path.abspath(a.kerf)
        self.dir = os.path.abspath(a.out)
        for sub in ("scenes", "images"):
            os.makedirs(os.path.join(self.dir, sub), exist_ok=True)
        self.results_path = os.path.join(self.dir, "results.json")
        self.results = {"meta": self.meta(), "rows": [], "tax": []}
        self.failed = []
        self.pov_dead = {}  # family -> member that ran out of POV-Ray time: larger ones are skipped

    def meta(self):
        cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
        pov = subprocess.run(["povray", "--version"], stderr=subprocess.STDOUT, stdout=subprocess.PIPE,
                             text=True).stdout
        pov = next((l for l in pov.splitlines() if l.startswith("POV-Ray")), "?")
        return {"started": time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime()), "nproc": os.cpu_count(),
                "cpu": cpu, "loadavg_start": open("/proc/loadavg").read().split()[:3], "pov": pov,
                "threads": self.a.threads, "runs": self.a.runs, "ref_size": self.a.ref_size,
                "family_size": self.a.family_size, "mask_size": self.a.mask_size, "quick": self.a.quick}

    def save(self):
        self.results["meta"]["loadavg_now"] = open("/proc/loadavg").read().split()[:3]
        json.dump(self.results, open(self.results_path + ".tmp", "w"), indent=1)
        os.replace(self.results_path + ".tmp", self.results_path)

    def write(self, s, size, union=False):
        base = os.path.join(self.dir, "scenes", s.name + ("_union" if union else ""))
        open(base + ".sdl", "w").write(scenes.sdl_text(s, union))
        if not union:
            open(base + ".pov", "w").write(scenes.pov_text(s, size, size))
        return base

    def kerf_cmd(self, sdl, out, size, extra=()):
        # --aa off: one ray per pixel, as POV-Ray's -A below (docs/quality.md
        # measures the anti-aliasing trade on its own).
        return [self.kerf, "render", sdl, "-o", out, "--stats", "-W", str(size), "-H", str(size),
                "--threads", str(self.a.threads), "--aa", "off"] + KERF_LIMITS + list(extra)

    def pov_cmd(self, pov, out, size, mask=False):
        cmd = ["povray", "+I" + pov, "+O" + out, f"+W{size}", f"+H{size}", "-A", f"+WT{self.a.threads}",
               "-D", "-V", "-GA", "+FP" if mask else "+FN"]
        return cmd + (["Declare=Mask=1"] if mask else [])

    def silhouette(self, s, base):
        m = self.a.mask_size
        img = os.path.join(self.dir, "images", s.name)
        run(self.kerf_cmd(base + ".sdl", img + ".kerf.mask.pgm", m, ["--aov", "depth"]))
        pov_mask = base + ".mask.pov"  # the mask variant must match the mask size's aspect
        open(pov_mask, "w").write(scenes.pov_text(s, m, m))
        run(self.pov_cmd(pov_mask, img + ".pov.mask.ppm", m, mask=True), timeout=self.timeout(s))
        return masks.iou(img + ".kerf.mask.pgm", img + ".pov.mask.ppm")

    def timeout(self, s):
        return self.a.pov_timeout if s.group == "ref" else self.a.pov_family_timeout

    def scene_row(self, s, size):
        base = self.write(s, size)
        img = os.path.join(self.dir, "images", s.name)
        row = {"name": s.name, "group": s.group, "param": s.param, "prims": s.prims, "size": size,
               "note": s.note}
        w, _, _ = run([self.kerf, "check", base + ".sdl"] + KERF_LIMITS)
        row["check_ms"] = w * 1e3
        _, _, err = run(self.kerf_cmd(base + ".sdl", img + ".1x1.png", 1))
        row["build_ms"] = kerf_stats(err)["render_s"] * 1e3
        row["iou"], row["kerf_px"], row["pov_px"] = None, 0, 0
        pov_on = not self.a.no_pov
        if pov_on and s.group in self.pov_dead:
            row["pov_skipped"] = f"a smaller {s.group} scene ({self.pov_dead[s.group]}) already took POV-Ray over {self.timeout(s):.0f} s"
            pov_on = False
        if pov_on:
            try:
                row["iou"], row["kerf_px"], row["pov_px"] = self.silhouette(s, base)
            except subprocess.TimeoutExpired:
                row["pov_skipped"] = f"POV-Ray's silhouette render alone ({self.a.mask_size}²) took over {self.timeout(s):.0f} s (killed)"
                self.pov_dead[s.group] = s.name
                pov_on = False
        kerf, pov, stats = [], [], []
        for i in range(self.a.runs):  # alternate, so load changes hit both alike
            w, mem_k, err = run(self.kerf_cmd(base + ".sdl", img + ".kerf.png", size))
            kerf.append((w, mem_k))
            stats.append(kerf_stats(err))
            if not pov_on or (pov and pov[0][0] > self.a.pov_once):
                continue  # a POV-Ray run that long is measured once (reported)
            try:
                w, mem_p, _ = run(self.pov_cmd(base + ".pov", img + ".pov.png", size), timeout=self.timeout(s))
                pov.append((w, mem_p))
            except subprocess.TimeoutExpired:
                row["pov_timeout_s"] = self.timeout(s)
                self.pov_dead[s.group] = s.name
                pov_on = False
        med = lambda xs: statistics.median(xs) if xs else None
        row.update({
            "kerf_wall_ms": [w * 1e3 for w, _ in kerf], "pov_wall_ms": [w * 1e3 for w, _ in pov],
            "kerf_mb": max(m for _, m in kerf), "pov_mb": max((m for _, m in pov), default=None),
            "render_ms": med([st["render_s"] * 1e3 for st in stats]), "mrays": med([st["mrays"] for st in stats]),
            "rays": stats[0]["rays"], "shadow": stats[0]["shadow"],
            "or": stats[0]["or"], "sub": stats[0]["sub"], "and": stats[0]["and"], "tests": stats[0]["tests"]})
        row["kerf_ms"] = med(row["kerf_wall_ms"])
        row["pov_ms"] = med(row["pov_wall_ms"])
        pairs = [p / k for k, p in zip(row["kerf_wall_ms"], row["pov_wall_ms"])]
        row["pair_ratios"] = pairs
        row["ratio"] = med(pairs)
        return row

    def tax_row(self, s, size):
        rows = {}
        for union in (False, True):
            base = self.write(s, size, union)
            out = os.path.join(self.dir, "images", s.name + ("_union" if union else "") + ".tax.png")
            rs = [kerf_stats(run(self.kerf_cmd(base + ".sdl", out, size))[2]) for _ in range(self.a.runs)]
            rows["union" if union else "csg"] = {
                "render_ms": statistics.median(r["render_s"] * 1e3 for r in rs),
                "tests": rs[0]["tests"], "or": rs[0]["or"], "sub": rs[0]["sub"], "and": rs[0]["and"]}
        return {"name": s.name, "prims": s.prims, "size": size, **rows,
                "tax": rows["csg"]["render_ms"] / rows["union"]["render_ms"]}

    def startup(self):
        """Fixed per-process cost (dynamic loading, library start-up) of both."""
        lens = scenes.lens()
        base = self.write(lens, 1)
        img = os.path.join(self.dir, "images", "startup")
        k = [run([self.kerf, "--version"])[0] for _ in range(3)]
        p = [run(self.pov_cmd(base + ".pov", img + ".pov.png", 1))[0] for _ in range(3)]
        self.results["meta"]["kerf_version_ms"] = statistics.median(k) * 1e3
        self.results["meta"]["pov_1x1_ms"] = statistics.median(p) * 1e3

    def go(self):
        refs = scenes.reference_models()
        only = re.compile(self.a.only) if self.a.only else None
        wanted = lambda s: not only or only.search(s.name)
        if not self.a.no_pov:
            self.startup()
        # Reference models first (the speed targets), then the CSG tax, then
        # the families: a run cut short keeps what matters most.
        for s in filter(wanted, refs):
            self.row(s, self.a.ref_size)
        if not self.a.no_tax:
            for s in filter(wanted, refs):
                t = self.tax_row(s, self.a.ref_size)
                self.results["tax"].append(t)
                self.save()
                print(f"tax {t['name']:16} csg {t['csg']['render_ms']:9.1f} ms  union {t['union']['render_ms']:9.1f} ms"
                      f"  x{t['tax']:.2f}", flush=True)
        for s in filter(wanted, scenes.families(self.a.quick)):
            self.row(s, self.a.family_size)
        self.results["meta"]["finished"] = time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime())
        self.save()
        return 1 if self.failed else 0

    def row(self, s, size):
        t0 = time.time()
        row = self.scene_row(s, size)
        self.results["rows"].append(row)
        self.save()
        print(fmt_row(row, time.time() - t0), flush=True)
        if row["iou"] is not None and row["iou"] < IOU_MIN:
            self.failed.append(s.name)
            print(f"FAIL {s.name}: silhouette IoU {row['iou']:.4f} < {IOU_MIN} -- the two renderers "
                  "do not show the same model; its ratio is meaningless", flush=True)

HEADER = (f"{'scene':16} {'size':>5} {'prims':>8} {'build':>8} {'#OR':>7} {'#SUB':>7} {'#AND':>6} {'tests':>8} "
          f"{'render':>9} {'MRay/s':>7} {'kerfMB':>7} {'kerf ms':>9} {'POV ms':>10} {'POV/kerf':>8} {'IoU':>6}")


def fmt_row(r, took):
    pov = f"{r['pov_ms']:10.0f}" if r["pov_ms"] else f"{'-':>10}"
    ratio = f"{r['ratio']:8.1f}" if r["ratio"] else f"{'-':>8}"
    return (f"{r['name']:16} {r['size']:5d} {r['prims']:8d} {r['build_ms']:8.1f} {r['or']:7.2f} {r['sub']:7.2f} "
            f"{r['and']:6.2f} {r['tests']:8.2f} {r['render_ms']:9.1f} {r['mrays']:7.2f} {r['kerf_mb']:7.0f} "
            f"{r['kerf_ms']:9.0f} {pov} {ratio} {r['iou'] or 0:6.4f}   ({took:.0f} s)")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--kerf", default="build/kerf")
    p.add_argument("--out", help="default bench/out, or bench/out/quick with --quick")
    p.add_argument("--quick", action="store_true", help="small sizes, small families, one run: a smoke test")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--ref-size", type=int, default=2048, help="reference models (speed targets are quoted at 2048)")
    p.add_argument("--family-size", type=int, default=512)
    p.add_argument("--mask-size", type=int, default=512, help="silhouette comparison size")
    p.add_argument("--pov-once", type=float, default=60, help="a POV-Ray run longer than this (s) is not repeated")
    p.add_argument("--pov-timeout", type=float, default=1800, help="per POV-Ray run, reference models (s)")
    p.add_argument("--pov-family-timeout", type=float, default=240,
                   help="per POV-Ray run in the families (s); larger members of that family then skip POV-Ray")
    p.add_argument("--only", help="regex: only scenes whose name matches")
    p.add_argument("--no-pov", action="store_true")
    p.add_argument("--no-tax", action="store_true")
    a = p.parse_args()
    if a.quick:
        a.runs, a.ref_size, a.family_size, a.mask_size = 1, 256, 128, 128
    a.out = a.out or ("bench/out/quick" if a.quick else "bench/out")
    b = Bench(a)
    print(HEADER, flush=True)
    rc = b.go()
    report.write(a.out)
    print(f"results: {b.results_path}, tables: {a.out}/tables.md, plots: {a.out}/scaling_*.png"
          + (f"; FAILED silhouettes: {', '.join(b.failed)}" if b.failed else ""))
    return rc


if __name__ == "__main__":
    sys.exit(main())
