#!/usr/bin/env bash
# From a fresh Debian machine: install dependencies, build, and render an
# example scene to an image.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh --render
./scripts/build.sh -DKERF_BUILD_TESTS=OFF -DKERF_BUILD_BENCH=OFF  # kerf alone: no test tools needed
./build/kerf render examples/showcase.sdl -o showcase.png -W 800 -H 600
echo "wrote $(pwd)/showcase.png"
