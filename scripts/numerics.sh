#!/usr/bin/env bash
# Measures the numerics suite and rewrites the measured part of docs/numerics.md.
#
#   scripts/numerics.sh [OUT]      (OUT: where the study folders go; default build/numerics)
#
# 1. `sled study` on every case of examples/numerics/suite.txt and on the flagship, over the
#    tolerance ladder $SLED_NUMERICS_TOLERANCES (default 1e-2 to 1e-6);
# 2. `sled run` of the conservative cases with each integrator at 1e-4, 1e-6 and 1e-8, for the
#    energy balance's drift (summary.json, energy_balance.relative_residual) and the free body's
#    angular momentum drift;
# 3. the CVODE peer (tests/bench/cvode_peer.cpp) beside sled's integrators, when it is built;
# 4. from those: the time each method needs to reach each error level, the convergence orders on
#    the smooth cases (least-squares slope of log error against log evaluations) and the energy
#    drift, written between the `numerics:begin` and `numerics:end` markers of docs/numerics.md,
#    with each case's work-precision plot copied to docs/numerics/CASE.svg.
#
# Needs a built sled ($SLED, default build/compiler/driver/sled) and python3 (the tables are
# computed by the Python at the end).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sled="${SLED:-${root}/build/compiler/driver/sled}"
out="${1:-${root}/build/numerics}"
tolerances="${SLED_NUMERICS_TOLERANCES:-1e-2,1e-3,1e-4,1e-5,1e-6}"
suite="${root}/examples/numerics/suite.txt"
conservative=(free_body spin_100 pendulum_chain)
methods=(exponential dopri5 rosenbrock)

[[ -x "${sled}" ]] || { echo "numerics.sh: no sled at ${sled}; build first" >&2; exit 1; }
mkdir -p "${out}"
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"

# A study of one case: NAME FILE [NAME=VALUE;...]
study() {
  local name="$1" file="$2" overrides="$3"
  local args=()
  if [[ -n "${overrides}" ]]; then
    IFS=';' read -ra items <<<"${overrides}"
    for item in "${items[@]}"; do
      item="$(echo "${item}" | sed 's/^ *//; s/ *$//')"
      [[ -n "${item}" ]] && args+=(--set "${item}")
    done
  fi
  echo "numerics.sh: study of ${name}" >&2
  "${sled}" study "${file}" "${args[@]}" --tolerances "${tolerances}" -o "${out}/${name}" \
    >"${out}/${name}/table.txt" 2>"${out}/${name}/log.txt" ||
    echo "numerics.sh: the study of ${name} failed (see ${out}/${name}/log.txt)" >&2
}

while read -r kind name file rest; do
  [[ -z "${kind}" || "${kind}" == \#* ]] && continue
  mkdir -p "${out}/${name}"
  echo "${kind}" >"${out}/${name}/kind"
  study "${name}" "${root}/examples/${file}" "${rest}"
done <"${suite}"
mkdir -p "${out}/flagship"
echo flagship >"${out}/flagship/kind"
study flagship "${root}/examples/frontal_sled.sled" ""

# Energy drift: the scene with its integrator line replaced by each method and tolerance.
mkdir -p "${out}/energy"
for name in "${conservative[@]}"; do
  for method in "${methods[@]}"; do
    for tolerance in 1e-4 1e-6 1e-8; do
      scene="${out}/energy/${name}_${method}_${tolerance}.sled"
      standard="^  integrator exponential { tolerance = 1e-6 }$"
      sed "s/${standard}/  integrator ${method} { tolerance = ${tolerance} }/" \
        "${root}/examples/numerics/${name}.sled" >"${scene}"
      grep -q "integrator ${method} { tolerance = ${tolerance} }" "${scene}" ||
        { echo "numerics.sh: ${name}.sled has no standard integrator line" >&2; exit 1; }
      "${sled}" run "${scene}" -o "${out}/energy/${name}_${method}_${tolerance}" >/dev/null 2>&1 ||
        true
    done
  done
done

# The CVODE peer (tests/bench/cvode_peer.cpp), when it is built (SLED_BENCH=ON with SUNDIALS).
peer="${SLED_CVODE_PEER:-${root}/build/tests/bench/sled_bench_cvode_peer}"
rm -f "${out}/cvode_peer.csv"
if [[ -x "${peer}" ]]; then
  echo "numerics.sh: the CVODE peer" >&2
  "${peer}" >"${out}/cvode_peer.csv.part" && mv "${out}/cvode_peer.csv.part" "${out}/cvode_peer.csv"
else
  echo "numerics.sh: no CVODE peer at ${peer}" \
    "(configure with -DSLED_BENCH=ON and libsundials-dev)" >&2
fi

load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "${out}" "${root}/docs/numerics.md" "${root}/docs/numerics" "${tolerances}" \
  "${load_before}" "${load_after}" "$(git -C "${root}" rev-parse --short HEAD)" <<'PY'
import csv, json, math, os, re, shutil, sys
from datetime import date

out, doc, plots, ladder, load_before, load_after, commit = sys.argv[1:8]
LEVELS = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6]
ORDERS = {"exponential": 3, "dopri5": 5, "rosenbrock": 3}
METHODS = list(ORDERS)
CONSERVATIVE = ["free_body", "spin_100", "pendulum_chain"]


def read_case(name):
    folder = os.path.join(out, name)
    rows = []
    path = os.path.join(folder, "study.csv")
    if os.path.exists(path):
        with open(path) as f:
            for r in csv.DictReader(f):
                rows.append({"method": r["method"], "tol": float(r["tolerance"]),
                             "time": float(r["wall_seconds"]), "steps": int(r["steps"]),
                             "evals": int(r["evaluations"]), "error": float(r["error_all"]),
                             "failed": r["failed"] == "1"})
    floor = None
    table = os.path.join(folder, "table.txt")
    if os.path.exists(table):
        m = re.search(r"differs from it by ([0-9.e+-]+)", open(table).read())
        if m:
            floor = float(m.group(1))
    kind = open(os.path.join(folder, "kind")).read().strip()
    return {"name": name, "kind": kind, "rows": rows, "floor": floor or 0.0,
            "failures": [l for l in open(table).read().splitlines() if "failed at" in l]
            if os.path.exists(table) else []}


def time_to(case, method, level):
    """The fastest completed run of the method with an error at or below the level; None when
    none reached it, 'floor' when the reference cannot resolve the level."""
    if case["floor"] > level:
        return "floor"
    times = [r["time"] for r in case["rows"]
             if r["method"] == method and not r["failed"] and r["error"] <= level]
    return min(times) if times else None


def fmt_time(t):
    if t is None:
        return "not reached"
    if t == "floor":
        return "unresolved"
    return f"{t * 1000:.3g} ms" if t < 1 else f"{t:.3g} s"


def slope(points):
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    sxx = sum((x - mx) ** 2 for x, _ in points)
    return sum((x - mx) * (y - my) for x, y in points) / sxx if sxx > 0 else float("nan")


def order(case, method, work):
    """Minus the least-squares slope of log error against log work, over completed runs whose
    error is at least ten times the reference's own uncertainty."""
    pts = [(math.log10(r[work]), math.log10(r["error"])) for r in case["rows"]
           if r["method"] == method and not r["failed"] and r["error"] > 10 * case["floor"]
           and r["error"] > 0]
    if len(pts) < 3:
        return None, len(pts)
    return -slope(pts), len(pts)


names = sorted(d for d in os.listdir(out) if os.path.exists(os.path.join(out, d, "kind")))
suite_order = []
for line in open(os.path.join(os.path.dirname(doc), "..", "examples", "numerics", "suite.txt")):
    f = line.split()
    if f and not f[0].startswith("#"):
        suite_order.append(f[1])
cases = [read_case(n) for n in suite_order + ["flagship"] if n in names]

L = []
L.append(f"Measured by `scripts/numerics.sh` on {date.today().isoformat()} at commit `{commit}`, "
         f"tolerance ladder {ladder}, on {os.cpu_count()} cores; load average (1, 5, 15 min) "
         f"{load_before} before and {load_after} after (the machine is shared: run times carry "
         "that noise, the errors and step counts do not).")
L.append("")
L.append("### Time to reach each error level")
L.append("")
L.append("The fastest run of each method whose error (*all*, of the channels' ranges) is at or "
         "below the level; *not reached*: no tolerance of the ladder got there; *unresolved*: "
         "below the reference's own uncertainty. The last column is dopri5's time over the "
         "exponential method's (the default), at each level where both got there.")
L.append("")
head = "| case | kind | method | " + " | ".join(f"{l:.0e}" for l in LEVELS) + " |"
L.append(head)
L.append("|" + "---|" * (3 + len(LEVELS)))
targets = []
for c in cases:
    for m in METHODS:
        cells = [fmt_time(time_to(c, m, l)) for l in LEVELS]
        L.append(f"| {c['name']} | {c['kind']} | {m} | " + " | ".join(cells) + " |")
    ratios = []
    for l in LEVELS:
        te, td = time_to(c, "exponential", l), time_to(c, "dopri5", l)
        if isinstance(te, float) and isinstance(td, float):
            ratios.append(f"{td / te:.2g}")
        else:
            ratios.append("-")
    L.append(f"| {c['name']} | | dopri5 / exponential | " + " | ".join(ratios) + " |")
    if c["kind"] in ("stiff", "extreme"):
        met = [l for l in LEVELS if isinstance(time_to(c, "exponential", l), float)
               and isinstance(time_to(c, "dopri5", l), float)
               and time_to(c, "dopri5", l) >= 3 * time_to(c, "exponential", l)]
        resolvable = [l for l in LEVELS if c["floor"] <= l]
        targets.append((c["name"], len(met), len(resolvable)))
L.append("")
L.append("Plots: " + ", ".join(f"[{c['name']}](numerics/{c['name']}.svg)" for c in cases
                               if os.path.exists(os.path.join(out, c["name"], "study.svg"))) + ".")
L.append("")
L.append("Reference uncertainty (the exponential method against the dopri5 reference, both at a "
         "hundredth of the tightest tolerance): " +
         ", ".join(f"{c['name']} {c['floor']:.1e}" for c in cases) + ".")
failures = [(c["name"], f.split()[0], f.split()[1], f[f.index("failed at"):]) for c in cases
            for f in c["failures"]]
L.append("")
if failures:
    L.append("Runs of the ladder that stopped with a failure (method, tolerance, where and why):")
    L.append("")
    for name, method, tol, what in failures:
        L.append(f"- {name}, {method} at {tol}: {what}")
else:
    L.append("No run of the ladder stopped with a failure.")
L.append("")
L.append("### Target: the default integrator at least 3x faster than dopri5 (stiff and extreme)")
L.append("")
L.append("| case | levels where exponential is 3x faster than dopri5 "
         "| levels the reference resolves |")
L.append("|---|---|---|")
for name, met, resolvable in targets:
    L.append(f"| {name} | {met} | {resolvable} |")
L.append("")
L.append("### Convergence orders on the smooth cases")
L.append("")
L.append("Minus the least-squares slope of log10 error against log10 accepted steps (and against "
         "log10 derivative evaluations), over the completed runs of the ladder whose error is at "
         "least ten times the reference's uncertainty; the target is to be within 0.5 of the "
         "theoretical order.")
L.append("")
L.append("| case | method | theoretical | observed (steps) | observed (evaluations) | runs "
         "| within 0.5 |")
L.append("|---|---|---|---|---|---|---|")
for c in cases:
    if c["kind"] != "smooth":
        continue
    for m in METHODS:
        p_steps, n = order(c, m, "steps")
        p_evals, _ = order(c, m, "evals")
        if p_steps is None:
            L.append(f"| {c['name']} | {m} | {ORDERS[m]} | - | - | {n} | too few runs |")
            continue
        ok = "yes" if abs(p_steps - ORDERS[m]) <= 0.5 else "no"
        L.append(f"| {c['name']} | {m} | {ORDERS[m]} | {p_steps:.2f} | {p_evals:.2f} | {n} "
                 f"| {ok} |")
L.append("")
peer_csv = os.path.join(out, "cvode_peer.csv")
L.append("### Beside CVODE")
L.append("")
if os.path.exists(peer_csv):
    peer = {}
    with open(peer_csv) as f:
        for r in csv.DictReader(f):
            peer.setdefault(r["case"], []).append(
                {"method": r["method"], "tol": float(r["tolerance"]),
                 "time": float(r["wall_seconds"]),
                 "steps": int(r["steps"]), "evals": int(r["evaluations"]),
                 "error": float(r["error_all"]), "failed": r["failed"] == "1"})
    L.append("`sled_bench_cvode_peer` (tests/bench/cvode_peer.cpp): the same right-hand side "
             "(runtime::MultibodySystem) integrated by SUNDIALS CVODE (BDF, dense Newton) and by "
             "sled's three methods, in one process, at relative tolerances 1e-2 to 1e-6, each "
             "against a dopri5 reference at 1e-10 (fastest of three runs). Time to reach each "
             "error level, as above; the last row of a case is CVODE's time over the exponential "
             "method's.")
    L.append("")
    L.append("| case | method | " + " | ".join(f"{l:.0e}" for l in LEVELS) + " |")
    L.append("|" + "---|" * (2 + len(LEVELS)))
    for name, rows in peer.items():
        c = {"rows": rows, "floor": 0.0}
        for m in METHODS + ["cvode"]:
            cells = [fmt_time(time_to(c, m, l)) for l in LEVELS]
            L.append(f"| {name} | {m} | " + " | ".join(cells) + " |")
        cells = []
        for l in LEVELS:
            te, tc = time_to(c, "exponential", l), time_to(c, "cvode", l)
            both = isinstance(te, float) and isinstance(tc, float)
            cells.append(f"{tc / te:.2g}" if both else "-")
        L.append(f"| {name} | cvode / exponential | " + " | ".join(cells) + " |")
else:
    L.append("Not measured in this run: the CVODE peer was not built (configure with "
             "`-DSLED_BENCH=ON` and Debian `libsundials-dev`).")
L.append("")
L.append("### Energy drift on the conservative cases")
L.append("")
L.append("`energy_balance.relative_residual` of `sled run` (the largest residual of kinetic + "
         "potential energy over the run, over the largest term), the scene run with each method "
         "and relative tolerance.")
L.append("")
L.append("| case | method | 1e-4 | 1e-6 | 1e-8 |")
L.append("|---|---|---|---|---|")
for name in CONSERVATIVE:
    for m in METHODS:
        cells = []
        for t in ("1e-4", "1e-6", "1e-8"):
            path = os.path.join(out, "energy", f"{name}_{m}_{t}", "summary.json")
            if not os.path.exists(path):
                cells.append("no run")
                continue
            s = json.load(open(path))
            if s.get("status") != "ok":
                cells.append("failed")
            else:
                cells.append(f"{s['energy_balance']['relative_residual']:.1e}")
        L.append(f"| {name} | {m} | " + " | ".join(cells) + " |")

# Angular momentum of the free body: |I w| (body axes, principal moments from its scene) is
# conserved in flight; its largest relative change over the run.
scene = open(os.path.join(os.path.dirname(doc), "..", "examples", "numerics", "free_body.sled"))
moments = [float(v) for v in re.search(r"inertia = \(([^)]*)\) kg\*m\^2", scene.read())
           .group(1).split(",")]
L.append("")
L.append("Angular momentum drift of `free_body` (the largest change of |I w| over the run, over "
         "its initial value, from the same runs' output rows):")
L.append("")
L.append("| method | 1e-4 | 1e-6 | 1e-8 |")
L.append("|---|---|---|---|")
for m in METHODS:
    cells = []
    for t in ("1e-4", "1e-6", "1e-8"):
        path = os.path.join(out, "energy", f"free_body_{m}_{t}", "timeseries.csv")
        if not os.path.exists(path):
            cells.append("no run")
            continue
        with open(path) as f:
            rows = list(csv.DictReader(f))
        axes = [f"box.block.angular_velocity.{a} [rad/s]" for a in "xyz"]
        norms = [math.sqrt(sum((i * float(r[a])) ** 2 for i, a in zip(moments, axes)))
                 for r in rows]
        cells.append(f"{max(abs(n - norms[0]) for n in norms) / norms[0]:.1e}")
    L.append(f"| {m} | " + " | ".join(cells) + " |")

os.makedirs(plots, exist_ok=True)
for c in cases:
    svg = os.path.join(out, c["name"], "study.svg")
    if os.path.exists(svg):
        shutil.copy(svg, os.path.join(plots, c["name"] + ".svg"))

text = open(doc).read()
begin, end = "<!-- numerics:begin -->", "<!-- numerics:end -->"
if begin not in text or end not in text:
    sys.exit("numerics.sh: docs/numerics.md has no numerics:begin / numerics:end markers")
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(doc, "w").write(head + begin + "\n" + "\n".join(L) + "\n" + end + tail)
print(f"numerics.sh: {doc} updated", file=sys.stderr)
PY
