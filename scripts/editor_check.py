#!/usr/bin/env python3
"""The VS Code recipe of docs/editors.md, run in a real VS Code: code-server
(VS Code's own workbench, served to a browser) on a folder holding a scene
with an error and the docs' tasks.json, copied from docs/editors.md itself,
driven by headless Chromium through chromedriver (tests/cli/view/webdriver.py).

It checks, as a user would see them:
- "kerf check" (Run Build Task, Ctrl+Shift+B) runs kerf, and the Problems
  panel lists the error at the line and column put into the scene;
- "kerf watch" runs kerf in the background; the Problems panel lists the
  error; a fix typed in the editor and saved (Ctrl+S) clears it and writes
  the image beside the scene, which opens in an editor tab; a new error
  typed and saved lists it again and keeps the image;
- "kerf view" prints the URL of its page in the task's terminal, and that
  page, opened in the browser, shows the render.
Exit 1 if a check failed; screenshots of each state go to --shots DIR.

Usage: editor_check.py KERF CODE_SERVER [--shots DIR]
(docs/editors.md, "Running the check again", says how to install code-server.)"""
import argparse
import base64
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "view"))
from webdriver import Browser, find_tools, free_port  # noqa: E402
from test_view_browser import full_image_after  # noqa: E402

# WebDriver's key codes (W3C WebDriver, "Keyboard actions").
KEY = {"Enter": "\ue007", "Escape": "\ue00c", "Control": "\ue009", "Shift": "\ue008", "F1": "\ue031",
       "End": "\ue010", "Backspace": "\ue003"}

# The error put into the scene, and where it is: line 2, column 5.
BAD = "sphere(1);\ny = foo(2);\n"
BAD_AT = (2, 5, "undefined function 'foo'")
GOOD = "sphere(1);\n"
# The second error, typed in the editor: `spere` at line 1, column 1.
TYPO = "spere(1);\n"
TYPO_AT = (1, 1, "unknown module 'spere'; did you mean 'sphere'?")


def tasks_json():
    """The tasks.json block of docs/editors.md's VS Code section, as written there."""
    text = open(os.path.join(ROOT, "docs", "editors.md")).read()
    section = text.split("\n## VS Code", 1)[1].split("\n## ", 1)[0]
    m = re.search(r"```json\n(.*?)```", section, re.S)
    if not m:
        sys.exit("editor_check: no ```json block in docs/editors.md's VS Code section")
    return m.group(1)


def user_settings():
    """A fresh user profile's settings: no welcome page, no trust prompt, and
    the terminal drawn into the DOM (not a canvas) so its text can be read."""
    return {
        "workbench.startupEditor": "none",
        "workbench.tips.enabled": False,
        "security.workspace.trust.enabled": False,
        "telemetry.telemetryLevel": "off",
        "terminal.integrated.gpuAcceleration": "off",
        "extensions.autoCheckUpdates": False,
        "extensions.autoUpdate": False,
        "update.mode": "none",
        "workbench.enableExperiments": False,
        "chat.disableAIFeatures": True,
        "files.autoSave": "off",
        "workbench.secondarySideBar.defaultVisibility": "hidden",
    }


failures = []


def check(cond, what):
    print(("ok: " if cond else "FAILED: ") + what, flush=True)
    if not cond:
        failures.append(what)
    return cond


class Editor:
    """code-server on one folder, and the browser showing it."""

    def __init__(self, code_server, folder, kerf, shots):
        self.folder = folder
        self.kerf = kerf
        self.shots = shots
        self.home = tempfile.mkdtemp(prefix="kerf_vscode_")
        data = os.path.join(self.home, "data")
        os.makedirs(os.path.join(data, "User"))
        with open(os.path.join(data, "User", "settings.json"), "w") as f:
            json.dump(user_settings(), f, indent=2)
        self.port = free_port()
        env = dict(os.environ)
        # kerf on PATH, as the tasks name it; code-server's own files in the
        # temporary home, not the user's.
        env["PATH"] = os.path.dirname(os.path.abspath(kerf)) + os.pathsep + env.get("PATH", "")
        # VS Code gives tasks the environment of a login shell (bash -il),
        # whose /etc/profile sets PATH anew: kerf must be on the PATH that
        # ~/.profile makes, as it is for a user who installed it.
        env["HOME"] = self.home
        with open(os.path.join(self.home, ".profile"), "w") as f:
            f.write('PATH="%s:$PATH"\n' % os.path.dirname(os.path.abspath(kerf)))
        env["XDG_CONFIG_HOME"] = os.path.join(self.home, "config")
        env["XDG_DATA_HOME"] = os.path.join(self.home, "share")
        self.log = open(os.path.join(self.home, "code-server.log"), "w+")
        self.proc = subprocess.Popen(
            [code_server, "--bind-addr", "127.0.0.1:%d" % self.port, "--auth", "none", "--disable-telemetry",
             "--disable-update-check", "--disable-workspace-trust", "--disable-getting-started-override",
             "--user-data-dir", data, "--extensions-dir", os.path.join(self.home, "extensions"), folder],
            stdout=self.log, stderr=subprocess.STDOUT, env=env, cwd=folder, start_new_session=True)
        self.url = "http://127.0.0.1:%d/" % self.port
        deadline = time.monotonic() + 60
        while True:
            try:
                with urllib.request.urlopen(self.url + "healthz", timeout=2) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if time.monotonic() > deadline or self.proc.poll() is not None:
                self.log.seek(0)
                raise AssertionError("code-server did not start:\n" + self.log.read()[-2000:])
            time.sleep(0.2)
        self.browser = Browser(*find_tools(), width=1280, height=800, limit=60)

    def shot(self, name, workbench=True):
        """A screenshot: of the editors and the panel below them (the part
        of the workbench docs/editors.md shows), or of the whole window."""
        if not self.shots:
            return
        path = os.path.join(self.shots, name + ".png")
        area = workbench and self.browser.js(
            "const a = document.querySelector('.part.editor'), b = document.querySelector('.part.panel');"
            " let n = a; while (n && !n.contains(b)) n = n.parentElement; return n;")
        if not area:
            return self.browser.screenshot(path)
        png = self.browser._s("GET", "/element/%s/screenshot" % next(iter(area.values())), timeout=30)
        with open(path, "wb") as f:
            f.write(base64.b64decode(png))

    def keys(self, *chord):
        """One chord (all keys down, then up in reverse), e.g. keys("Control", "s")."""
        codes = [KEY.get(k, k) for k in chord]
        acts = [{"type": "keyDown", "value": c} for c in codes] + [{"type": "keyUp", "value": c} for c in reversed(codes)]
        self.browser._s("POST", "/actions", {"actions": [{"type": "key", "id": "keyboard", "actions": acts}]})
        self.browser._s("DELETE", "/actions")

    def type(self, text):
        acts = []
        for ch in text:
            c = KEY["Enter"] if ch == "\n" else ch
            acts += [{"type": "keyDown", "value": c}, {"type": "keyUp", "value": c}]
        self.browser._s("POST", "/actions", {"actions": [{"type": "key", "id": "keyboard", "actions": acts}]})

    def wait(self, script, what, limit=30.0):
        return self.browser.wait_for(script, what, limit)

    def open_workbench(self):
        self.browser.get(self.url + "?folder=" + self.folder)
        self.wait("return !!document.querySelector('.explorer-folders-view .monaco-list-row');",
                  "the workbench with the folder in the explorer", 90)

    def click_explorer(self, name):
        """Opens a file of the folder as a user does: a click in the explorer."""
        row = self.wait("for (const r of document.querySelectorAll('.explorer-folders-view .monaco-list-row'))"
                        "  if (r.getAttribute('aria-label') === arguments[0]) return r; return null;".replace(
                            "arguments[0]", json.dumps(name)), "%s in the explorer" % name)
        eid = next(iter(row.values()))
        self.browser._s("POST", "/element/%s/click" % eid, {})
        self.wait("const t = document.querySelector('.tabs-container .tab.active');"
                  " return t && t.getAttribute('aria-label').startsWith(%s);" % json.dumps(name),
                  "%s open in the active tab" % name)

    def choose(self, label, limit=30.0):
        """Clicks the entry of the open quick input whose label is `label`
        (typing narrows the list; the best fuzzy match may be another)."""
        self.type(label)
        row = self.wait("for (const r of document.querySelectorAll('.quick-input-list .monaco-list-row'))"
                        "  if ((r.querySelector('.label-name') || r).textContent.trim() === %s) return r;"
                        " return null;" % json.dumps(label), "%r in the quick input" % label, limit)
        self.browser._s("POST", "/element/%s/click" % next(iter(row.values())), {})

    def click_tab(self, name):
        tab = self.wait("for (const t of document.querySelectorAll('.tabs-container .tab'))"
                        "  if (t.getAttribute('aria-label').startsWith(%s)) return t; return null;" % json.dumps(name),
                        "the tab of %s" % name)
        self.browser._s("POST", "/element/%s/click" % next(iter(tab.values())), {})
        self.wait("const t = document.querySelector('.tabs-container .tab.active');"
                  " return t && t.getAttribute('aria-label').startsWith(%s) &&"
                  " document.activeElement && document.activeElement.closest('.monaco-editor');" % json.dumps(name),
                  "the editor of %s focused" % name)

    def palette(self, command, limit=60.0):
        """Runs a command from the command palette (F1), by its title. The
        tasks' commands come a few seconds after the workbench shows: until
        then the palette lacks them, and it is opened again."""
        deadline = time.monotonic() + limit
        while True:
            self.keys("F1")
            self.wait("const i = document.querySelector('.quick-input-widget input');"
                      " return i && document.activeElement === i;", "the command palette")
            try:
                return self.choose(command, 5.0)
            except AssertionError:
                if time.monotonic() > deadline:
                    raise
                self.keys("Escape")

    def quick_pick_open(self):
        return self.browser.js("const w = document.querySelector('.quick-input-widget');"
                               " return w && w.style.display !== 'none' ? w.textContent : null;")

    def problems(self):
        """The Problems panel's rows: [text, ...] (the panel must be shown)."""
        return self.browser.js("return [...document.querySelectorAll('.markers-panel .monaco-list-row')]"
                               ".map(r => r.getAttribute('aria-label') || r.textContent);")

    def terminal_has(self, text, limit=15.0):
        """Whether a terminal shows text within the limit (its rows joined,
        as the terminal wraps long lines)."""
        want = re.sub(r"\s+", "", text)
        deadline = time.monotonic() + limit
        while time.monotonic() < deadline:
            if want in re.sub(r"\s+", "", self.terminal_text() or ""):
                return True
            time.sleep(0.2)
        print("  (the terminals showed:\n%s)" % self.terminal_text(), flush=True)
        return False

    def terminal_text(self):
        """The text of the terminals (DOM renderer: rows of spans)."""
        return self.browser.js("const t = [...document.querySelectorAll('.terminal-wrapper.active .xterm-rows,"
                               " .terminal-wrapper .xterm-rows')];"
                               " return t.map(x => [...x.children].map(r => r.textContent).join('\\n')).join('\\n----\\n');")

    def close(self):
        try:
            self.browser.close()
        finally:
            if self.proc.poll() is None:
                try:
                    os.killpg(self.proc.pid, signal.SIGTERM)
                    self.proc.wait(10)
                except (ProcessLookupError, subprocess.TimeoutExpired):
                    os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait()
            self.log.close()
            shutil.rmtree(self.home, ignore_errors=True)


def markers(ed, want, what, limit=30.0):
    """Waits until the Problems panel holds exactly `want` (the panel's
    rows are redrawn after the markers change: poll, never read once)."""
    ed.palette("Problems: Focus on Problems View")
    rows = None
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        rows = [r for r in ed.problems() if not r.startswith(("1 problems", "No problems"))]
        if rows == want:
            break
        time.sleep(0.2)
    return check(rows == want, "%s: Problems panel %r" % (what, rows))


def marker(at):
    line, col, message = at
    return "Error: %s at line %d and character %d." % (message, line, col)


def edit(ed, text):
    """Replaces the scene in its editor tab by typing, and saves (Ctrl+S)."""
    ed.click_tab("scene.sdl")
    ed.keys("Control", "a")
    ed.type(text)
    ed.keys("Control", "s")
    ed.wait("const t = document.querySelector('.tabs-container .tab.active');"
            " return t && !t.classList.contains('dirty');", "the scene saved")


def task_ran(ed, *args):
    """Whether a task's kerf runs with exactly these arguments, read from
    /proc: the terminal shows only its last rows, and the `Executing task`
    line has scrolled away once kerf has printed a few lines."""
    kerf = os.path.realpath(ed.kerf)
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            exe = os.path.realpath("/proc/%s/exe" % pid)
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                argv = [a.decode() for a in f.read().split(b"\0")[:-1]]
        except OSError:
            continue
        if exe == kerf and argv[1:] == list(args):
            return True
    return False


def wait_file(path, newer_than, what, limit=30.0):
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        if os.path.exists(path) and os.stat(path).st_mtime_ns > newer_than:
            with open(path, "rb") as f:
                return check(f.read(8) == b"\x89PNG\r\n\x1a\n", what)
        time.sleep(0.1)
    return check(False, what + " (no new %s)" % os.path.basename(path))


def run(ed, folder):
    scene = os.path.join(folder, "scene.sdl")
    png = os.path.join(folder, "scene.png")
    ed.open_workbench()
    ed.click_explorer("scene.sdl")
    ed.wait("const v = document.querySelector('.editor-instance .monaco-editor .view-lines');"
            " return v && v.textContent.includes('foo(2)');", "the scene's text in the editor")
    ed.click_tab("scene.sdl")

    # kerf check: the default build task (Ctrl+Shift+B; a key pressed right
    # after the workbench loads may come before the task system: the palette
    # waits for it).
    ed.palette("Tasks: Run Build Task")
    ed.wait("return %s.test(document.querySelector('.panel') ? document.querySelector('.panel').textContent : '');"
            % "/Executing task: kerf check /", "the check task's terminal")
    check(ed.terminal_has("kerf check " + scene), "kerf check task: the terminal ran `kerf check %s`" % scene)
    check(ed.terminal_has(scene + ":2:5: error: undefined function 'foo'"),
          "kerf check task: kerf's diagnostic in the terminal")
    markers(ed, [marker(BAD_AT)], "kerf check task")
    ed.shot("vscode_check")

    # kerf watch: a background task; its matcher follows each run.
    ed.palette("Tasks: Run Task")
    ed.choose("kerf watch")
    ed.wait("return %s.test(document.querySelector('.panel').textContent);" % "/kerf watch: nothing written to /",
            "the watch task's first run in its terminal")
    check(task_ran(ed, "watch", scene, "--no-progress"),
          "kerf watch task: kerf runs `kerf watch %s --no-progress`" % scene)
    markers(ed, [marker(BAD_AT)], "kerf watch task, first run")
    check(not os.path.exists(png), "kerf watch task: no image for a scene with an error")

    # The fix, typed and saved in the editor: the error goes, the image comes.
    before = 0
    edit(ed, GOOD)
    wait_file(png, before, "kerf watch task: after the fix is saved, scene.png written beside the scene")
    markers(ed, [], "kerf watch task, after the fix")
    ed.click_explorer("scene.png")
    size = ed.wait("return [...document.querySelectorAll('.statusbar-item')].map(r => r.textContent.trim())"
                   ".find(t => /^\\d+x\\d+$/.test(t));", "the image preview's size in the status bar")
    check(size == "800x600", "scene.png opens in an editor tab (Image Preview, %s)" % size)
    # Beside the scene, as the docs advise.
    ed.palette("View: Move Editor into Right Group")
    ed.wait("return document.querySelectorAll('.editor-group-container').length === 2;", "the image beside the scene")
    ed.shot("vscode_watch_image")

    # A new error, saved: listed at its place, the last image kept.
    kept = os.stat(png).st_mtime_ns
    edit(ed, TYPO)
    markers(ed, [marker(TYPO_AT)], "kerf watch task, a typo saved")
    time.sleep(1.0)
    check(os.stat(png).st_mtime_ns == kept, "kerf watch task: the typo leaves scene.png as it was")
    ed.shot("vscode_watch_error")
    edit(ed, GOOD)
    wait_file(png, kept, "kerf watch task: the next fix renders again")
    markers(ed, [], "kerf watch task, after the second fix")

    # kerf view: the URL of its page in the task's terminal; the page, opened
    # in the browser (a tab of its own), shows the render.
    ed.palette("Tasks: Run Task")
    ed.choose("kerf view")
    url = ed.wait("const m = /kerf view: (http:\\/\\/127\\.0\\.0\\.1:\\d+\\/) shows/.exec("
                  "[...document.querySelectorAll('.terminal-wrapper .xterm-rows')]"
                  ".map(x => [...x.children].map(r => r.textContent).join('')).join(''));"
                  " return m && m[1];", "kerf view's URL in the task's terminal")
    check(task_ran(ed, "view", scene), "kerf view task: kerf runs `kerf view %s`" % scene)
    ed.shot("vscode_view_terminal")
    handle = ed.browser._s("POST", "/window/new", {"type": "tab"})["handle"]
    ed.browser._s("POST", "/window", {"handle": handle})
    ed.browser.get(url)
    page = full_image_after(ed.browser, 0, "the full render in kerf view's page", 60)
    # The sphere of radius 1 seen from the page's camera covers the disc a
    # pinhole camera projects (vertical fov), less its darkest rim, which
    # is as grey as the background (tests/cli/view/test_view_browser.py
    # checks the disc exactly, with a red sphere).
    cam = re.search(r"position = \[([-\d.e]+), ([-\d.e]+), ([-\d.e]+)\].*look_at = \[0, 0, 0\].*fov = ([\d.]+)",
                    page["statement"])
    disc = 0.0
    if cam:
        dist = math.sqrt(sum(float(cam.group(k)) ** 2 for k in (1, 2, 3)))
        r_px = math.tan(math.asin(1 / dist)) / math.tan(math.radians(float(cam.group(4)) / 2)) * page["h"] / 2
        disc = math.pi * r_px * r_px
    check(page["w"] == 800 and page["h"] == 600 and not page["diag"].strip() and
          0.85 * disc < page["object"] < 1.02 * disc,
          "kerf view's page (%s) shows the %dx%d render, %d px of sphere (the projected disc: %.0f px), no diagnostic"
          % (url, page["w"], page["h"], page["object"], disc))
    ed.shot("vscode_view_page", workbench=False)


def main():
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # kill: the editor and browser go too
    ap = argparse.ArgumentParser()
    ap.add_argument("kerf")
    ap.add_argument("code_server")
    ap.add_argument("--shots")
    ap.add_argument("--keep", action="store_true", help="leave the editor running (exploring)")
    a = ap.parse_args()
    if not find_tools():
        sys.exit("editor_check: needs Chromium and chromedriver (apt-get install chromium chromium-driver)")
    if a.shots:
        os.makedirs(a.shots, exist_ok=True)
    # A long folder name: kerf's lines are wider than the terminal, which
    # wraps them; the matchers must still read each as one line.
    top = tempfile.mkdtemp(prefix="kerf_vscode_ws_")
    folder = os.path.join(top, os.environ.get("KERF_EDITOR_FOLDER", "a_folder_whose_name_is_long_enough_that_every_kerf_line_wraps_in_the_terminal"))
    os.makedirs(os.path.join(folder, ".vscode"))
    with open(os.path.join(folder, ".vscode", "tasks.json"), "w") as f:
        f.write(tasks_json())
    with open(os.path.join(folder, "scene.sdl"), "w") as f:
        f.write(BAD)
    ed = Editor(a.code_server, folder, a.kerf, a.shots)
    try:
        try:
            if not os.environ.get("KERF_EDITOR_EXPLORE"):
                run(ed, folder)
            else:
                ed.open_workbench()
                ed.click_explorer("scene.sdl")
        except Exception:
            ed.shot("failure", workbench=False)
            raise
        if a.keep:
            print(ed.url, ed.browser.base, ed.browser.session, flush=True)
            time.sleep(3600)
    finally:
        ed.close()
        shutil.rmtree(top, ignore_errors=True)
    print("editor_check: %s" % ("FAILED: " + "; ".join(failures) if failures else "all passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
