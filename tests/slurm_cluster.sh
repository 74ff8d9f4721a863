#!/usr/bin/env bash
# A one-node SLURM cluster on this machine, for tests of the batch script:
# Debian's munged, slurmctld and slurmd as root, with a slurm.conf of their
# own in DIR (docs/architecture.md, "Debian's SLURM"). Needs root and the
# packages slurmctld, slurmd, slurm-client and munge (scripts/install-deps.sh).
#
#   slurm_cluster.sh start DIR   # prints 'export SLURM_CONF=...' on success
#   slurm_cluster.sh stop DIR    # ends the daemons started by 'start DIR'
#
# 'start' exits 77 with a message when the daemons cannot run here (no root,
# no packages, a port taken) so that a test can report the skip.
set -uo pipefail
action=${1:?usage: slurm_cluster.sh start|stop DIR} dir=${2:?usage: slurm_cluster.sh start|stop DIR}
skip() { echo "slurm_cluster: cannot start a SLURM cluster here: $*" >&2; exit 77; }

stop() {
  for d in slurmd slurmctld munged; do
    [[ -f $dir/$d.pid ]] || continue
    pid=$(cat "$dir/$d.pid")
    kill "$pid" 2>/dev/null
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
    rm -f "$dir/$d.pid"
  done
}

if [[ $action == stop ]]; then
  stop
  exit 0
fi
[[ $action == start ]] || { echo "slurm_cluster: unknown action '$action' (start or stop)" >&2; exit 2; }
[[ $(id -u) -eq 0 ]] || skip "the daemons need root (running as $(id -un))"
for exe in munged slurmctld slurmd sbatch srun scontrol; do
  command -v "$exe" > /dev/null || skip "'$exe' not found (packages slurmctld slurmd slurm-client munge)"
done

dir=$(mkdir -p "$dir" && cd "$dir" && pwd)
mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
chown munge: "$dir/munge"
chmod 0755 "$dir/munge"
# munged: its own socket, so that a munged of the machine is left alone. The
# key is Debian's (made when the package was installed), or a new one.
key=/etc/munge/munge.key
if [[ ! -s $key ]]; then
  key=$dir/munge/munge.key
  dd if=/dev/urandom of="$key" bs=1 count=1024 status=none
  chown munge: "$key"; chmod 0400 "$key"
fi
socket=$dir/munge/munge.socket
runuser -u munge -- munged --key-file="$key" --socket="$socket" --pid-file="$dir/munge/munged.pid" \
  --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed" --force \
  || skip "munged did not start (log: $dir/munge/munged.log)"
cp "$dir/munge/munged.pid" "$dir/munged.pid"

node=$(hostname -s)
cpus=$(nproc)
# Ports away from SLURM's defaults (6817/6818), so a site's daemons are not hit.
ctld_port=${FE2DEM_SLURMCTLD_PORT:-16817} d_port=${FE2DEM_SLURMD_PORT:-16818}
cat > "$dir/slurm.conf" <<EOF
ClusterName=fe2demtest
SlurmctldHost=$node
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket,cred_expire=5
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=2
MpiDefault=none
ReturnToService=2
JobRequeue=1
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
KillWait=10
NodeName=$node CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=FORCE:4
EOF
export SLURM_CONF=$dir/slurm.conf
slurmctld -i -f "$SLURM_CONF" || { stop; skip "slurmctld did not start (log: $dir/slurmctld.log)"; }
slurmd -f "$SLURM_CONF" || { stop; skip "slurmd did not start (log: $dir/slurmd.log)"; }
for _ in $(seq 100); do
  sinfo -h -o %T 2>/dev/null | grep -qx idle && { echo "export SLURM_CONF=$SLURM_CONF"; exit 0; }
  sleep 0.2
done
stop
skip "the node did not become idle within 20 s ($(sinfo -h -o '%T %E' 2>&1); logs in $dir)"
