"""A `kerf view` the test owns (tests/cli/view/): started on a scene in a
temporary folder, its URL read from standard output, its events read from
/events with the standard library only; killed however the test ends.
Every wait is a poll with a deadline."""
import http.client
import json
import os
import re
import signal
import socket
import subprocess
import tempfile
import time


class View:
    def __init__(self, kerf, scene_text, extra=(), name="scene.sdl", relative=False):
        self.dir = tempfile.mkdtemp(prefix="kerf_view_")
        self.scene = os.path.join(self.dir, name)
        self.write(scene_text)
        self.err = open(os.path.join(self.dir, "view.err"), "w+")
        # relative: run in the scene's folder and name it as a user would
        # (the page then shows name:line:col, not a temporary path).
        self.proc = subprocess.Popen([os.path.abspath(kerf), "view", name if relative else self.scene,
                                      "-W", "160", "-H", "120", *extra], cwd=self.dir if relative else None,
                                     stdout=subprocess.PIPE, stderr=self.err, text=True)
        line = self.proc.stdout.readline()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        if not m:
            self.close()
            raise AssertionError("kerf view printed no URL: %r" % line)
        self.port = int(m.group(1))
        self.url = m.group(0)

    def write(self, text, path=None):
        # Saved by rename, as editors do: never half a file.
        path = path or self.scene
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, path)

    def request(self, method, path, headers=None, timeout=10):
        c = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        try:
            c.request(method, path, headers=headers or {})
            r = c.getresponse()
            return r.status, r.read(), r
        finally:
            c.close()

    def alive(self):
        return self.proc.poll() is None

    def fds(self):
        return len(os.listdir("/proc/%d/fd" % self.proc.pid))

    def threads(self):
        with open("/proc/%d/status" % self.proc.pid) as f:
            return int(re.search(r"Threads:\s+(\d+)", f.read()).group(1))

    def close(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGKILL)
        self.proc.wait()
        self.err.close()

    def log(self):
        with open(self.err.name) as f:
            return f.read()


class Events:
    """The page's event stream, read on a raw socket (chunked SSE)."""

    def __init__(self, view):
        self.sock = socket.create_connection(("127.0.0.1", view.port), timeout=1)
        self.sock.sendall(b"GET /events HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % view.port)
        self.buf = b""
        self.head = None

    def _fill(self, timeout):
        self.sock.settimeout(timeout)
        try:
            data = self.sock.recv(65536)
        except socket.timeout:
            return
        if not data:
            raise AssertionError("the event stream closed")
        self.buf += data

    def _events(self):
        # Chunk framing stripped loosely: SSE lines are what matter.
        if self.head is None:
            if b"\r\n\r\n" not in self.buf:
                return []
            self.head, self.buf = self.buf.split(b"\r\n\r\n", 1)
        text = re.sub(rb"\r\n[0-9a-f]+\r\n", b"", b"\r\n" + self.buf)
        out = []
        while b"\n\n" in text:
            block, text = text.split(b"\n\n", 1)
            kind = re.search(rb"^event: (\w+)$", block, re.M)
            data = re.search(rb"^data: (.*)$", block, re.M)
            if kind and data:
                out.append((kind.group(1).decode(), json.loads(data.group(1))))
        self.buf = text.lstrip(b"\r\n")
        # Keep a trailing partial chunk header out of the way.
        return out

    def wait_for(self, predicate, limit=20.0):
        """The first event (kind, data) for which predicate holds."""
        deadline = time.monotonic() + limit
        while time.monotonic() < deadline:
            for ev in self._events():
                if predicate(*ev):
                    return ev
            self._fill(0.2)
        raise AssertionError("no matching event within %.0f s" % limit)

    def close(self):
        self.sock.close()
