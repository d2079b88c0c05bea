#!/usr/bin/env bash
# Starts a private single-node Slurm (munged, slurmctld, slurmd on
# localhost) in folder $1, with its own munge key, sockets, spool, state and
# ports, so it never touches a system Slurm or another test's. Prints the
# environment (SLURM_CONF=..) to source for sbatch/squeue/scontrol. Exit 77
# when Slurm or munge is missing or cannot start here (the test is then
# skipped, never passed); stop it with stop_slurm.sh $1.
set -uo pipefail
dir=$1
skip() { echo "slurm: cannot start: $*" >&2; exit 77; }
for t in munged mungekey slurmctld slurmd sbatch squeue scontrol; do
  command -v "$t" >/dev/null || skip "$t is not installed (apt-get install slurm-wlm munge)"
done
[[ $(id -u) -eq 0 ]] || skip "slurmd needs root here (it starts jobs as their user)"
mkdir -p "$dir"/{munge,spool,state,log}
chmod 700 "$dir/munge"
mungekey -c -k "$dir/munge/munge.key" -b 1024 2>/dev/null || skip "mungekey failed"
chmod 400 "$dir/munge/munge.key"
socket=$dir/munge/munge.socket
munged -S "$socket" --key-file "$dir/munge/munge.key" --pid-file "$dir/munge/munged.pid" \
  --log-file "$dir/log/munged.log" --seed-file "$dir/munge/seed" -f 2>"$dir/log/munged.err" ||
  skip "munged did not start: $(cat "$dir/log/munged.err")"
# Two free ports for slurmctld and slurmd, picked at random; a clash shows
# as a start failure below.
base=$((20000 + RANDOM % 20000))
cpus=$(nproc)
cat >"$dir/slurm.conf" <<CONF
ClusterName=kerftest
SlurmctldHost=localhost
SlurmctldPort=$base
SlurmdPort=$((base + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/slurmd-%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd-%n.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SchedulerParameters=sched_min_interval=0,batch_sched_delay=0
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
KillWait=2
NodeName=localhost CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -f "$SLURM_CONF" 2>"$dir/log/slurmctld.err" || skip "slurmctld did not start: $(tail -3 "$dir/log/slurmctld.err")"
slurmd -f "$SLURM_CONF" -N localhost 2>"$dir/log/slurmd.err" || skip "slurmd did not start: $(tail -3 "$dir/log/slurmd.err")"
for _ in $(seq 100); do
  state=$(sinfo -h -N -o %t 2>/dev/null | head -1)
  [[ $state == idle* || $state == mix* ]] && { echo "SLURM_CONF=$SLURM_CONF"; exit 0; }
  sleep 0.1
done
skip "the node did not come up (state '${state:-none}'): $(tail -3 "$dir/log/slurmd.log" 2>/dev/null)"
