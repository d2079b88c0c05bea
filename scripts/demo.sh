#!/usr/bin/env bash
# From a fresh Debian machine: install dependencies, build, and render an
# example scene to an image.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
./build/kerf render examples/showcase.sdl -o showcase.png -W 800 -H 600
echo "wrote $(pwd)/showcase.png"
