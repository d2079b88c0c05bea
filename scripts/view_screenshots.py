#!/usr/bin/env python3
"""The screenshots of `kerf view` in docs/editors.md, taken by headless
Chromium (the browser test's driver, tests/cli/view/webdriver.py) on a copy
of examples/showcase.sdl at 800x600: the render, the view after a mouse
orbit, and a typo in the scene with its diagnostic in the page.

Usage: scripts/view_screenshots.py KERF [OUTDIR]   (default docs/img)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "view"))
from view_process import View  # noqa: E402
from webdriver import Browser, find_tools  # noqa: E402

SHOWN = ("const i = document.getElementById('view'); return i.complete && i.naturalWidth > 0 &&"
         " i.dataset.stage === 'full' && +i.dataset.id > %d && document.getElementById('statement').value !== %r"
         " ? [+i.dataset.id, document.getElementById('statement').value] : null;")


def main():
    kerf = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "img")
    tools = find_tools()
    if not tools:
        sys.exit("needs Chromium and chromedriver (apt-get install chromium chromium-driver)")
    text = open(os.path.join(ROOT, "examples", "showcase.sdl")).read()
    view = View(kerf, text, extra=["-W", "800", "-H", "600"], name="showcase.sdl", relative=True)
    browser = Browser(*tools, width=1100, height=760)
    try:
        browser.get(view.url)
        shown, _ = browser.wait_for(SHOWN % (0, ""), "the first full image", 60)
        browser.screenshot(os.path.join(out, "view_render.png"))
        before = browser.js("return document.getElementById('statement').value;")
        browser.drag("#stage", -160, 40)
        shown, _ = browser.wait_for(SHOWN % (shown, before), "the orbited image", 60)
        browser.screenshot(os.path.join(out, "view_orbit.png"))
        view.write(text.replace("torus(R = 0.32", "tours(R = 0.32"))
        browser.wait_for("return document.getElementById('diag').className === 'error';", "the diagnostic", 60)
        browser.screenshot(os.path.join(out, "view_error.png"))
    finally:
        browser.close()
        view.close()
    print("wrote view_render.png, view_orbit.png, view_error.png to", out)


if __name__ == "__main__":
    main()
