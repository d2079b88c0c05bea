#!/usr/bin/env python3
"""kerf against OpenSCAD's own test data (docs/openscad.md, "OpenSCAD's
test data").

OpenSCAD's repository keeps hundreds of small .scad files under
tests/data/scad (2D, 3D, functions, misc, ...). They are not part of this
repository: fetch openscad/openscad and unpack its tests/data folder
somewhere outside it, then give that folder's scad/ as --data.

Each file runs, from its own folder (relative imports resolve as in
OpenSCAD), through
  - `kerf check FILE` (or `kerf render` of a tiny image with --render),
    with a timeout; the outcome is pass (exit 0), error (exit 1 or 2 with
    a located `error:` line: its first message is kept), or crash (a
    signal, another exit code, or a failure without an error line) and
    timeout, which must both be zero;
  - Debian's `openscad` 2021.01, `openscad -o F.echo FILE`, to know what
    the reference accepts: accepted (no ERROR), error (an ERROR line: a
    failed assert, a recursion, ... which kerf should refuse too), or newer
    (a parser error: syntax of a later OpenSCAD, counted apart). Its
    results are cached in --cache by the file's hash.
For files both accept, the ECHO lines are compared too.

usage: scripts/openscad_testdata.py --data DIR/tests/data/scad
         [--kerf build/kerf] [--openscad openscad] [--timeout 60]
         [--jobs 2] [--render] [--cache FILE] [--only SUBSTR]
         [--list pass,error,crash,echo,...] [--top 25]
exit: 0, or 1 when any file crashes or times out in kerf, 2 bad usage.
"""
import argparse
import collections
import concurrent.futures
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile

ERROR_LINE = re.compile(r"(?:^|: )error: (.*)$")


def run(cmd, cwd, timeout):
    """(exit code or 'timeout', combined stdout+stderr text)."""
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=timeout)
        return p.returncode, p.stdout.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode("utf-8", "replace") if e.stdout else ""
        return "timeout", out


def echo_lines(text):
    return [l for l in text.splitlines() if l.startswith("ECHO:")]


def kerf_outcome(kerf, path, timeout, render, scratch):
    folder, name = os.path.split(path)
    if render:
        out = os.path.join(scratch, hashlib.sha1(path.encode()).hexdigest() + ".png")
        cmd = [kerf, "render", name, "-o", out, "-W", "16", "-H", "12",
               "--no-progress", "--quality", "draft"]
    else:
        cmd = [kerf, "check", name]
    rc, text = run(cmd, folder, timeout)
    if rc == "timeout":
        return {"kind": "timeout", "message": f"no result in {timeout} s", "echo": []}
    first = None
    for line in text.splitlines():
        m = ERROR_LINE.search(line)
        if m and not line.startswith("ECHO:"):
            first = m.group(1)
            break
    if rc == 0:
        kind = "pass"
    elif rc in (1, 2) and first is not None:
        kind = "error"
    else:
        kind = "crash"
        first = f"exit {rc}: " + (text.strip().splitlines() or [""])[-1]
    return {"kind": kind, "message": first, "echo": echo_lines(text),
            "warnings": sum(1 for l in text.splitlines() if ": warning: " in l)}


def openscad_outcome(openscad, path, timeout, scratch):
    folder, name = os.path.split(path)
    echo = os.path.join(scratch, hashlib.sha1(path.encode()).hexdigest() + ".echo")
    rc, text = run([openscad, "-o", echo, name], folder, timeout)
    # With -o F.echo, OpenSCAD writes its messages (ECHO, WARNING, ERROR)
    # into F.echo rather than to its standard error.
    if os.path.exists(echo):
        # Its own output may end without a line break (misc/unicode-tests.scad
        # prints a row of backslashes): the file's first line stays a line.
        if text and not text.endswith("\n"):
            text += "\n"
        with open(echo, encoding="utf-8", errors="replace") as f:
            text += f.read()
        os.unlink(echo)
    errors = [l for l in text.splitlines() if l.startswith("ERROR:")]
    if rc == "timeout":
        kind = "timeout"
    elif any("Parser error" in l for l in errors):
        kind = "newer"
    elif errors or rc != 0:
        kind = "error"
    else:
        kind = "accepted"
    return {"kind": kind, "message": errors[0] if errors else None,
            "echo": echo_lines(text)}


def normalise(message):
    """A message's shape, so that one cause counts once: quoted names and
    numbers replaced."""
    m = re.sub(r"'[^']*'", "'…'", message)
    m = re.sub(r'"[^"]*"', '"…"', m)
    return re.sub(r"-?\b\d+(\.\d+)?(e[-+]?\d+)?\b", "N", m)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--data", required=True, help="OpenSCAD's tests/data/scad")
    ap.add_argument("--kerf", default="build/kerf")
    ap.add_argument("--openscad", default="openscad")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--render", action="store_true")
    ap.add_argument("--cache", help="JSON file keeping OpenSCAD's outcomes")
    ap.add_argument("--only", default="", help="files whose path contains this")
    ap.add_argument("--list", default="crash,timeout",
                    help="outcomes to list file by file: pass, error, crash, "
                         "timeout, echo (ECHO lines differ), refused (kerf "
                         "passes what OpenSCAD refuses)")
    ap.add_argument("--top", type=int, default=25)
    args = ap.parse_args()

    data = os.path.realpath(args.data)
    kerf = os.path.realpath(args.kerf)
    if not os.path.isdir(data) or not os.access(kerf, os.X_OK):
        print(f"need --data folder and a kerf binary ({data}, {kerf})", file=sys.stderr)
        return 2
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(data)
                   for f in fs if f.endswith(".scad") and args.only in os.path.join(d, f))
    cache = {}
    if args.cache and os.path.exists(args.cache):
        cache = json.load(open(args.cache))

    scratch = tempfile.mkdtemp(prefix="kerf-testdata-")

    def one(path):
        rel = os.path.relpath(path, data)
        digest = hashlib.sha1(open(path, "rb").read()).hexdigest()
        ref = cache.get(rel)
        if not ref or ref.get("sha1") != digest:
            ref = openscad_outcome(args.openscad, path, 2 * args.timeout, scratch)
            ref["sha1"] = digest
        return rel, kerf_outcome(kerf, path, args.timeout, args.render, scratch), ref

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(one, files))
    if args.cache:
        cache.update({rel: ref for rel, _, ref in results})
        with open(args.cache, "w") as f:
            json.dump(cache, f, indent=0, sort_keys=True)
    try:
        os.rmdir(scratch)
    except OSError:
        pass

    table = collections.Counter()
    messages = collections.Counter()
    listed = set(args.list.split(","))
    for rel, k, ref in results:
        table[(ref["kind"], k["kind"])] += 1
        if ref["kind"] == "accepted" and k["kind"] == "error":
            messages[normalise(k["message"])] += 1
        echo_differs = (ref["kind"] == "accepted" and k["kind"] == "pass"
                        and k["echo"] != ref["echo"])
        if echo_differs:
            table[("accepted", "pass, echo differs")] += 1
        show = (k["kind"] in listed or (echo_differs and "echo" in listed)
                or ("refused" in listed and ref["kind"] == "error" and k["kind"] == "pass"))
        if show:
            print(f"{k['kind'].upper():8} {rel}: {k['message'] or ''}"
                  f"  [openscad: {ref['kind']}{': ' + ref['message'] if ref['message'] else ''}]")
            if echo_differs and "echo" in listed:
                for a, b in zip(ref["echo"] + [""] * len(k["echo"]), k["echo"] + [""] * len(ref["echo"])):
                    if a != b:
                        print(f"    openscad: {a}\n    kerf:     {b}")
                        break

    mode = "render" if args.render else "check"
    print(f"\n{len(results)} files, kerf {mode} against openscad 2021.01 -o F.echo")
    for ref_kind in ("accepted", "error", "newer", "timeout"):
        row = {k: table[(ref_kind, k)] for k in ("pass", "error", "crash", "timeout")}
        total = sum(row.values())
        if not total:
            continue
        extra = (f", {table[('accepted', 'pass, echo differs')]} of the passes echo differently"
                 if ref_kind == "accepted" else "")
        print(f"  openscad {ref_kind:8} {total:4}: kerf pass {row['pass']}, error {row['error']}, "
              f"crash {row['crash']}, timeout {row['timeout']}{extra}")
    print(f"\ntop kerf errors on files OpenSCAD accepts ({sum(messages.values())}):")
    for message, n in messages.most_common(args.top):
        print(f"  {n:4}  {message}")
    bad = sum(table[(r, k)] for r in ("accepted", "error", "newer", "timeout")
              for k in ("crash", "timeout"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
