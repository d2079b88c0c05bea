#!/usr/bin/env bash
# Configures and builds kerf into build/ (RelWithDebInfo), with the tests and
# benchmarks unless the extra arguments (given to the CMake configure step)
# say otherwise: stated each time, so a build configured by demo.sh without
# them gets them back.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKERF_BUILD_TESTS=ON -DKERF_BUILD_BENCH=ON "$@" >/dev/null
cmake --build build -j"$(nproc)"
