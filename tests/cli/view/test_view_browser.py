#!/usr/bin/env python3
"""`kerf view`'s page in a real browser (docs/editors.md, "kerf view"): a
headless Chromium, driven through chromedriver with the standard library
(tests/cli/view/webdriver.py), opens the URL kerf prints and must show

- the render: the <img> holds a 320x240 image in which a red sphere of
  radius 1 seen from 5 units covers the disc a pinhole camera projects
  (radius tan(asin(r/d)) / tan(fov/2) * H/2 pixels, counted in the page
  through a canvas);
- after a save that makes the sphere blue and of radius 0.5, a newer image
  with the smaller disc, in blue;
- after a save with a syntax error, the diagnostic with the place kerf
  check gives (scene.sdl:2:8) in the page, the last image kept;
- after the fix, the diagnostic gone and a new image;
- after a mouse drag (orbit), an image from a camera at the same distance
  (a centred sphere: the same disc) and a camera statement that moved;
- after a turn of the wheel (zoom in), a camera nearer the target and the
  larger disc projected from that distance.

Exit 77 (ctest: skipped) where Chromium or chromedriver is missing.
KERF_VIEW_SCREENSHOTS=DIR saves the page at each state (DIR/*.png).

Usage: test_view_browser.py KERF"""
import math
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_process import View  # noqa: E402
from webdriver import Browser, find_tools  # noqa: E402

W, H, FOV, DIST = 320, 240, 40, 5


# A light of its own: the studio look's ground would add the sphere's
# shadow to the pixels that differ from the background.
def scene(radius, color, error=False):
    return ("material(color = \"%s\")\n%s\ncamera(position = [0, -%g, 0], look_at = [0, 0, 0], fov = %g);\n"
            "light(position = [3, -6, 5]);\n" %
            (color, "sphere(;" if error else "sphere(%g);" % radius, DIST, FOV))


def disc_pixels(radius, dist=DIST):
    """The area, in pixels, of a centred sphere's silhouette (a circle)."""
    r_px = math.tan(math.asin(radius / dist)) / math.tan(math.radians(FOV / 2)) * H / 2
    return math.pi * r_px * r_px


# What the page shows, read in the page: the image's id, stage and size,
# and the pixels that differ from the background (the corner) with their
# mean colour; the diagnostics box and the camera statement; whether the
# image on screen is of the page's newest camera (a drag sends several
# cameras, and images of the earlier ones arrive after it ends).
STATE = """
const i = document.getElementById('view'), d = document.getElementById('diag');
const s = { diag: d.textContent, diagClass: d.className, statement: document.getElementById('statement').value,
            id: +(i.dataset.id || 0), stage: i.dataset.stage || '', w: i.naturalWidth, h: i.naturalHeight,
            settled: !!(cam && shownCam && sameCam(cam, shownCam)) };
if (!i.complete || !i.naturalWidth) return s;
const c = document.createElement('canvas');
c.width = i.naturalWidth; c.height = i.naturalHeight;
const g = c.getContext('2d');
g.drawImage(i, 0, 0);
const p = g.getImageData(0, 0, c.width, c.height).data;
let n = 0, r = 0, gr = 0, b = 0;
for (let k = 0; k < p.length; k += 4) {
  if (Math.abs(p[k] - p[0]) + Math.abs(p[k + 1] - p[1]) + Math.abs(p[k + 2] - p[2]) > 30) {
    n++; r += p[k]; gr += p[k + 1]; b += p[k + 2];
  }
}
s.object = n; s.rgb = n ? [r / n, gr / n, b / n] : [0, 0, 0];
return s;
"""

failures = []


def check(cond, what):
    print(("ok: " if cond else "FAILED: ") + what, flush=True)
    if not cond:
        failures.append(what)


def full_image_after(browser, newer_than, what, limit=20.0):
    """The page's state once it shows a full image newer than newer_than."""
    return browser.wait_for("const s = (function(){%s})(); return s.stage === 'full' && s.id > %d && s.object !== undefined"
                            " ? s : null;" % (STATE, newer_than), what, limit)


def check_disc(s, radius, dominant, what, dist=DIST):
    want = disc_pixels(radius, dist)
    check(s["w"] == W and s["h"] == H, "%s: the image is %dx%d (got %dx%d)" % (what, W, H, s["w"], s["h"]))
    check(abs(s["object"] - want) < 0.07 * want,
          "%s: the sphere covers %.0f px, the projected disc %.0f px" % (what, s["object"], want))
    rgb = s["rgb"]
    check(rgb[dominant] > 1.5 * max(rgb[k] for k in range(3) if k != dominant),
          "%s: the sphere is %s (mean %s)" % (what, "red green blue".split()[dominant], [round(x) for x in rgb]))


def main():
    tools = find_tools()
    if not tools:
        print("skipped: needs Chromium and chromedriver (Debian: apt-get install chromium chromium-driver)")
        return 77
    kerf = sys.argv[1]
    shots = os.environ.get("KERF_VIEW_SCREENSHOTS")
    started = time.monotonic()
    view = View(kerf, scene(1, "red"), extra=["-W", str(W), "-H", str(H)])
    browser = None
    try:
        browser = Browser(*tools)
        browser.get(view.url)

        s = full_image_after(browser, 0, "the first full image in the page")
        check_disc(s, 1, 0, "first image")
        check(s["diag"] == "", "no diagnostics on a good scene (got %r)" % s["diag"])
        if shots:
            browser.screenshot(os.path.join(shots, "view_render.png"))

        view.write(scene(0.5, "blue"))
        s = full_image_after(browser, s["id"], "a new image after the save")
        check_disc(s, 0.5, 2, "after the save")

        last = s["id"]
        view.write(scene(0.5, "blue", error=True))
        e = browser.wait_for("const d = document.getElementById('diag');"
                             " return d.className === 'error' && d.textContent || null;", "the error in the page")
        check(re.search(r"scene\.sdl:2:8: error: expected '\)'", e) is not None,
              "the page shows the located diagnostic scene.sdl:2:8 (got %r)" % e)
        time.sleep(0.3)  # an image that should not come would come now
        s = browser.js("return (function(){%s})();" % STATE)
        check(s["id"] == last and s["object"] > 0, "the last good image stays on an error (id %d, was %d)" % (s["id"], last))
        if shots:
            browser.screenshot(os.path.join(shots, "view_error.png"))

        view.write(scene(0.5, "blue"))
        s = full_image_after(browser, last, "a new image after the fix")
        check(s["diag"] == "", "the fix clears the diagnostic (got %r)" % s["diag"])
        check_disc(s, 0.5, 2, "after the fix")

        before = s["statement"]
        browser.drag("#stage", 150, 60)
        s = browser.wait_for("const s = (function(){%s})(); return s.stage === 'full' && s.id > %d && s.settled &&"
                             " s.statement !== %r && s.object !== undefined ? s : null;" % (STATE, s["id"], before),
                             "an image of the orbited camera")
        m = re.search(r"position = \[([^\]]*)\], look_at = \[([^\]]*)\]", s["statement"])
        pos = [float(x) for x in m.group(1).split(",")]
        at = [float(x) for x in m.group(2).split(",")]
        check(at == [0, 0, 0] and abs(math.dist(pos, at) - DIST) < 1e-4 and abs(pos[0]) > 0.5,
              "the orbit moves the camera around the target at the same distance (%s)" % s["statement"])
        check_disc(s, 0.5, 2, "after the orbit")
        if shots:
            browser.screenshot(os.path.join(shots, "view_orbit.png"))

        before = s["statement"]
        browser.wheel("#stage", -300)
        s = browser.wait_for("const s = (function(){%s})(); return s.stage === 'full' && s.id > %d && s.settled &&"
                             " s.statement !== %r && s.object !== undefined ? s : null;" % (STATE, s["id"], before),
                             "an image of the zoomed camera")
        m = re.search(r"position = \[([^\]]*)\]", s["statement"])
        dist = math.dist([float(x) for x in m.group(1).split(",")], [0, 0, 0])
        check(dist < 0.9 * DIST, "the wheel brings the camera nearer (%.3f from the target, was %g)" % (dist, DIST))
        check_disc(s, 0.5, 2, "after the zoom", dist)
    finally:
        if browser:
            browser.close()
        view.close()
    print("%d failures, %.1f s" % (len(failures), time.monotonic() - started))
    if failures:
        print(view.log())
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
