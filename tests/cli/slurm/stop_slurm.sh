#!/usr/bin/env bash
# Stops what start_slurm.sh $1 started, by the pids it recorded.
dir=$1
for f in "$dir"/slurmd-*.pid "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
  [[ -f $f ]] && kill "$(cat "$f")" 2>/dev/null
done
exit 0
