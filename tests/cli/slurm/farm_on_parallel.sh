#!/usr/bin/env bash
# scripts/slurm/parallel.sh with GNU parallel on this machine (":" as the
# only host; over ssh the same commands run remotely): 6 bands assembled
# must be the bytes of a single render, 3 frames those of a local --frames
# render, and a rerun must keep every file (parallel's job log, kerf's
# --resume). Usage: farm_on_parallel.sh KERF SOURCE_DIR; exit 77 (skipped)
# without GNU parallel.
set -euo pipefail
kerf=$1 root=$2
command -v parallel >/dev/null || { echo "GNU parallel is not installed (apt-get install parallel)" >&2; exit 77; }
work=$(mktemp -d /tmp/kerf_parallel.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work"
cat >scene.sdl <<'SCENE'
material(color = "orange") translate([4 * $t - 1.5, 0, 0]) sphere(1);
cube([3, 1, 2], center = true);
SCENE
echo ":" >hosts
export KERF=$kerf HOSTS=$work/hosts SCENE=$work/scene.sdl WIDTH=80 HEIGHT=60 KERF_ARGS="--seed 5"
mkdir local
TILES=6 "$root/scripts/slurm/parallel.sh" tiles 2>/dev/null
"$kerf" render scene.sdl -W 80 -H 60 --seed 5 -o local/scene.png
cmp scene.png local/scene.png
FRAMES=3 "$root/scripts/slurm/parallel.sh" frames 2>/dev/null
"$kerf" render scene.sdl -W 80 -H 60 --seed 5 --frames 3 -o local/scene.png
for i in 1 2 3; do cmp "scene_000$i.png" "local/scene_000$i.png"; done
before=$(ls -i scene_tile*.png scene_000*.png)
TILES=6 "$root/scripts/slurm/parallel.sh" tiles 2>/dev/null
FRAMES=3 "$root/scripts/slurm/parallel.sh" frames 2>/dev/null
[[ $(ls -i scene_tile*.png scene_000*.png) == "$before" ]] || { echo "FAIL: the rerun rendered again" >&2; exit 1; }
echo "parallel farm: 6 bands assembled byte-identical, 3 frames, rerun kept them all"
