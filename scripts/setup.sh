#!/usr/bin/env bash
# Installs exactly the Debian packages kerf's build and tests need.
# Idempotent: does nothing when they are all present. `--bench` adds the
# benchmark peers and plotting (POV-Ray, gnuplot).
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libembree-dev libtbb-dev tao-pegtl-dev libopenimageio-dev libpng-dev zlib1g-dev libglm-dev catch2
  clang libclang-rt-14-dev   # libFuzzer + sanitizers for the fuzz test
  libbenchmark-dev
  openscad   # its examples are the corpus test (scripts/openscad_corpus.sh) and its echo output the reference
)
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
