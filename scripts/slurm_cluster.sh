#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for testing `sled sweep --slurm` against a real
# scheduler: munged, slurmctld and slurmd (Debian's `munge` and `slurm-wlm`), with a
# configuration, state and logs in a folder of their own. Needs root (the daemons run as root
# and munge).
#
#   scripts/slurm_cluster.sh start [DIR]   start it (DIR default /tmp/sled-slurm); prints the
#                                          SLURM_CONF to export for sbatch and squeue
#   scripts/slurm_cluster.sh stop [DIR]    stop the daemons this script started
#   scripts/slurm_cluster.sh status [DIR]  sinfo of the cluster
#
# The node offers every core of the machine (CR_Core: one array task per core at a time) in a
# partition `debug`, without accounting; jobs run as the user who submits them.
set -euo pipefail

action="${1:-}"
dir="${2:-/tmp/sled-slurm}"
conf="${dir}/slurm.conf"

die() {
  echo "slurm_cluster: $*" >&2
  exit 1
}

start() {
  [[ $(id -u) -eq 0 ]] || die "needs root (the daemons run as root and munge)"
  for program in munged slurmctld slurmd sbatch squeue sinfo; do
    command -v "${program}" >/dev/null 2>&1 || [[ -x "/usr/sbin/${program}" ]] ||
      die "no ${program}: install the Debian packages slurm-wlm and munge"
  done
  mkdir -p "${dir}/state" "${dir}/spool" "${dir}/munge"
  local host cpus memory
  host="$(hostname -s)"
  cpus="$(nproc)"
  memory="$(awk '/MemTotal/ { print int($2 / 1024 / 2) }' /proc/meminfo)"

  # munge: its own key, socket and pid under DIR, so that a system munged is left alone.
  if [[ ! -f "${dir}/munge/munge.key" ]]; then
    dd if=/dev/urandom of="${dir}/munge/munge.key" bs=1024 count=1 status=none
  fi
  chown -R munge:munge "${dir}/munge"
  chmod 700 "${dir}/munge"
  chmod 400 "${dir}/munge/munge.key"
  local socket="${dir}/munge/munge.socket"
  if ! [[ -S "${socket}" ]] || ! MUNGE_SOCKET="${socket}" munge -n -S "${socket}" >/dev/null 2>&1; then
    runuser -u munge -- /usr/sbin/munged --key-file="${dir}/munge/munge.key" \
      --socket="${socket}" --pid-file="${dir}/munge/munged.pid" \
      --log-file="${dir}/munge/munged.log" --seed-file="${dir}/munge/munged.seed" --force
  fi

  cat >"${conf}" <<EOF
# Written by scripts/slurm_cluster.sh: a one-node cluster for sled's tests.
ClusterName=sled-test
SlurmctldHost=${host}(127.0.0.1)
SlurmctldPort=6917
SlurmdPort=6918
AuthType=auth/munge
AuthInfo=socket=${socket}
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=${dir}/state
SlurmdSpoolDir=${dir}/spool
SlurmctldPidFile=${dir}/slurmctld.pid
SlurmdPidFile=${dir}/slurmd.pid
SlurmctldLogFile=${dir}/slurmctld.log
SlurmdLogFile=${dir}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MaxArraySize=1001
NodeName=${host} NodeAddr=127.0.0.1 CPUs=${cpus} RealMemory=${memory} State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="${conf}"
  if ! [[ -f "${dir}/slurmctld.pid" ]] || ! kill -0 "$(cat "${dir}/slurmctld.pid")" 2>/dev/null; then
    /usr/sbin/slurmctld -f "${conf}" -i
  fi
  if ! [[ -f "${dir}/slurmd.pid" ]] || ! kill -0 "$(cat "${dir}/slurmd.pid")" 2>/dev/null; then
    /usr/sbin/slurmd -f "${conf}"
  fi
  # Until the node is idle (the controller has heard from slurmd).
  local tries=0
  until sinfo --noheader --format=%T 2>/dev/null | grep -q idle; do
    tries=$((tries + 1))
    if [[ ${tries} -gt 60 ]]; then
      sinfo >&2 || true
      tail -n 20 "${dir}/slurmctld.log" "${dir}/slurmd.log" >&2 || true
      die "the node did not come up within 30 s (logs above)"
    fi
    sleep 0.5
  done
  echo "slurm_cluster: up; export SLURM_CONF=${conf}"
}

stop() {
  for pidfile in "${dir}/slurmd.pid" "${dir}/slurmctld.pid" "${dir}/munge/munged.pid"; do
    if [[ -f "${pidfile}" ]]; then
      local pid
      pid="$(cat "${pidfile}")"
      kill "${pid}" 2>/dev/null || true
      for _ in $(seq 1 50); do
        kill -0 "${pid}" 2>/dev/null || break
        sleep 0.1
      done
      rm -f "${pidfile}"
    fi
  done
  echo "slurm_cluster: stopped"
}

case "${action}" in
  start) start ;;
  stop) stop ;;
  status) SLURM_CONF="${conf}" sinfo ;;
  *) die "usage: $0 start|stop|status [DIR]" ;;
esac
