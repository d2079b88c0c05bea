#!/usr/bin/env python3
"""`kerf view` over HTTP (docs/spec.md §13, docs/editors.md "kerf view"),
driven from the Python standard library against the real binary:

- it listens on loopback only, and refuses --host that is not loopback;
- it answers only its own routes: path traversal and every file name get
  404 and never a file's bytes;
- a Host, Origin or Sec-Fetch-Site that is not its own gets 403 (DNS
  rebinding, foreign pages), also for POST /camera, which then moves nothing;
- 1,000 concurrent requests, stalled and trickling clients and malformed
  HTTP leave it answering, with no file descriptors or threads left over;
- a save re-renders, an error arrives as file:line:col and keeps the image,
  a camera posted comes back as a `camera(...)` statement that kerf itself
  reads as the same camera (kerf dump), and the newest of a burst of
  cameras is the one rendered.

Usage: test_view_server.py KERF"""
import os
import re
import selectors
import socket
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_process import Events, View  # noqa: E402

KERF = sys.argv[1]
SCENE = "material(color = \"red\") sphere(1);\ncamera(position = [0, -5, 0], look_at = [0, 0, 0]);\n"
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAILED:", what, flush=True)


def non_loopback_address():
    """An address of this machine that is not loopback (no packet is sent)."""
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        s.connect(("192.0.2.123", 9))
        a = s.getsockname()[0]
        return None if a.startswith("127.") else a
    except OSError:
        return None
    finally:
        s.close()


def test_refuses_other_hosts():
    for host in ["0.0.0.0", "::", "192.0.2.2", "10.0.0.1", "example.com", "127.0.0.1.example.com", ""]:
        r = subprocess.run([KERF, "view", "x.sdl", "--host", host], capture_output=True, text=True, timeout=10)
        check(r.returncode == 2 and "loopback" in r.stderr, "--host %r refused with exit 2 (got %d: %s)" %
              (host, r.returncode, r.stderr.strip()))


def test_loopback_only(v):
    # A second server cannot take the same port (no SO_REUSEPORT sharing).
    r = subprocess.run([KERF, "view", v.scene, "--port", str(v.port)], capture_output=True, text=True, timeout=10)
    check(r.returncode == 2 and "cannot listen" in r.stderr, "a second kerf view on port %d is refused (got %d: %s)" %
          (v.port, r.returncode, r.stderr.strip()))
    addr = non_loopback_address()
    if not addr:
        print("note: no non-loopback address here; the bind check is the --host one only")
        return
    s = socket.socket()
    s.settimeout(3)
    try:
        s.connect((addr, v.port))
        check(False, "kerf view answered on %s:%d, not loopback" % (addr, v.port))
    except OSError:
        pass
    finally:
        s.close()


def test_routes(v):
    status, body, r = v.request("GET", "/")
    check(status == 200 and b"<html" in body and r.getheader("Content-Type").startswith("text/html"), "/ serves the page")
    check("frame-ancestors 'none'" in (r.getheader("Content-Security-Policy") or ""), "the page may not be framed")
    secret = open(v.scene, "rb").read()
    for path in ["/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/image/../../../etc/passwd",
                 "/image/..%2f..%2f..%2fetc%2fpasswd", "/image/1.png/../../etc/passwd", "//etc/passwd",
                 "/etc/passwd", "/scene.sdl", "/" + os.path.basename(v.scene), v.scene, "/view.err",
                 "/index.html", "/page.html", "/image/", "/image/abc.png", "/image/1.png%00.sdl",
                 "/image/99999999999999999999999.png", "/events/../scene.sdl", "/.%2e/scene.sdl",
                 "/?file=/etc/passwd", "/%00"]:
        status, body, _ = v.request("GET", path)
        want = 200 if path == "/?file=/etc/passwd" else 404  # the page; the query means nothing
        check(status == want, "GET %s is %d (got %d)" % (path, want, status))
        check(b"root:" not in body and secret not in body, "GET %s gives no file's bytes" % path)
    for method in ["PUT", "DELETE", "PATCH"]:
        status, _, _ = v.request(method, "/")
        check(status in (404, 405, 400), "%s / refused (got %d)" % (method, status))


def test_foreign_hosts(v):
    p = v.port
    bad = [{"Host": "evil.example:%d" % p}, {"Host": "127.0.0.1:%d" % (p + 1 if p < 65535 else p - 1)},
           {"Host": "127.0.0.1"}, {"Host": "localhost.evil.example:%d" % p}, {"Host": "127.0.0.2:%d" % p},
           {"Origin": "http://evil.example"}, {"Origin": "http://evil.example:%d" % p}, {"Origin": "null"},
           {"Origin": "https://127.0.0.1:%d" % p}, {"Sec-Fetch-Site": "cross-site"},
           {"Sec-Fetch-Site": "same-site"}]
    for headers in bad:
        for path in ["/", "/events", "/image/1.png"]:
            status, _, _ = v.request("GET", path, headers)
            check(status == 403, "GET %s with %s is 403 (got %d)" % (path, headers, status))
    for headers in [{"Host": "localhost:%d" % p}, {"Origin": "http://127.0.0.1:%d" % p},
                    {"Origin": "http://localhost:%d" % p}, {"Sec-Fetch-Site": "same-origin"}]:
        status, _, _ = v.request("GET", "/", headers)
        check(status == 200, "GET / with %s is 200 (got %d)" % (headers, status))
    # No Host at all (HTTP/1.0): not its own either.
    s = socket.create_connection(("127.0.0.1", p), timeout=5)
    s.sendall(b"GET / HTTP/1.0\r\n\r\n")
    head = s.recv(200)
    s.close()
    check(head.startswith(b"HTTP/1.1 403"), "a request without Host is 403 (got %r)" % head[:20])


def test_camera_statement(v):
    ev = Events(v)
    try:
        ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full")
        # A foreign page posting a camera is refused and moves nothing.
        status, _, _ = v.request("POST", "/camera?position=9,9,9&look_at=0,0,0&up=0,0,1&fov=20",
                                 {"Origin": "http://evil.example"})
        check(status == 403, "a foreign POST /camera is 403 (got %d)" % status)
        for q in ["position=1,2&look_at=0,0,0&up=0,0,1&fov=30", "position=1,2,3&look_at=1,2,3&up=0,0,1&fov=30",
                  "position=1,2,3&look_at=0,0,0&up=0,0,1&fov=180", "position=nan,2,3&look_at=0,0,0&up=0,0,1&fov=30",
                  "position=1e31,2,3&look_at=0,0,0&up=0,0,1&fov=30", "position=0,0,5&look_at=0,0,0&up=0,0,1&fov=30",
                  "position=1,2,3&look_at=0,0,0&up=0,0,1", "position=1,2,3&look_at=0,0,0&up=0,0,1&fov=30&height=2",
                  "position=1,2,3x&look_at=0,0,0&up=0,0,1&fov=30"]:
            status, _, _ = v.request("POST", "/camera?" + q)
            check(status == 400, "POST /camera?%s is 400 (got %d)" % (q, status))
        status, _, _ = v.request("POST", "/camera?position=4.25,-3.5,2.125&look_at=0.5,0,-0.25&up=0,0,1&fov=33.5")
        check(status == 204, "a good camera is accepted (got %d)" % status)
        _, d = ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full" and d["camera"]["fov"] == 33.5)
        check(d["camera"]["position"] == [4.25, -3.5, 2.125], "the image is rendered from the camera posted")
        stmt = d["statement"]
        check(stmt == "camera(position = [4.25, -3.5, 2.125], look_at = [0.5, 0, -0.25], up = [0, 0, 1], fov = 33.5);",
              "the statement reads %s" % stmt)
        # kerf itself, reading the statement, has the same camera.
        pasted = os.path.join(v.dir, "pasted.sdl")
        with open(pasted, "w") as f:
            f.write(stmt + "\nsphere(1);\n")
        dump = subprocess.run([KERF, "dump", pasted], capture_output=True, text=True, timeout=20).stdout
        check("camera perspective position=[4.25 -3.5 2.125] look_at=[0.5 0 -0.25] up=[0 0 1] fov=33.5" in dump,
              "kerf dump of the pasted statement shows the same camera: %s" % dump.splitlines()[2:3])
        # An orthographic view as well.
        status, _, _ = v.request("POST", "/camera?position=0,-8,0&look_at=0,0,0&up=0,0,1&height=3.5")
        _, d = ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full" and d["camera"]["orthographic"])
        check(d["statement"].endswith('projection = "orthographic", height = 3.5);'), "orthographic: %s" % d["statement"])
        # A burst of cameras: the newest is the one rendered last.
        for i in range(20):
            v.request("POST", "/camera?position=%d,-6,1&look_at=0,0,0&up=0,0,1&fov=40" % (i - 10))
        _, d = ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full" and d["camera"]["position"][0] == 9)
        time.sleep(0.5)
        status, _, _ = v.request("GET", d["url"])
        check(status == 200, "the newest image can be fetched")
        status, _, _ = v.request("POST", "/reset")
        _, d = ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full" and d["camera"]["position"] == [0, -5, 0])
        check(True, "reset returns to the scene's camera")
    finally:
        ev.close()


def test_save_and_error(v):
    ev = Events(v)
    try:
        _, first = ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full")
        v.write(SCENE.replace("sphere(1)", "cube(1.5, center = true)"))
        # The stream may skip the preview (it sends the newest image of
        # each kind): the preview is the image just before the full one.
        _, full = ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full" and d["id"] > first["id"])
        status, png, _ = v.request("GET", "/image/%d.png" % (full["id"] - 1))
        width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
        check(status == 200 and png[:8] == b"\x89PNG\r\n\x1a\n" and (width, height) == (40, 30),
              "a save renders a quarter-size preview first (got %d, %dx%d)" % (status, width, height))
        check((full["width"], full["height"]) == (160, 120), "then the full image")
        pre = full
        v.write("sphere(1);\ncube(;\n")
        _, diag = ev.wait_for(lambda k, d: k == "diagnostics" and d["error"])
        check(re.search(r"scene\.sdl:2:6: error: ", diag["text"]) is not None, "the error is located: %r" % diag["text"])
        check("scene.sdl:2:6: error:" in v.log(), "the error is on standard error too")
        status, _, _ = v.request("GET", "/image/%d.png" % pre["id"])
        check(status == 200, "the last images stay while the scene is broken")
        v.write(SCENE)
        _, ok = ev.wait_for(lambda k, d: k == "diagnostics" and not d["error"])
        ev.wait_for(lambda k, d: k == "image" and d["stage"] == "full")
    finally:
        ev.close()


def many_concurrent(v, n):
    """n connections open at once, each a GET /, all answered 200."""
    sel = selectors.DefaultSelector()
    socks = []
    for _ in range(n):
        s = socket.socket()
        s.setblocking(False)
        s.connect_ex(("127.0.0.1", v.port))
        socks.append(s)
        sel.register(s, selectors.EVENT_WRITE, [b"", False])
    req = b"GET / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nConnection: close\r\n\r\n" % v.port
    done, ok = 0, 0
    deadline = time.monotonic() + 90
    while done < n and time.monotonic() < deadline:
        for key, mask in sel.select(1):
            s, state = key.fileobj, key.data
            if mask & selectors.EVENT_WRITE and not state[1]:
                try:
                    s.sendall(req)
                except OSError:
                    sel.unregister(s)
                    done += 1
                    continue
                state[1] = True
                sel.modify(s, selectors.EVENT_READ, state)
            elif mask & selectors.EVENT_READ:
                try:
                    chunk = s.recv(65536)
                except OSError:
                    chunk = b""
                if chunk:
                    state[0] += chunk
                else:
                    sel.unregister(s)
                    done += 1
                    ok += state[0].startswith(b"HTTP/1.1 200") and b"</html>" in state[0]
    for s in socks:
        s.close()
    return ok


def test_load(v):
    base_fds, base_threads = v.fds(), v.threads()
    start = time.monotonic()
    ok = many_concurrent(v, 1000)
    check(ok == 1000, "1000 concurrent requests all answered 200 (%d were, in %.1f s)" % (ok, time.monotonic() - start))
    print("1000 concurrent GET /: %.2f s" % (time.monotonic() - start))

    # Stalled clients: connected, half a request, then nothing. Each frees
    # its thread after the read timeout.
    stalled = []
    for _ in range(100):
        s = socket.create_connection(("127.0.0.1", v.port))
        s.sendall(b"GET / HTTP/1.1\r\nHost: 127.0")
        stalled.append(s)
    # Trickling clients (a byte every 0.3 s), fewer than the server's threads.
    stop = threading.Event()

    def trickle():
        s = socket.create_connection(("127.0.0.1", v.port))
        try:
            for b in b"GET / HTTP/1.1\r\nX-Slow: " + b"a" * 1000:
                if stop.is_set():
                    break
                s.send(bytes([b]))
                time.sleep(0.3)
        except OSError:
            pass
        finally:
            s.close()

    tricklers = [threading.Thread(target=trickle) for _ in range(16)]
    for t in tricklers:
        t.start()
    t0 = time.monotonic()
    answered = False
    while time.monotonic() - t0 < 30:
        try:
            status, _, _ = v.request("GET", "/", timeout=30)
            answered = status == 200
            break
        except OSError:
            time.sleep(0.2)
    check(answered, "a request beside 100 stalled and 16 trickling clients is answered")
    print("answered beside stalled and trickling clients after %.2f s" % (time.monotonic() - t0))
    stop.set()
    for t in tricklers:
        t.join()
    for s in stalled:
        s.close()

    # Malformed HTTP, each on its own connection.
    garbage = [b"\x00\x01\x02\xff" * 64 + b"\r\n\r\n", b"GARBAGE\r\n\r\n", b"GET\r\n\r\n", b"GET /\r\n\r\n",
               b"GET / HTTP/9.9\r\nHost: 127.0.0.1\r\n\r\n", b"BREW / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % v.port,
               b"GET / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX: " % v.port + b"a" * 100000 + b"\r\n\r\n",
               b"GET /" + b"a" * 20000 + b" HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % v.port,
               b"POST /camera HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nContent-Length: -5\r\n\r\n" % v.port,
               b"POST /camera HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nContent-Length: 99999999999999999999\r\n\r\nx" % v.port,
               b"POST /camera HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nContent-Length: 10000000\r\n\r\nxx" % v.port,
               b"POST /camera HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\nxx\r\n" % v.port,
               b"GET / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nRange: bytes=99999999-1\r\n\r\n" % v.port,
               b"GET / HTTP/1.1\r\n" + b"X: y\r\n" * 5000 + b"\r\n",
               b"GET /%%zz HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % v.port,
               b"\r\n" * 10000]
    for g in garbage:
        s = socket.create_connection(("127.0.0.1", v.port), timeout=10)
        try:
            s.sendall(g)
            s.recv(4096)
        except OSError:
            pass
        s.close()
        check(v.alive(), "kerf view survives %r" % g[:40])
    status, _, _ = v.request("GET", "/")
    check(status == 200, "still answering after malformed requests")

    # Nothing left over once the clients are gone and the timeouts passed.
    deadline = time.monotonic() + 20
    while time.monotonic() < deadline and (v.fds() > base_fds + 2 or v.threads() > base_threads + 2):
        time.sleep(0.5)
    check(v.fds() <= base_fds + 2, "file descriptors back to %d (now %d)" % (base_fds, v.fds()))
    check(v.threads() <= base_threads + 2, "threads back to %d (now %d)" % (base_threads, v.threads()))


def main():
    test_refuses_other_hosts()
    v = View(KERF, SCENE)
    try:
        test_loopback_only(v)
        test_routes(v)
        test_foreign_hosts(v)
        test_save_and_error(v)
        test_camera_statement(v)
        test_load(v)
        check(v.alive(), "kerf view is still running")
    finally:
        v.close()
    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
