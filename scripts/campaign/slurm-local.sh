#!/usr/bin/env bash
# A one-node Slurm cluster for trying the job-array script (docs/scale.md)
# on a workstation or in CI: munge, slurmctld and slurmd on this host, all
# state under DIR, configured by DIR/slurm.conf (export SLURM_CONF to use
# it). Needs root (slurmd runs jobs as their users) and Debian's slurm-wlm
# and munge packages.
#
#   scripts/campaign/slurm-local.sh start DIR   # prints: export SLURM_CONF=DIR/slurm.conf
#   scripts/campaign/slurm-local.sh stop DIR
set -euo pipefail
action=${1:-} dir=${2:-}
if [ -z "$action" ] || [ -z "$dir" ]; then sed -n '8,9p' "$0" >&2; exit 2; fi
mkdir -p "$dir" && dir=$(cd "$dir" && pwd)
export SLURM_CONF=$dir/slurm.conf

stop() {
  for pid in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munged.pid"; do
    [ -f "$pid" ] && kill "$(cat "$pid")" 2> /dev/null || true
  done
  sleep 1
}

case $action in
  stop) stop; exit 0 ;;
  start) ;;
  *) sed -n '8,9p' "$0" >&2; exit 2 ;;
esac
[ "$(id -u)" -eq 0 ] || { echo "slurm-local.sh: needs root (slurmd)" >&2; exit 2; }
for tool in munged slurmctld slurmd sbatch; do
  command -v $tool > /dev/null || { echo "slurm-local.sh: $tool missing (apt-get install slurm-wlm munge)" >&2; exit 2; }
done
mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
host=$(hostname -s)
cpus=$(nproc)
memory=$(awk '/MemTotal/ { print int($2 / 1024 / 2) }' /proc/meminfo)
cat > "$SLURM_CONF" <<CONF
ClusterName=dartcheck
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=campaign Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# munge's own socket and key, so a system munged (if any) is left alone.
cp /etc/munge/munge.key "$dir/munge/munge.key" 2> /dev/null || dd if=/dev/urandom of="$dir/munge/munge.key" bs=1 count=1024 2> /dev/null
chmod 600 "$dir/munge/munge.key"
socket=$dir/munge/munge.socket
munged --force --key-file="$dir/munge/munge.key" --socket="$socket" --pid-file="$dir/munged.pid" \
  --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed"
echo "AuthInfo=socket=$socket" >> "$SLURM_CONF"
slurmctld -i
slurmd
# Ready when the node is idle (at most 30 s).
for _ in $(seq 60); do
  if sinfo -h -o %t 2> /dev/null | grep -q idle; then echo "export SLURM_CONF=$SLURM_CONF"; exit 0; fi
  sleep 0.5
done
echo "slurm-local.sh: the node did not come up; logs in $dir" >&2
tail -5 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
stop
exit 1
