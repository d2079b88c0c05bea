#!/usr/bin/env python3
"""Save-to-image latency of the editor loop (docs/editors.md, "How fast"):
for each reference model (bench/scenes.py) at 800x600, the time from the
rename that saves the scene to

- kerf view: the preview, then the full image, loaded in the page of a
  headless Chromium (the browser test's driver, tests/cli/view/); each
  <img> load is stamped in the page with the system clock the saver reads;
- kerf watch: the preview, then the full image, in place as OUT (its
  inode, size or time changes; polled every millisecond).

Both include kerf's 100 ms debounce, evaluation and lowering: what a user
waits for. Each save appends a comment, so the scene is evaluated again but
draws the same. Medians over --saves saves per model, after a first render
that is not counted.

Usage: python3 bench/view_latency.py KERF [--saves 7] [--only REGEX] [--no-watch] [--no-view]"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tests", "cli", "view"))
import scenes  # noqa: E402
from view_process import View  # noqa: E402
from webdriver import Browser, find_tools  # noqa: E402

W, H = 800, 600

# Every image the page shows, with the moment it is on screen.
STAMP = """
window.kerfLoads = window.kerfLoads || [];
const i = document.getElementById('view');
if (!i.kerfStamped) {
  i.kerfStamped = true;
  i.addEventListener('load', () => window.kerfLoads.push(
    { id: +i.dataset.id, stage: i.dataset.stage, t: (performance.timeOrigin + performance.now()) / 1000 }));
}
return true;
"""


def save(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    t = time.time()
    os.replace(tmp, path)
    return t


def measure_view(kerf, browser, text, saves, threads):
    view = View(kerf, text, extra=["-W", str(W), "-H", str(H), "--threads", str(threads)], relative=True)
    try:
        browser.get(view.url)
        browser.js(STAMP)
        # The first image may be on screen before the stamps are set up.
        browser.wait_for("const i = document.getElementById('view');"
                         " return i.dataset.stage === 'full' && i.complete;", "the first image", 120)
        pre, full = [], []
        for k in range(saves):
            seen = browser.js("return window.kerfLoads.length;")
            t0 = save(view.scene, text + "// save %d\n" % k)
            loads = browser.wait_for("const l = window.kerfLoads.slice(%d);"
                                     " return l.some(x => x.stage === 'full') ? l : null;" % seen, "a new image", 120)
            p = [x["t"] for x in loads if x["stage"] == "preview"]
            if p:  # the page skips a preview that arrives after its full image
                pre.append(p[0] - t0)
            full.append(next(x["t"] for x in loads if x["stage"] == "full") - t0)
            time.sleep(0.3)
        return pre, full
    finally:
        view.close()


def file_state(path):
    try:
        st = os.stat(path)
        return (st.st_ino, st.st_size, st.st_mtime_ns)
    except FileNotFoundError:
        return None


def measure_watch(kerf, text, saves, threads):
    d = tempfile.mkdtemp(prefix="kerf_watch_bench_")
    scene, out = os.path.join(d, "scene.sdl"), os.path.join(d, "scene.png")
    save(scene, text)
    err = open(os.path.join(d, "watch.err"), "w+")
    proc = subprocess.Popen([kerf, "watch", scene, "-o", out, "-W", str(W), "-H", str(H), "--threads", str(threads),
                             "--no-progress"], stderr=err)
    try:
        deadline = time.monotonic() + 120
        while "rendered" not in open(err.name).read():
            if time.monotonic() > deadline or proc.poll() is not None:
                raise AssertionError("kerf watch did not render: " + open(err.name).read())
            time.sleep(0.01)
        pre, full = [], []
        for k in range(saves):
            runs = open(err.name).read().count("rendered")
            state = file_state(out)
            t0 = save(scene, text + "// save %d\n" % k)
            stamps = []
            deadline = time.monotonic() + 120
            while len(stamps) < 2 and time.monotonic() < deadline:
                now = file_state(out)
                if now != state:
                    stamps.append(time.time() - t0)
                    state = now
                elif stamps and open(err.name).read().count("rendered") > runs:
                    break  # the full image came within a poll of the preview
                time.sleep(0.001)
            pre.append(stamps[0])
            if len(stamps) > 1:
                full.append(stamps[1])
            time.sleep(0.3)
        return pre, full
    finally:
        proc.kill()
        proc.wait()
        err.close()
        shutil.rmtree(d, ignore_errors=True)


def med(xs):
    return "%.0f" % (1000 * statistics.median(xs)) if xs else "–"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("kerf")
    p.add_argument("--saves", type=int, default=7)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--only", default="")
    p.add_argument("--no-view", action="store_true")
    p.add_argument("--no-watch", action="store_true")
    a = p.parse_args()
    models = [s for s in scenes.reference_models() if re.search(a.only, s.name)]
    tools = None if a.no_view else find_tools()
    if not a.no_view and not tools:
        sys.exit("kerf view needs Chromium and chromedriver (apt-get install chromium chromium-driver); or --no-view")
    browser = Browser(*tools, width=1100, height=760) if tools else None
    print("| model | prims | view: save → preview ms | view: save → full ms | watch: save → preview ms |"
          " watch: save → full ms |")
    print("|---|---:|---:|---:|---:|---:|")
    try:
        for s in models:
            text = scenes.sdl_text(s)
            vp, vf = measure_view(a.kerf, browser, text, a.saves, a.threads) if browser else ([], [])
            wp, wf = ([], []) if a.no_watch else measure_watch(a.kerf, text, a.saves, a.threads)
            print("| %s | %d | %s | %s | %s | %s |" % (s.name, s.prims, med(vp), med(vf), med(wp), med(wf)), flush=True)
    finally:
        if browser:
            browser.close()


if __name__ == "__main__":
    main()
