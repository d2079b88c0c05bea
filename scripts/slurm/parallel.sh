#!/usr/bin/env bash
# The same farm without Slurm: GNU parallel runs the bands (or frames) on
# the machines listed in HOSTS over ssh, then the bands are joined here
# (docs/farm.md):
#   HOSTS=hosts.txt SCENE=s.sdl TILES=16 scripts/slurm/parallel.sh tiles
#   HOSTS=hosts.txt SCENE=s.sdl FRAMES=240 scripts/slurm/parallel.sh frames
# HOSTS is a parallel --sshloginfile ("4/node1" runs 4 jobs on node1; ":"
# is this machine). The scene goes to each host and the images come back
# (--transferfile/--return), so no shared file system is needed; kerf must
# be installed on every host (KERF names it, the same path everywhere).
# Give KERF_ARGS --threads N to match the jobs per host. Rerunning after an
# interruption renders only what is missing (--resume).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mode=${1:?usage: parallel.sh frames|tiles}
# shellcheck source=scripts/slurm/farm.sh
source "$here/farm.sh"
: "${HOSTS:?set HOSTS to a GNU parallel --sshloginfile}"
cd "$(dirname "$SCENE")"
scene=$(basename "$SCENE")
out=$(basename "$OUT")
[[ $(dirname "$OUT") == . || $(realpath "$(dirname "$OUT")") == "$(pwd)" ]] ||
  { echo "parallel.sh: OUT must lie beside the scene" >&2; exit 2; }
args=("$scene" -o "$out" "${render_args[@]:3}")
# The job log lets a rerun skip what finished (--resume-failed) on any host.
p=(parallel --sshloginfile "$HOSTS" --transferfile "$scene" --cleanup --joblog "${out%.*}.$mode.log" --resume-failed)
case $mode in
  tiles)
    : "${TILES:?set TILES to the number of bands}"
    OUT=$out
    mapfile -t bands < <(tile_files "$TILES")
    last=$((TILES - 1))
    "${p[@]}" --return "${out%.*}_tile{=\$_=sprintf('%0${#last}d',\$_)=}of$TILES.png" \
      "$KERF" render "${args[@]}" --tile "{}/$TILES" ::: $(seq 0 "$last")
    "$KERF" assemble "$out" "${bands[@]}"
    ;;
  frames)
    : "${FRAMES:?set FRAMES to the number of frames}"
    digits=$(( ${#FRAMES} > 4 ? ${#FRAMES} : 4 ))
    "${p[@]}" --return "${out%.*}_{=\$_=sprintf('%0${digits}d',\$_)=}.png" \
      "$KERF" render "${args[@]}" --frames "$FRAMES" --frame "{}" ::: $(seq 1 "$FRAMES")
    ;;
  *) echo "parallel.sh: expected frames or tiles, not '$mode'" >&2; exit 2 ;;
esac
