#!/usr/bin/env bash
# The whole test suite, from a fresh Debian machine: install dependencies,
# build, run every Catch2 test through CTest, then fuzz parse+evaluate for a
# bounded time (clang, ASan/UBSan, libFuzzer).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
./scripts/fuzz.sh "${KERF_FUZZ_SECONDS:-60}"
cd build
ctest --output-on-failure -j"$(nproc)" --timeout 300
