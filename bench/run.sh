#!/usr/bin/env bash
# The benchmark in one command: installs the peers (POV-Ray, gnuplot, time),
# builds kerf, renders every scene with kerf and POV-Ray alternately and
# prints one row per scene; results, tables and plots land in bench/out/.
#   bench/run.sh            # full run (reference models at 2048², ~35 min on 2 cores)
#   bench/run.sh --quick    # smoke test: small images, small families, one run (bench/out/quick/)
# Other options: python3 bench/bench.py --help (e.g. --only 'holes', --no-pov).
# Exits non-zero when a silhouette check fails (the two renderers disagree).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh --bench
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)" --target kerf
exec python3 bench/bench.py "$@"
