#!/usr/bin/env bash
# Runs `kerf check` on every example file of the Debian `openscad` package
# (docs/openscad.md, "The corpus") and prints the pass count and, for each
# failure, its first diagnostic. A failure whose first error names a 2D
# shape or an extrusion is marked [2D]: that half of OpenSCAD is another
# issue's work. Prints "skipped" and exits 0 when the examples are not
# installed (apt-get install openscad).
#
# usage: scripts/openscad_corpus.sh [KERF_BINARY] [EXAMPLES_DIR]
#   exit 0 always, unless KERF_CORPUS_MIN=N is set and fewer than N pass.
set -uo pipefail
cd "$(dirname "$0")/.."
kerf=${1:-build/kerf}
examples=${2:-/usr/share/openscad/examples}
if [[ ! -d "$examples" ]]; then
  echo "openscad corpus: skipped (no $examples; apt-get install openscad)"
  exit 0
fi
if [[ ! -x "$kerf" ]]; then
  echo "openscad corpus: no kerf binary at $kerf" >&2
  exit 2
fi
kerf=$(realpath "$kerf")

two_d='square|circle|polygon|text|linear_extrude|rotate_extrude|projection|offset|import|surface'
pass=0 total=0 two_d_fail=0
failures=()
while IFS= read -r f; do
  total=$((total + 1))
  # Run from the file's folder, as OpenSCAD resolves relative imports.
  out=$(cd "$(dirname "$f")" && timeout 60 "$kerf" check "$(basename "$f")" 2>&1 >/dev/null)
  rc=$?
  if [[ $rc -eq 0 ]]; then
    pass=$((pass + 1))
    continue
  fi
  first=$(grep -m1 -E ': error: |^kerf: error' <<<"$out")
  [[ -z "$first" ]] && first="exit $rc: $(head -n1 <<<"$out")"
  tag=""
  if grep -qE "'($two_d)' \(.*\) is not implemented" <<<"$first"; then
    tag=" [2D]"
    two_d_fail=$((two_d_fail + 1))
  fi
  failures+=("${f#"$examples"/}$tag: ${first#*: error: }")
done < <(find "$examples" -name '*.scad' | sort)

for line in "${failures[@]}"; do echo "FAIL $line"; done
echo "openscad corpus: $pass of $total pass kerf check ($two_d_fail of the failures stop at a 2D shape)"
if [[ -n "${KERF_CORPUS_MIN:-}" && $pass -lt $KERF_CORPUS_MIN ]]; then
  echo "openscad corpus: fewer than KERF_CORPUS_MIN=$KERF_CORPUS_MIN pass" >&2
  exit 1
fi
exit 0
