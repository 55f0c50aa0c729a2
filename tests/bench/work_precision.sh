#!/usr/bin/env bash
# Error against cost for each of sled's methods and CVODE, case by case, at equal accuracy.
#
#   tests/bench/work_precision.sh [CASE...]     (default: the stiff cases of issue 16)
#
#   SLED_WP_TOLERANCES=1e-2,1e-3,...   the tolerance ladder (default 1e-2 to 1e-7)
#   SLED_WP_METHODS=auto,exponential,dopri5,cvode   the methods (default: all five and cvode)
#
# Runs the CVODE peer (tests/bench/cvode_peer.cpp: every method on the suite case, errors as
# `sled study` measures them, against a dopri5 reference at 1e-10) and prints, per case, each
# method's run at each tolerance (error, steps, evaluations, wall time), then the cost each method
# needs to reach each error level (log-log interpolation between the ladder's runs; `-` when no
# run of the ladder reaches it), in derivative evaluations (the machine-independent cost) and in
# wall time, with the machine's load beside it. Instruction counts of single runs:
# `perf stat -e instructions build/compiler/driver/sled run SCENE`.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
peer="${SLED_CVODE_PEER:-${root}/build/tests/bench/sled_bench_cvode_peer}"
tolerances="${SLED_WP_TOLERANCES:-1e-2,1e-3,1e-4,1e-5,1e-6,1e-7}"
methods="${SLED_WP_METHODS:-auto,exponential,dopri5,rosenbrock,cvs,cvode}"
[[ -x "${peer}" ]] || { echo "work_precision.sh: no CVODE peer at ${peer} (SLED_BENCH=ON)" >&2; exit 1; }
cases=("$@")
if [[ ${#cases[@]} -eq 0 ]]; then
  cases=(viscous_damping stiff_decay joint_stops tension_tether contact_1e8 contact_1e9
         contact_1e10 contact_1e11 airbag_gas)
fi

csv="$(mktemp)"
trap 'rm -f "${csv}"' EXIT
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
(cd "${root}" && "${peer}" "--tolerances=${tolerances}" "--methods=${methods}" "${cases[@]}") \
  >"${csv}" 2>/dev/null
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

python3 - "${csv}" "${load_before}" "${load_after}" <<'PY'
import csv, math, sys
from collections import defaultdict

path, load_before, load_after = sys.argv[1:4]
LEVELS = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6]
runs = defaultdict(lambda: defaultdict(list))
order = []
for row in csv.DictReader(open(path)):
    case, method = row["case"], row["method"]
    if case not in order:
        order.append(case)
    runs[case][method].append(row)


def cost_to(rows, level, key):
    """The cost at which the error first reaches `level`, log-log between ladder neighbours."""
    points = sorted((float(r[key]), float(r["error_all"])) for r in rows
                    if r["failed"] == "0" and float(r["error_all"]) >= 0)
    best = None
    for i, (cost, error) in enumerate(points):
        if error <= level:
            if i > 0 and points[i - 1][1] > level and error > 0:
                c0, e0 = points[i - 1]
                f = math.log(e0 / level) / math.log(e0 / error)
                cost = math.exp(math.log(c0) + f * (math.log(cost) - math.log(c0)))
            best = cost if best is None else min(best, cost)
            break
    return best


print(f"load (1, 5, 15 min) before {load_before}, after {load_after}")
for case in order:
    print(f"\n== {case}")
    print(f"{'method':<12} {'tol':>7} {'error':>9} {'steps':>7} {'evals':>8} {'wall ms':>9}")
    for method, rows in runs[case].items():
        for r in rows:
            flag = "  failed" if r["failed"] != "0" else ""
            print(f"{method:<12} {float(r['tolerance']):>7.0e} {float(r['error_all']):>9.2e} "
                  f"{r['steps']:>7} {r['evaluations']:>8} {1e3 * float(r['wall_seconds']):>9.3f}"
                  f"{flag}")
    for key, label, fmt in (("evaluations", "evaluations", "{:.0f}"),
                            ("wall_seconds", "wall ms", "{:.3g}")):
        print(f"-- {label} to reach an error level")
        print(f"{'method':<12}" + "".join(f"{l:>10.0e}" for l in LEVELS))
        for method, rows in runs[case].items():
            cells = []
            for level in LEVELS:
                c = cost_to(rows, level, key)
                if c is not None and key == "wall_seconds":
                    c *= 1e3
                cells.append("-" if c is None else fmt.format(c))
            print(f"{method:<12}" + "".join(f"{c:>10}" for c in cells))
PY
