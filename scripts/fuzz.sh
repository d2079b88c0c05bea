#!/usr/bin/env bash
# Builds the libFuzzer target over parse + evaluate + lower + render with clang and ASan/UBSan
# into build-fuzz/, then runs it for the given number of seconds (default 60)
# from the seed corpus (examples/, stdlib/, tests/fuzz/corpus/, tests/scripts/),
# each input as a .sdl and as a .scad file.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
CXX=clang++ cmake -S . -B build-fuzz -DKERF_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target kerf_fuzz_eval
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp examples/*.sdl stdlib/*.sdl tests/fuzz/corpus/* "$corpus"/ 2>/dev/null || true
# The golden scripts (tests/scripts/, the fuzz regressions among them, the
# .scad ones in OpenSCAD's dialect) seed it too; each input runs in both
# dialects (tests/fuzz/fuzz_eval.cpp). OpenSCAD's own examples are not
# seeds: some take seconds under the sanitizers (Advanced/GEB.scad, 2 s
# without them), past the timeout that catches hangs.
find tests/scripts -name '*.sdl' -o -name '*.scad' | while read -r f; do cp "$f" "$corpus/scripts_${f//\//_}"; done
# fontconfig's process-lifetime state is not a leak (tests/fuzz/lsan.supp).
export LSAN_OPTIONS="suppressions=$(pwd)/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# ASan's quarantine of freed blocks (256 MB by default) fragments its heap:
# a mutation of the tail-call golden script (500,000 loop passes, strings
# growing to 20,000 characters) peaked at 1.9 GB under it and passed the
# 2 GB limit below, where kerf itself needs 10 MB; 16 MB keeps that input
# at 0.37 GB and still catches a use of a block freed shortly before.
export ASAN_OPTIONS="quarantine_size_mb=16${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
echo "fuzzing parse + evaluate + lower + render for ${seconds}s" >&2
./build-fuzz/tests/fuzz/kerf_fuzz_eval -max_total_time="$seconds" -max_len=4096 \
  -timeout=10 -rss_limit_mb=2048 -dict=tests/fuzz/sdl.dict -print_final_stats=1 "$corpus" 2>build-fuzz/fuzz.log \
  || { tail -50 build-fuzz/fuzz.log; echo "fuzz: FAILED (crash input saved as crash-* in $(pwd))" >&2; exit 1; }
grep -E "stat::number_of_executed_units|Done" build-fuzz/fuzz.log >&2 || true
