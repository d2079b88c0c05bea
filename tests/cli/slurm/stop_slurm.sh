#!/usr/bin/env bash
# Stops what start_slurm.sh $1 started, by the pids it recorded, and waits
# (at most 5 s) until they are gone, so the folder can be removed.
dir=$1
pids=()
for f in "$dir"/slurmd-*.pid "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
  [[ -f $f ]] && pids+=("$(cat "$f")")
done
[[ ${#pids[@]} -gt 0 ]] && kill "${pids[@]}" 2>/dev/null
# A daemon whose parent does not reap it stays a zombie: that counts as gone.
alive() { [[ -r /proc/$1/stat ]] && [[ $(cut -d' ' -f3 "/proc/$1/stat" 2>/dev/null) != Z ]]; }
for _ in $(seq 50); do
  left=0
  for p in "${pids[@]}"; do alive "$p" && left=1; done
  [[ $left -eq 0 ]] && break
  sleep 0.1
done
exit 0
