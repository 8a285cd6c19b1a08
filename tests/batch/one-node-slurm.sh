#!/usr/bin/env bash
# one-node-slurm.sh start DIR | stop DIR: a Slurm cluster of this machine alone, for the batch
# tests: munged, slurmctld and slurmd from Debian's munge and slurm-wlm, every file (key,
# configuration, state, logs, sockets) under DIR, on ports of its own, so it neither needs nor
# touches a system-wide Slurm. `start` prints the SLURM_CONF to export; `stop` ends every daemon
# it started. Needs root (slurmd runs jobs as their users).
set -eu
mode=${1:?usage: one-node-slurm.sh start|stop DIR}
dir=$(realpath -m "${2:?usage: one-node-slurm.sh start|stop DIR}")

stop() {
  if [ -f "$dir/slurm.conf" ]; then
    SLURM_CONF="$dir/slurm.conf" scontrol shutdown >/dev/null 2>&1 || true
  fi
  for pidfile in slurmd.pid slurmctld.pid munged.pid; do
    [ -f "$dir/run/$pidfile" ] || continue
    pid=$(cat "$dir/run/$pidfile")
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
}

if [ "$mode" = stop ]; then stop; exit 0; fi
[ "$mode" = start ] || { echo "usage: one-node-slurm.sh start|stop DIR" >&2; exit 2; }
for program in munged mungekey slurmctld slurmd sbatch scontrol sinfo; do
  command -v "$program" >/dev/null || { echo "one-node-slurm: $program is not installed (apt-get install slurm-wlm munge)" >&2; exit 3; }
done
[ "$(id -u)" = 0 ] || { echo "one-node-slurm: needs root" >&2; exit 3; }

mkdir -p "$dir/run" "$dir/log" "$dir/state" "$dir/spool"
chmod 700 "$dir"
mungekey -c -f -k "$dir/munge.key" >/dev/null
chmod 600 "$dir/munge.key"
munged --force --key-file="$dir/munge.key" --socket="$dir/run/munge.sock" \
  --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$dir/run/munge.seed"

node=$(hostname -s)
memory=$(awk '/MemTotal/ { print int($2 / 1024 * 0.8) }' /proc/meminfo)
# Ports of our own, from the process id, so a second cluster or a system Slurm keeps its own.
port=$((20000 + ($$ % 2000) * 2))
cat >"$dir/slurm.conf" <<CONF
ClusterName=lacrima-test
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/run/munge.sock
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
NodeName=$node CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=lacrima Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"
slurmctld -i
slurmd
for _ in $(seq 100); do
  if sinfo -h -o %T 2>/dev/null | grep -q idle; then echo "$SLURM_CONF"; exit 0; fi
  sleep 0.2
done
echo "one-node-slurm: the node did not become idle; see $dir/log" >&2
stop
exit 1
