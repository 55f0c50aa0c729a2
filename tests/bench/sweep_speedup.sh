#!/usr/bin/env bash
# The sweep's speed-up on every core, and the Slurm path's overhead per run (docs/sweeps.md).
#
#   tests/bench/sweep_speedup.sh [BUILD] [REPEATS]
#
# 1. A sweep of 16 flagship runs (examples/frontal_sled.sled, speed 40..70 km/h in 2 km/h steps)
#    with --jobs 1 and with --jobs 2, each REPEATS times (default 3), alternating; prints each
#    wall time, the medians and their ratio. Every run's timeseries.csv of the two sweeps is
#    compared byte for byte.
# 2. With root and the slurm-wlm and munge packages: the same sweep through a one-node cluster
#    (scripts/slurm_cluster.sh), one array task per run, against the local sweep with as many
#    jobs as the node has cores; prints the overhead per run.
# Measure on a quiet machine (`uptime`): other work on the cores shows up as a lower speed-up.
# SWEEP_BENCH_SLURM=0 leaves out part 2. SWEEP_BENCH_DIR=/dev/shm writes the sweeps there (default
# /tmp): on a RAM file system the runs' outputs cost no disk time, which leaves the processes'
# own speed-up (docs/sweeps.md).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
sled="$(cd "${root}" && realpath "${1:-build}")/compiler/driver/sled"
repeats="${2:-3}"
work="$(mktemp -d "${SWEEP_BENCH_DIR:-/tmp}/sled-sweep-bench.XXXXXX")"
chmod 755 "${work}"
trap 'rm -rf "${work}"' EXIT
design=(--vary "speed=40..70 km/h step 2")

now() { date +%s.%N; }
elapsed() { awk -v a="$(now)" -v b="$1" 'BEGIN { printf "%.3f", a - b }'; }
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "sweep_speedup: load before: $(cut -d' ' -f1-3 /proc/loadavg)"
one=()
two=()
for repeat in $(seq 1 "${repeats}"); do
  for jobs in 1 2; do
    rm -rf "${work}/j${jobs}"
    start="$(now)"
    "${sled}" sweep "${root}/examples/frontal_sled.sled" "${design[@]}" -o "${work}/j${jobs}" \
      --jobs "${jobs}" 2>/dev/null
    seconds="$(elapsed "${start}")"
    echo "sweep_speedup: 16 flagship runs, --jobs ${jobs}: ${seconds} s"
    if [[ ${jobs} -eq 1 ]]; then one+=("${seconds}"); else two+=("${seconds}"); fi
  done
  for run in "${work}"/j1/runs/*; do
    cmp -s "${run}/timeseries.csv" "${work}/j2/runs/$(basename "${run}")/timeseries.csv" ||
      { echo "sweep_speedup: runs differ between --jobs 1 and 2: ${run}" >&2; exit 1; }
  done
done
m1="$(median "${one[@]}")"
m2="$(median "${two[@]}")"
echo "sweep_speedup: load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "sweep_speedup: median ${m1} s with 1 job, ${m2} s with 2 jobs: speed-up $(awk -v a="${m1}" -v b="${m2}" 'BEGIN { printf "%.2f", a / b }')x (runs byte-identical)"

if [[ "${SWEEP_BENCH_SLURM:-1}" == 0 ]]; then exit 0; fi
if [[ $(id -u) -ne 0 ]] || ! command -v sbatch >/dev/null || ! [[ -x /usr/sbin/munged ]]; then
  echo "sweep_speedup: the Slurm part needs root and the slurm-wlm and munge packages; skipped"
  exit 0
fi
cluster="${work}/cluster"
"${root}/scripts/slurm_cluster.sh" start "${cluster}" >/dev/null
trap '"${root}/scripts/slurm_cluster.sh" stop "${cluster}" >/dev/null 2>&1; rm -rf "${work}"' EXIT
export SLURM_CONF="${cluster}/slurm.conf"
cores="$(nproc)"
slurm=()
local_times=()
for repeat in $(seq 1 "${repeats}"); do
  rm -rf "${work}/slurm" "${work}/local"
  start="$(now)"
  "${sled}" sweep "${root}/examples/frontal_sled.sled" "${design[@]}" -o "${work}/slurm" --slurm \
    --wait 2>/dev/null
  slurm+=("$(elapsed "${start}")")
  start="$(now)"
  "${sled}" sweep "${root}/examples/frontal_sled.sled" "${design[@]}" -o "${work}/local" \
    --jobs "${cores}" 2>/dev/null
  local_times+=("$(elapsed "${start}")")
  echo "sweep_speedup: 16 flagship runs through Slurm (16 array tasks, ${cores} at a time): ${slurm[-1]} s; locally with ${cores} jobs: ${local_times[-1]} s"
done
ms="$(median "${slurm[@]}")"
ml="$(median "${local_times[@]}")"
echo "sweep_speedup: Slurm overhead: median ${ms} s against ${ml} s locally: $(awk -v s="${ms}" -v l="${ml}" 'BEGIN { printf "%.2f", (s - l) / 16 }') s per run"
