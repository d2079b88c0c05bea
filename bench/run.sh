#!/usr/bin/env bash
# The benchmark in one command: installs the peers (POV-Ray, gnuplot, time),
# builds kerf, renders every scene with kerf and POV-Ray alternately and
# prints one row per scene; tables and plots land in bench/out/.
#   bench/run.sh            # full run (reference models at 2048², ~45 min on 2 cores)
#   bench/run.sh --quick    # smoke test: small images, small families, one run
# Other options: python3 bench/bench.py --help (e.g. --only 'holes', --no-pov).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh --bench
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)" --target kerf
status=0
python3 bench/bench.py "$@" || status=$?
out=bench/out
for ((i = 1; i <= $#; i++)); do [[ "${!i}" == --out ]] && { j=$((i + 1)); out="${!j}"; }; done
python3 bench/report.py "$out" >/dev/null && echo "tables: $out/tables.md, plots: $out/scaling_*.png"
exit "$status"
