#!/usr/bin/env bash
# OpenSCAD's own outlines of the text() cases beside this script: each
# CASE.scad is exported by Debian's openscad (2021.01) to CASE.dxf, the
# reference test_layout.cpp compares kerf's glyphs with, its curves cut
# into 128 chords each ($fn) so that they lie close to the true ones. Run it again only
# when a case is added or changed:  tests/interpreter/text/reference/make_reference.sh
set -euo pipefail
cd "$(dirname "$0")"
for scad in *.scad; do
  openscad -D '$fn=128' -o "${scad%.scad}.dxf" "$scad" 2>/dev/null
done
