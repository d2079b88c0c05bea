"""A headless Chromium the test owns (tests/cli/view/), driven through
chromedriver's W3C WebDriver HTTP protocol with the Python standard library
only: no Selenium, nothing from pip. Everything it starts (chromedriver,
Chromium, a fresh profile folder) goes when close() runs or the test ends.
Every wait is a poll with a deadline."""
import base64
import json
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import urllib.error
import urllib.request

# Debian's chromium package: /usr/bin/chromium is a shell launcher around
# this binary; chromedriver is given the binary itself.
CHROMIUM_CANDIDATES = ["/usr/lib/chromium/chromium", "/usr/bin/chromium", "/usr/bin/chromium-browser"]
DRIVER_CANDIDATES = ["/usr/bin/chromedriver", "/usr/lib/chromium/chromedriver"]


def find_tools():
    """(chromium, chromedriver) paths, or None where either is missing."""
    chromium = os.environ.get("KERF_CHROMIUM") or next((p for p in CHROMIUM_CANDIDATES if os.access(p, os.X_OK)), None)
    driver = os.environ.get("KERF_CHROMEDRIVER") or shutil.which("chromedriver") or \
        next((p for p in DRIVER_CANDIDATES if os.access(p, os.X_OK)), None)
    return (chromium, driver) if chromium and driver else None


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


class WebDriverError(AssertionError):
    pass


class Browser:
    def __init__(self, chromium, driver, width=900, height=720, limit=30.0):
        self.dir = tempfile.mkdtemp(prefix="kerf_browser_")
        self.log = open(os.path.join(self.dir, "chromedriver.log"), "w+")
        self.port = free_port()
        # Its own process group: Chromium's children go with it.
        self.proc = subprocess.Popen([driver, "--port=%d" % self.port], stdout=self.log, stderr=subprocess.STDOUT,
                                     start_new_session=True)
        self.base = "http://127.0.0.1:%d" % self.port
        self.session = None
        deadline = time.monotonic() + limit
        while True:
            try:
                if self._call("GET", "/status", timeout=2).get("ready"):
                    break
            except (OSError, WebDriverError):
                pass
            if time.monotonic() > deadline or self.proc.poll() is not None:
                self.close()
                raise WebDriverError("chromedriver did not start")
            time.sleep(0.1)
        args = ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--no-first-run", "--no-default-browser-check", "--disable-extensions",
                "--window-size=%d,%d" % (width, height), "--user-data-dir=" + os.path.join(self.dir, "profile")]
        caps = {"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {"binary": chromium, "args": args}}}}
        try:
            self.session = self._call("POST", "/session", caps, timeout=limit)["sessionId"]
        except Exception:
            self.close()
            raise

    def _call(self, method, path, body=None, timeout=20):
        data = json.dumps(body).encode() if body is not None else None
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as r:
                answer = json.loads(r.read() or b"{}")
        except urllib.error.HTTPError as e:
            try:
                answer = json.loads(e.read())
            except ValueError:
                raise WebDriverError("%s %s: HTTP %d" % (method, path, e.code))
            v = answer.get("value") or {}
            raise WebDriverError("%s %s: %s: %s" % (method, path, v.get("error"), (v.get("message") or "")[:300]))
        return answer.get("value")

    def _s(self, method, path, body=None, timeout=20):
        return self._call(method, "/session/%s%s" % (self.session, path), body, timeout)

    def get(self, url):
        self._s("POST", "/url", {"url": url}, timeout=30)

    def js(self, script, *args):
        """The value of a function body run in the page."""
        return self._s("POST", "/execute/sync", {"script": script, "args": list(args)})

    def element(self, css):
        v = self._s("POST", "/element", {"using": "css selector", "value": css})
        return next(iter(v.values()))

    def drag(self, css, dx, dy, steps=6):
        """A left-button drag from the element's centre, in small moves as a hand makes."""
        el = self.element(css)
        moves = [{"type": "pointerMove", "duration": 0, "origin": {"element-6066-11e4-a52e-4f735466cecf": el},
                  "x": 0, "y": 0}, {"type": "pointerDown", "button": 0}]
        for i in range(1, steps + 1):
            moves.append({"type": "pointerMove", "duration": 30, "origin": "pointer",
                          "x": dx // steps, "y": dy // steps})
        moves.append({"type": "pointerUp", "button": 0})
        self._s("POST", "/actions", {"actions": [{"type": "pointer", "id": "mouse",
                                                    "parameters": {"pointerType": "mouse"}, "actions": moves}]})

    def wheel(self, css, delta_y):
        """One turn of the mouse wheel over the element's centre."""
        el = self.element(css)
        self._s("POST", "/actions", {"actions": [{"type": "wheel", "id": "wheel", "actions": [
            {"type": "scroll", "x": 0, "y": 0, "deltaX": 0, "deltaY": delta_y, "duration": 0,
             "origin": {"element-6066-11e4-a52e-4f735466cecf": el}}]}]})

    def screenshot(self, path):
        with open(path, "wb") as f:
            f.write(base64.b64decode(self._s("GET", "/screenshot", timeout=30)))

    def wait_for(self, script, what, limit=20.0, *args):
        """The first truthy value of script, polled until the deadline."""
        deadline = time.monotonic() + limit
        last = None
        while time.monotonic() < deadline:
            last = self.js(script, *args)
            if last:
                return last
            time.sleep(0.05)
        raise AssertionError("%s: not within %.0f s (last: %r)" % (what, limit, last))

    def close(self):
        if self.session:
            try:
                self._call("DELETE", "/session/" + self.session, timeout=10)
            except Exception:
                pass
            self.session = None
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self.proc.wait()
        self.log.close()
        shutil.rmtree(self.dir, ignore_errors=True)
