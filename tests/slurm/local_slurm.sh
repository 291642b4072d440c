#!/usr/bin/env bash
# A single-node Slurm on localhost for the slurm tests, all of its state in DIR:
#   local_slurm.sh start DIR   munged, slurmctld and slurmd in foreground mode (-D) in the
#                              background; waits (at most 30 s) until the node is idle; prints
#                              the SLURM_CONF to export.
#   local_slurm.sh stop DIR    stops the three daemons by the PIDs recorded in DIR (TERM, then
#                              KILL after 10 s); touches no other process and no system service.
# Settings that work without cgroups: proctrack/linuxproc, task/none, no accounting.
set -euo pipefail
action=${1:-}
dir=${2:-}
if [ -z "$action" ] || [ -z "$dir" ]; then
  echo "usage: local_slurm.sh start|stop DIR" >&2
  exit 2
fi
dir=$(mkdir -p "$dir" && cd "$dir" && pwd)

stop_pid() {  # stop_pid NAME: TERM the PID recorded in DIR/NAME.pid, KILL it after 10 s
  local file=$dir/$1.pid pid
  [ -f "$file" ] || return 0
  pid=$(cat "$file")
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null || true
  fi
  rm -f "$file"
}

if [ "$action" = stop ]; then
  stop_pid slurmd
  stop_pid slurmctld
  stop_pid munged
  exit 0
fi
[ "$action" = start ] || { echo "local_slurm.sh: unknown action '$action'; expected start or stop" >&2; exit 2; }

for tool in munged slurmctld slurmd sbatch squeue scontrol; do
  command -v "$tool" >/dev/null || { echo "local_slurm.sh: $tool not found (packages slurmctld slurmd slurm-client munge)" >&2; exit 3; }
done
mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/log"
# munged wants its socket's folder, and every folder above it, open to all (execute).
chmod 0755 "$dir" "$dir/munge"
# munged refuses a key that others can read; 1 KiB of random bytes, as mungekey makes.
head -c 1024 /dev/urandom > "$dir/munge/munge.key"
chmod 0600 "$dir/munge/munge.key"
socket=$dir/munge/munge.socket
cpus=$(nproc)
cat > "$dir/slurm.conf" <<CONF
ClusterName=onelighttest
SlurmctldHost=localhost
SlurmUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pidfile
SlurmdPidFile=$dir/slurmd.pidfile
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
ReturnToService=2
MinJobAge=600
MaxArraySize=10001
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

munged --socket="$socket" --key-file="$dir/munge/munge.key" --pid-file="$dir/munge/munged.pidfile" \
  --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munge.seed" --foreground \
  > "$dir/log/munged.out" 2>&1 &
echo $! > "$dir/munged.pid"
for _ in $(seq 100); do [ -S "$socket" ] && break; sleep 0.1; done
[ -S "$socket" ] || { echo "local_slurm.sh: munged did not start: $(tail -n 1 "$dir/log/munged.out" 2>/dev/null)" >&2; exit 1; }

slurmctld -D -f "$dir/slurm.conf" > "$dir/log/slurmctld.out" 2>&1 &
echo $! > "$dir/slurmctld.pid"
slurmd -D -f "$dir/slurm.conf" > "$dir/log/slurmd.out" 2>&1 &
echo $! > "$dir/slurmd.pid"

for _ in $(seq 300); do
  state=$(timeout 5 sinfo -h -n localhost -o %T 2>/dev/null || true)
  [ "$state" = idle ] && { echo "$dir/slurm.conf"; exit 0; }
  sleep 0.1
done
echo "local_slurm.sh: the node is not idle after 30 s (state '${state:-none}'); see $dir/log/" >&2
exit 1
