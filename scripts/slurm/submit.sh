#!/usr/bin/env bash
# Submits a kerf render to Slurm (docs/farm.md):
#   submit.sh frames [SBATCH OPTION...]   an array of FRAMES frame jobs
#   submit.sh tiles  [SBATCH OPTION...]   an array of TILES band jobs and an
#                                         assembly job that waits for them
# The render's parameters come from the environment (farm.sh: SCENE, OUT,
# WIDTH, HEIGHT, QUALITY, FRAMES, TILES, KERF, KERF_ARGS); further
# arguments go to every sbatch (--partition, --time, --cpus-per-task, ...).
# Prints the job ids. Resumable: run it again after a failure or a kill and
# only the missing frames or bands are rendered.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mode=${1:?usage: submit.sh frames|tiles [SBATCH OPTION...]}
shift
export KERF_FARM_DIR=$here  # Slurm runs a copy of the script: farm.sh is found through this
# shellcheck source=scripts/slurm/farm.sh
( source "$here/farm.sh" ) || exit 2   # the parameters, checked before anything is queued
case $mode in
  frames)
    : "${FRAMES:?set FRAMES to the number of frames}"
    sbatch --parsable --export=ALL --array="1-$FRAMES" "$@" "$here/frames.sbatch"
    ;;
  tiles)
    : "${TILES:?set TILES to the number of bands}"
    tiles=$(sbatch --parsable --export=ALL --array="0-$((TILES - 1))" "$@" "$here/tiles.sbatch")
    echo "$tiles"
    sbatch --parsable --export=ALL --dependency="afterok:${tiles%%;*}" --kill-on-invalid-dep=yes "$@" \
      "$here/assemble.sbatch"
    ;;
  *) echo "submit.sh: expected frames or tiles, not '$mode'" >&2; exit 2 ;;
esac
