#!/usr/bin/env bash
# The farm scripts on a real single-node Slurm (docs/farm.md): starts one
# (start_slurm.sh), submits the frame array and the tile array with its
# assembly job through scripts/slurm/submit.sh, waits with a bound, and
# checks every frame against a local --frames render, the assembled image
# against a single render (byte for byte), and that resubmitting after a
# killed job keeps the finished frames and renders the rest.
# Usage: farm_on_slurm.sh KERF SOURCE_DIR. Exit 77 (CTest: skipped) where
# Slurm cannot start.
set -euo pipefail
kerf=$1 root=$2
here=$root/tests/cli/slurm
work=$(mktemp -d /tmp/kerf_slurm.XXXXXX)
trap '"$here/stop_slurm.sh" "$work/slurm"; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; for f in "$work"/logs/*; do [[ -f $f ]] && { echo "== $f"; cat "$f"; }; done >&2; exit 1; }

env_line=$("$here/start_slurm.sh" "$work/slurm") || exit $?
export "${env_line?}"

# Wait until none of the jobs is pending or running, at most $1 seconds.
wait_jobs() {
  local limit=$1 ids=$2 left=""
  for ((i = 0; i < limit * 10; i++)); do
    left=$(squeue -h -j "$ids" -o %i 2>/dev/null || true)
    [[ -z $left ]] && return 0
    sleep 0.1
  done
  fail "jobs $ids still queued after $limit s: $(squeue -h -j "$ids" -o '%i %T %r')"
}

cat >"$work/scene.sdl" <<'SCENE'
camera(position = [0, -8, 3], look_at = [0, 0, 0]);
material(color = "orange") translate([4 * $t - 1.5, 0, 0]) sphere(1);
material(color = "steelblue") difference() { cube([6, 1, 4], center = true); rotate([90, 0, 0]) cylinder(h = 3, r = 0.7, center = true); }
SCENE
mkdir -p "$work"/{frames,tiles,local,logs}
export KERF=$kerf SCENE=$work/scene.sdl WIDTH=96 HEIGHT=64 QUALITY=final
cd "$work"
sb=(--output "$work/logs/%x-%A_%a.log")

# Tiles and their assembly, byte-identical to one render of the whole image.
ids=$(OUT=$work/tiles/t.png TILES=8 "$root/scripts/slurm/submit.sh" tiles "${sb[@]}" | tr '\n' ',')
tiles_job=${ids%%,*} assemble_job=${ids#*,}
assemble_job=${assemble_job%,}
# Eight bands on two CPUs take seconds: the assembly is still waiting.
dependency=$(squeue -h -j "$assemble_job" -o %E)
[[ $dependency == "afterok:${tiles_job}_*"* ]] || fail "the assembly job waits for '$dependency', not the tiles"
wait_jobs 60 "${ids%,}"
"$kerf" render "$SCENE" -W $WIDTH -H $HEIGHT --threads 2 -o "$work/local/single.png" 2>/dev/null
[[ -f $work/tiles/t.png ]] || fail "the assembly job wrote no image"
cmp "$work/tiles/t.png" "$work/local/single.png" || fail "assembled image differs from the single render"

# Frames: a job killed part way, then resubmitted. Big enough frames that
# the kill lands while some are still to do.
frame_args=(-W 480 -H 360)
export WIDTH=480 HEIGHT=360 QUALITY=best
n=8
jid=$(OUT=$work/frames/f.png FRAMES=$n "$root/scripts/slurm/submit.sh" frames "${sb[@]}")
for ((i = 0; i < 200; i++)); do
  (( $(find "$work/frames" -name 'f_*.png' | wc -l) >= 2 )) && break
  sleep 0.1
done
scancel --signal=KILL --full "$jid"; scancel "$jid"
wait_jobs 60 "$jid"
done_before=$(find "$work/frames" -name 'f_*.png' | wc -l)
stray=$(find "$work/frames" -type f ! -name 'f_[0-9][0-9][0-9][0-9].png')
[[ -z $stray ]] || fail "the killed renders left files behind: $stray"
(( done_before >= 1 && done_before < n )) || fail "expected the kill to leave part of the $n frames, found $done_before"
ls -i "$work"/frames >"$work/inodes_before"
jid=$(OUT=$work/frames/f.png FRAMES=$n "$root/scripts/slurm/submit.sh" frames "${sb[@]}")
wait_jobs 60 "$jid"
# The rerun reads each frame back whole (every CRC) before it skips it:
# what the kill left is complete frames, no partial ones.
skipped=$(cat "$work"/logs/kerf-frames-"${jid}"_*.log | grep -c "already rendered, skipped" || true)
(( skipped == done_before )) || fail "the rerun skipped $skipped frames, $done_before were finished"
while read -r inode name; do
  [[ $(ls -i "$work/frames/$name" | cut -d' ' -f1) == "$inode" ]] || fail "$name was rendered again"
done <"$work/inodes_before"
"$kerf" render "$SCENE" "${frame_args[@]}" --aa-samples 64 --aa-threshold 0.02 --frames $n -o "$work/local/f.png" 2>/dev/null
for ((i = 1; i <= n; i++)); do
  name=$(printf 'f_%04d.png' "$i")
  cmp "$work/frames/$name" "$work/local/$name" || fail "frame $name differs from a local --frames render"
done
echo "slurm farm: 8 bands assembled byte-identical; $n frames, $done_before kept across a killed job"
