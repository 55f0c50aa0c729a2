#!/usr/bin/env bash
# `sled sweep --slurm` against a real Slurm: starts the one-node cluster of
# scripts/slurm_cluster.sh, submits a sweep of a small scene (8 runs, one failing numerically)
# as a job array and waits for it, runs the same sweep locally, and compares the two: the same
# statuses, criteria and peaks in sweep.csv (all but the wall times) and byte-identical runs.
# Prints the Slurm path's overhead per run against the local sweep. Stops the cluster after.
#
#   scripts/slurm_sweep_test.sh [BUILD]   BUILD default build (the sled program in
#                                         BUILD/compiler/driver/sled)
#
# Exit 0 passed, 1 failed; 0 with "skipped" when Slurm or munge is not installed or not root.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sled="$(cd "${root}" && realpath "${1:-build}")/compiler/driver/sled"
[[ -x "${sled}" ]] || { echo "slurm_sweep_test: no ${sled}; build first" >&2; exit 1; }
if [[ $(id -u) -ne 0 ]] || ! command -v sbatch >/dev/null || ! [[ -x /usr/sbin/munged ]]; then
  echo "slurm_sweep_test: skipped (needs root and the Debian packages slurm-wlm and munge)"
  exit 0
fi

work="$(mktemp -d /tmp/sled-slurm-test.XXXXXX)"
chmod 755 "${work}"  # munged runs as munge and reaches its files inside
cluster="${work}/cluster"
cleanup() {
  "${root}/scripts/slurm_cluster.sh" stop "${cluster}" >/dev/null 2>&1 || true
  rm -rf "${work}"
}
trap cleanup EXIT

"${root}/scripts/slurm_cluster.sh" start "${cluster}"
export SLURM_CONF="${cluster}/slurm.conf"

# A ball dropped on a floor of varied stiffness; 1e12 N/m is too stiff for the minimum step and
# fails numerically (exit 3, recorded in the table).
cat >"${work}/floor.sled" <<'EOF'
scenario "floor" {
  param stiffness = 1e5 N/m
  time { end = 100 ms  output_every = 1 ms }
  integrator dopri5 { tolerance = 1e-6  min_step = 0.1 ms }
  plane floor on ground { corners = (-1, -1, 0) m, (1, -1, 0) m, (-1, 1, 0) m }
  body ball {
    segment sphere {
      mass = 1 kg
      inertia = (0.001, 0.001, 0.001) kg*m^2
      ellipsoid { semi_axes = (50, 50, 50) mm }
    }
  }
  contact ball.sphere with floor { force = stiffness }
  initial ball { position = (0, 0, 70) mm }
  output { position ball.sphere }
}
EOF
design=(--vary "stiffness=1e4,2e4,5e4,1e5,2e5,5e5,1e6,1e12 N/m")
runs=8

status=0
start=$(date +%s.%N)
"${sled}" sweep "${work}/floor.sled" "${design[@]}" -o "${work}/cluster-sweep" --slurm --wait \
  --tasks 4 --time 5 || status=$?
slurm_seconds=$(awk -v a="$(date +%s.%N)" -v b="${start}" 'BEGIN { print a - b }')
if [[ ${status} -ne 3 ]]; then
  echo "slurm_sweep_test: FAILED: the Slurm sweep exited ${status}, not 3 (one run fails)" >&2
  tail -n 5 "${work}"/cluster-sweep/slurm/*.log >&2 || true
  exit 1
fi

start=$(date +%s.%N)
status=0
"${sled}" sweep "${work}/floor.sled" "${design[@]}" -o "${work}/local-sweep" --jobs 2 \
  2>/dev/null || status=$?
local_seconds=$(awk -v a="$(date +%s.%N)" -v b="${start}" 'BEGIN { print a - b }')
[[ ${status} -eq 3 ]] || { echo "slurm_sweep_test: FAILED: the local sweep exited ${status}" >&2; exit 1; }

# The tables without the wall-time column (the fields before it hold no commas), then every
# run's files byte for byte.
wall="$(head -n 1 "${work}/local-sweep/sweep.csv" | tr ',' '\n' | grep -n '^wall_seconds$' | cut -d: -f1)"
strip() { cut -d, -f"1-$((wall - 1)),$((wall + 1))-" "$1"; }
if ! diff <(strip "${work}/cluster-sweep/sweep.csv") <(strip "${work}/local-sweep/sweep.csv"); then
  echo "slurm_sweep_test: FAILED: the tables differ (above)" >&2
  exit 1
fi
for run in "${work}"/local-sweep/runs/*; do
  name="$(basename "${run}")"
  for file in timeseries.csv timeseries_filtered.csv; do
    [[ -f "${run}/${file}" ]] || continue
    cmp -s "${run}/${file}" "${work}/cluster-sweep/runs/${name}/${file}" ||
      { echo "slurm_sweep_test: FAILED: runs/${name}/${file} differs" >&2; exit 1; }
  done
done
grep -q ",failed,3," "${work}/cluster-sweep/sweep.csv" ||
  { echo "slurm_sweep_test: FAILED: the failing run is not recorded" >&2; exit 1; }

printf 'slurm_sweep_test: passed: %d runs in %.1f s through Slurm (4 array tasks and the collecting job), %.1f s locally with 2 jobs: %.2f s of overhead per run\n' \
  "${runs}" "${slurm_seconds}" "${local_seconds}" \
  "$(awk -v s="${slurm_seconds}" -v l="${local_seconds}" -v n="${runs}" 'BEGIN { print (s - l) / n }')"
echo "1 passed, 0 failed"
