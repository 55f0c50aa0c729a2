#!/usr/bin/env bash
# Instructions per dynamics evaluation, sled's Forward against MuJoCo's mj_forward, counted by
# callgrind in the dynamics benchmark: repeatable on a busy machine, where the benchmark's times
# are not. Each count is the instructions inside the function divided by its calls.
#
#   tests/bench/instruction_counts.sh [build/tests/bench/sled_bench_dynamics_bench]
set -euo pipefail
bench=${1:-build/tests/bench/sled_bench_dynamics_bench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Instructions per call of the function matching $2 in the benchmark $1.
count() {
  local filter=$1 function=$2 out="$work/callgrind.out"
  valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect="$function" \
    "$bench" --benchmark_filter="$filter" --benchmark_min_time=0.02 >/dev/null 2>&1
  # Total collected instructions over the calls made to the function. Callgrind names a
  # function in full once ("fn=(id) name" or "cfn=(id) name") and by its id after that.
  awk -v pattern="$function" '
    /^summary:/ { total = $2 }
    /^c?fn=\([0-9]+\) / {
      id = $1; sub(/^c?fn=/, "", id)
      name = $0; sub(/^c?fn=\([0-9]+\) /, "", name)
      # A trailing * matches any suffix, as in --toggle-collect.
      if (pattern ~ /\*$/) match_id[id] = index(name, substr(pattern, 1, length(pattern) - 1)) == 1
      else match_id[id] = name == pattern
    }
    /^cfn=/ { id = $1; sub(/^cfn=/, "", id); inside = match_id[id] }
    /^calls=/ { if (inside) { split($1, parts, "="); calls += parts[2] } }
    END { if (calls > 0) printf "%.0f", total / calls; else printf "n/a" }' "$out"
}

printf '%-12s %14s %14s %8s\n' model sled_Ir mujoco_Ir ratio
row() {
  local label=$1 sled_filter=$2 mujoco_filter=${3:-}
  local s m=""
  s=$(count "$sled_filter" 'sled::runtime::Forward(*')
  [[ -n $mujoco_filter ]] && m=$(count "$mujoco_filter" 'mj_forward')
  awk -v l="$label" -v s="$s" -v m="$m" 'BEGIN {
    if (m == "") printf "%-12s %14s %14s %8s\n", l, s, "-", "-"
    else printf "%-12s %14s %14s %8.2f\n", l, s, m, s / m }'
}
row cvs15 'BM_SledForward$' 'BM_MujocoForward$'
for n in 5 10 15 30 45 60; do
  row "chain$n" "BM_SledForwardScaling/$n\$" "BM_MujocoForwardScaling/$n\$"
done
# The four-bar example with and without its loop-closing constraint (sled only).
row fourbar 'BM_SledForwardFourBar$'
row fourbar_open 'BM_SledForwardFourBarOpen$'
