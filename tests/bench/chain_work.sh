#!/usr/bin/env bash
# Issue 16, item 3: the 60-link chain (tests/bench/chain_60.sled) with each method at 1e-5 and
# 1e-6: instructions inside sled::runtime::Run counted by callgrind (repeatable on a busy
# machine), steps and evaluations from sled run, and each run's error from sled study (against
# its dopri5 reference at a hundredth of the tightest tolerance).
#
#   tests/bench/chain_work.sh [build/compiler/driver/sled]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
sled="${1:-${root}/build/compiler/driver/sled}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$sled" study "${root}/tests/bench/chain_60.sled" --tolerances 1e-5,1e-6 --jobs 1 \
  -o "$work/study" >"$work/study.txt" 2>/dev/null || true
printf '%-12s %6s %14s %7s %7s %10s\n' method tol instructions steps evals error
for method in dopri5 rosenbrock exponential auto; do
  for tolerance in 1e-5 1e-6; do
    scene="$work/${method}_${tolerance}.sled"
    sed "s/integrator auto { tolerance = 1e-6 }/integrator ${method} { tolerance = ${tolerance} }/" \
      "${root}/tests/bench/chain_60.sled" >"$scene"
    valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
      "--toggle-collect=sled::runtime::Run(*" "$sled" run "$scene" -o "$work/run" \
      >/dev/null 2>"$work/run.log"
    instructions=$(awk '/^summary:/ { print $2 }' "$work/cg.out")
    steps=$(sed -n 's/.*(\([0-9]*\) steps.*/\1/p' "$work/run.log")
    evals=$(sed -n 's/.*rejected, \([0-9]*\) evaluations.*/\1/p' "$work/run.log")
    error=$(awk -v m="$method" -v t="$tolerance" '$1 == m && $2 + 0 == t + 0 { print $7 }' \
      "$work/study.txt")
    printf '%-12s %6s %14s %7s %7s %10s\n' "$method" "$tolerance" "$instructions" "$steps" \
      "$evals" "${error:--}"
  done
done
