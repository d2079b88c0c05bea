#!/usr/bin/env bash
# Installs exactly the Debian packages kerf needs. Idempotent: does nothing
# when they are all present. `--render`: only what building and running
# kerf needs (the README's render command); default: also the test suite's
# tools and peers; `--bench` adds the benchmark peers and plotting
# (POV-Ray, gnuplot).
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libembree-dev libtbb-dev tao-pegtl-dev libopenimageio-dev libpng-dev zlib1g-dev libglm-dev
  libopenexr-dev libtiff-dev libjpeg-dev   # .exr, .tif, .jpg written and read without loading OpenImageIO
  libfreetype-dev libfontconfig-dev libharfbuzz-dev fonts-liberation2   # text(): outlines, lookup, shaping, default font
  libqhull-dev   # hull(), minkowski(): convex hulls (libqhull_r)
  libpolyclipping-dev   # offset(): Clipper's polygon booleans and offsets
  libdxflib-dev   # import() of .dxf drawings
  libxml2-dev   # import() of .svg drawings and .amf meshes: the XML (kerf parses path data itself)
  lib3mf-dev libzip-dev   # import() of .3mf meshes (the lib3mf 1.8 OpenSCAD 2021.01 links; it needs -lzip) and zipped .amf
  libcpp-httplib-dev   # kerf view's HTTP server
)
if [[ "${1:-}" != "--render" ]]; then
  packages+=(
    catch2 libbenchmark-dev
    clang libclang-rt-14-dev   # libFuzzer + sanitizers for the fuzz test
    openscad   # its examples are the corpus test (scripts/openscad_corpus.sh) and its echo output the reference
    slurm-wlm munge parallel   # the farm scripts' test starts a real single-node Slurm (docs/farm.md)
    python3 chromium chromium-driver   # kerf view's tests: HTTP and security from Python, the page in headless Chromium
  )
fi
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(povray gnuplot-nox hyperfine time)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

sudo=()
[[ $(id -u) -ne 0 ]] && sudo=(sudo)
echo "kerf setup: installing ${missing[*]}" >&2
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
