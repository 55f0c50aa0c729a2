#!/usr/bin/env bash
# Measures the numerics suite and rewrites the measured part of docs/numerics.md.
#
#   scripts/numerics.sh [OUT]      (OUT: where the study folders go; default build/numerics)
#
#   SLED_NUMERICS_CASES="free_body lock_cascade"   measures only those cases of the suite (and
#                                                  `flagship` only when named); default: all. The
#                                                  page keeps every other case's rows and lines as
#                                                  the earlier run wrote them, and says which run
#                                                  measured which cases
#   SLED_NUMERICS_TABLES_ONLY=1  measures nothing: rewrites the tables from OUT as an earlier
#                                run left it
#   SLED_NUMERICS_DOC=FILE     writes the tables into FILE (and the plots beside it, in
#                              numerics/) instead of docs/numerics.md, say to try the script on
#                              a few cases without touching the published page
#
# 1. `sled study` on every case of examples/numerics/suite.txt and on the flagship, over the
#    tolerance ladder $SLED_NUMERICS_TOLERANCES (default 1e-2 to 1e-6);
# 2. `sled run` of the conservative cases with each integrator at 1e-4, 1e-6 and 1e-8, for the
#    energy balance's drift (summary.json, energy_balance.relative_residual) and, from the output
#    rows, the momentum drift: the free body's linear momentum (against gravity's impulse) and
#    angular momentum, and the heavy top's angular momentum about the vertical through its tip;
# 3. the CVODE peer (tests/bench/cvode_peer.cpp) beside sled's integrators on every case (events,
#    load histories and all), when it is built;
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
doc="${SLED_NUMERICS_DOC:-${root}/docs/numerics.md}"
cases="${SLED_NUMERICS_CASES:-}"
conservative=(free_body spin_100 pendulum_chain)
methods=(auto exponential dopri5 rosenbrock cvs)

load_before="(not recorded: tables rewritten from an earlier run)"
order_tolerances="${SLED_NUMERICS_ORDER_TOLERANCES:-1e-5,3e-6,1e-6,3e-7,1e-7,3e-8,1e-8,3e-9,1e-9,3e-10,1e-10}"
if [[ -z "${SLED_NUMERICS_TABLES_ONLY:-}" ]]; then
[[ -x "${sled}" ]] || { echo "numerics.sh: no sled at ${sled}; build first" >&2; exit 1; }
mkdir -p "${out}"
# Whether a case is measured in this run (all of them unless SLED_NUMERICS_CASES names some).
wanted() {
  [[ -z "${cases}" ]] || [[ " ${cases//,/ } " == *" $1 "* ]]
}
# Only this run's cases are tabulated: forget the folders of earlier runs.
rm -f "${out}"/*/kind
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
  wanted "${name}" || continue
  mkdir -p "${out}/${name}"
  echo "${kind}" >"${out}/${name}/kind"
  study "${name}" "${root}/examples/${file}" "${rest}"
done <"${suite}"
# The convergence orders of the smooth cases: a second study over the asymptotic range, in
# half-decade steps (numerics.md §6), where the tolerance rather than the output landings sets the
# step count (at 1e-2 to 1e-4 dopri5 takes 44 to 82 steps for the pendulum chain's 40 output
# intervals, so its error falls faster than its steps grow).
rm -rf "${out}/order"
while read -r kind name file rest; do
  [[ "${kind}" == smooth ]] || continue
  wanted "${name}" || continue
  mkdir -p "${out}/order/${name}"
  echo "${kind}" >"${out}/order/${name}/kind"
  echo "numerics.sh: order sweep of ${name}" >&2
  "${sled}" study "${root}/examples/${file}" --tolerances "${order_tolerances}" \
    -o "${out}/order/${name}" >"${out}/order/${name}/table.txt" \
    2>"${out}/order/${name}/log.txt" ||
    echo "numerics.sh: the order sweep of ${name} failed" >&2
done <"${suite}"
if [[ -z "${cases}" ]] || wanted flagship; then
  mkdir -p "${out}/flagship"
  echo flagship >"${out}/flagship/kind"
  study flagship "${root}/examples/frontal_sled.sled" ""
fi

# Energy drift: the scene with its integrator line replaced by each method and tolerance.
rm -rf "${out}/energy"
mkdir -p "${out}/energy"
for name in "${conservative[@]}"; do
  wanted "${name}" || continue
  for method in "${methods[@]}"; do
    for tolerance in 1e-4 1e-6 1e-8; do
      scene="${out}/energy/${name}_${method}_${tolerance}.sled"
      standard="^  integrator auto { tolerance = 1e-6 }$"
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
  peer_cases=()
  [[ -n "${cases}" ]] && read -ra peer_cases <<<"${cases//,/ }"
  "${peer}" "--tolerances=${tolerances}" "${peer_cases[@]}" >"${out}/cvode_peer.csv.part" \
    2>"${out}/cvode_peer.log" && mv "${out}/cvode_peer.csv.part" "${out}/cvode_peer.csv"
else
  echo "numerics.sh: no CVODE peer at ${peer}" \
    "(configure with -DSLED_BENCH=ON and libsundials-dev)" >&2
fi

fi
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
[[ -n "${SLED_NUMERICS_TABLES_ONLY:-}" ]] && load_after="(not recorded)"
python3 - "${out}" "${doc}" "$(dirname "${doc}")/numerics" "${tolerances}" \
  "${load_before}" "${load_after}" "$(git -C "${root}" rev-parse --short HEAD)" "${root}" \
  "${order_tolerances}" "${cases}" <<'PY'
import csv, json, math, os, re, shutil, sys
from datetime import date

out, doc, plots, ladder, load_before, load_after, commit, root, order_tolerances, only = \
    sys.argv[1:11]
LEVELS = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6]
METHODS = ["auto", "exponential", "dopri5", "rosenbrock", "cvs"]
# Theoretical orders (auto is dopri5 or the exponential method, step by step: no single order;
# rosenbrock's steps on the smooth cases are not stiff, so its order-4 method takes them).
ORDERS = {"exponential": 3, "dopri5": 5, "rosenbrock": 4, "cvs": 3}
STIFF_TARGET = ["viscous_damping", "joint_stops", "tension_tether", "contact_1e8", "contact_1e9",
                "contact_1e10", "contact_1e11", "airbag_gas", "belt_restraint"]
CONSERVATIVE = ["free_body", "spin_100", "pendulum_chain"]


def read_case(name, parent=None):
    folder = os.path.join(parent or out, name)
    rows = []
    path = os.path.join(folder, "study.csv")
    if os.path.exists(path):
        with open(path) as f:
            for r in csv.DictReader(f):
                rows.append({"method": r["method"], "tol": float(r["tolerance"]),
                             "time": float(r["wall_seconds"]), "steps": int(r["steps"]),
                             "evals": int(r["evaluations"]), "error": float(r["error_all"]),
                             "failed": r["failed"] == "1",
                             "decaying": int(r.get("decaying_steps") or 0)})
    floor = None
    table = os.path.join(folder, "table.txt")
    if os.path.exists(table):
        m = re.search(r"floor \(the references differ by\) +([0-9.e+-]+)", open(table).read())
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
for line in open(os.path.join(root, "examples", "numerics", "suite.txt")):
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
         "below the reference's own uncertainty. The last row of a case is auto's time (the "
         "default) over the fastest of the other four methods, at each level where both got "
         "there.")
L.append("")
head = "| case | kind | method | " + " | ".join(f"{l:.0e}" for l in LEVELS) + " |"
L.append(head)
L.append("|" + "---|" * (3 + len(LEVELS)))
for c in cases:
    for m in METHODS:
        cells = [fmt_time(time_to(c, m, l)) for l in LEVELS]
        L.append(f"| {c['name']} | {c['kind']} | {m} | " + " | ".join(cells) + " |")
    ratios = []
    for l in LEVELS:
        ta = time_to(c, "auto", l)
        others = [time_to(c, m, l) for m in METHODS if m != "auto"]
        others = [t for t in others if isinstance(t, float)]
        if isinstance(ta, float) and others:
            ratios.append(f"{ta / min(others):.2g}")
        else:
            ratios.append("-")
    L.append(f"| {c['name']} | | auto / fastest other | " + " | ".join(ratios) + " |")
L.append("")
L.append("Plots: " + ", ".join(f"[{c['name']}](numerics/{c['name']}.svg)" for c in cases
                               if os.path.exists(os.path.join(out, c["name"], "study.svg"))) + ".")
L.append("")
L.append("Reference uncertainty (the floor: what the dopri5 reference and its cross-check, the "
         "exponential method, both at a hundredth of the tightest tolerance, differ by): " +
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
L.append("### Recommendation per case")
L.append("")
L.append("The fastest method to reach each error level (from the table above; *-*: none got "
         "there or the reference does not resolve it).")
L.append("")
L.append("| case | kind | " + " | ".join(f"{l:.0e}" for l in LEVELS) + " |")
L.append("|---|---|" + "---|" * len(LEVELS))
for c in cases:
    cells = []
    for l in LEVELS:
        timed = [(time_to(c, m, l), m) for m in METHODS]
        timed = [(t, m) for t, m in timed if isinstance(t, float)]
        cells.append(min(timed)[1] if timed else "-")
    L.append(f"| {c['name']} | {c['kind']} | " + " | ".join(cells) + " |")
L.append("")
L.append("What the `cvs` method integrates exponentially: the share of its accepted steps "
         "in which at least one 3-vector group (a free body's linear or angular velocity, a ball "
         "joint's angular velocity) had a trusted decay rate (`decaying_steps` of `study.csv`), "
         "at each tolerance of the ladder. The other steps are Kutta's third-order Runge-Kutta "
         "steps.")
L.append("")
L.append("| case | kind | " + " | ".join(f"{t:.0e}" for t in LEVELS) + " |")
L.append("|---|---|" + "---|" * len(LEVELS))
for c in cases:
    cells = []
    for t in LEVELS:
        runs = [r for r in c["rows"] if r["method"] == "cvs" and abs(r["tol"] - t) < 1e-3 * t]
        cells.append(f"{100 * runs[0]['decaying'] / runs[0]['steps']:.0f} %"
                     if runs and runs[0]["steps"] > 0 else "-")
    L.append(f"| {c['name']} | {c['kind']} | " + " | ".join(cells) + " |")
L.append("")
L.append("### Convergence orders on the smooth cases")
L.append("")
L.append("Minus the least-squares slope of log10 error against log10 accepted steps (and against "
         "log10 derivative evaluations), over the completed runs whose error is at least ten "
         "times the reference's uncertainty. *Asymptotic*: a separate study of each smooth case "
         f"at the tolerances {order_tolerances} (half-decade steps, the reference at a hundredth "
         "of the tightest), where the tolerance sets the step count; this is the observed order "
         "the target (within 0.5 of the theoretical order) is judged on. *Ladder*: the same fit "
         "over the work-precision ladder above, whose loose end is pre-asymptotic and whose step "
         "counts there are floored by the landings on the output times, which steepens the "
         "slope.")
L.append("")
L.append("| case | method | theoretical | asymptotic (steps) | asymptotic (evaluations) | runs "
         "| ladder (steps) | within 0.5 |")
L.append("|---|---|---|---|---|---|---|---|")
order_names = sorted(d for d in os.listdir(os.path.join(out, "order"))
                     if os.path.exists(os.path.join(out, "order", d, "kind"))) \
    if os.path.isdir(os.path.join(out, "order")) else []
for c in cases:
    if c["kind"] != "smooth":
        continue
    sweep = read_case(c["name"], os.path.join(out, "order")) if c["name"] in order_names else None
    for m in ORDERS:
        p_ladder, _ = order(c, m, "steps")
        ladder_text = f"{p_ladder:.2f}" if p_ladder is not None else "-"
        p_steps, n = order(sweep, m, "steps") if sweep else (None, 0)
        p_evals, _ = order(sweep, m, "evals") if sweep else (None, 0)
        if p_steps is None:
            L.append(f"| {c['name']} | {m} | {ORDERS[m]} | - | - | {n} | {ladder_text} "
                     "| too few runs |")
            continue
        ok = "yes" if abs(p_steps - ORDERS[m]) <= 0.5 else "no"
        L.append(f"| {c['name']} | {m} | {ORDERS[m]} | {p_steps:.2f} | {p_evals:.2f} | {n} "
                 f"| {ladder_text} | {ok} |")
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
                 "events": int(r["events"]), "error": float(r["error_all"]),
                 "failed": r["failed"] == "1"})
    tightest = min(float(t) for t in ladder.split(","))
    L.append("`sled_bench_cvode_peer` (tests/bench/cvode_peer.cpp): the same right-hand side "
             "(runtime::MultibodySystem) integrated by SUNDIALS CVODE (BDF, dense Newton) and by "
             "sled's five methods, in one process, at relative tolerances "
             f"{ladder.replace(',', ', ')}, each against a dopri5 reference at 1e-10 (fastest of "
             "three runs), on every case of the suite. CVODE is driven as sled's integrators "
             "drive the system: the system's event functions (impulsive joint stops and contacts, "
             "joint locks and unlocks) are CVODE's root functions, and at a root the events are "
             "handled, the state projected and the histories committed, and CVODE restarts there "
             "(`CVodeReInit`); unit quaternions and loop constraints are projected after each "
             "step by CVODE's own projection (`CVodeSetProjFn`); the load histories of contacts "
             "and belts are committed after each accepted step, on that step's state (CVODE "
             "driven one step at a time), never on an interpolated one; and it lands on each "
             "output time, as sled's methods do. Time to reach each error level, as above; the "
             f"column *at {tightest:.0e}* is the run's error at the tightest tolerance (and, "
             "when the case has events, how many the run located); the last row of a case is "
             "CVODE's time over the exponential method's.")
    L.append("")
    L.append("| case | method | " + " | ".join(f"{l:.0e}" for l in LEVELS) +
             f" | at {tightest:.0e} |")
    L.append("|" + "---|" * (3 + len(LEVELS)))
    ordered = [n for n in suite_order if n in peer] + [n for n in peer if n not in suite_order]
    for name in ordered:
        rows = peer[name]
        c = {"rows": rows, "floor": 0.0}
        any_events = any(r["events"] > 0 for r in rows)
        for m in METHODS + ["cvode"]:
            cells = [fmt_time(time_to(c, m, l)) for l in LEVELS]
            last = [r for r in rows if r["method"] == m and r["tol"] == tightest]
            if not last:
                at = "no run"
            elif last[0]["failed"]:
                at = "failed"
            else:
                at = f"{last[0]['error']:.1e}"
                if any_events:
                    at += f" ({last[0]['events']} events)"
            L.append(f"| {name} | {m} | " + " | ".join(cells) + f" | {at} |")
        cells = []
        for l in LEVELS:
            te, tc = time_to(c, "exponential", l), time_to(c, "cvode", l)
            both = isinstance(te, float) and isinstance(tc, float)
            cells.append(f"{tc / te:.2g}" if both else "-")
        L.append(f"| {name} | cvode / exponential | " + " | ".join(cells) + " | |")
    study_cases = {c["name"]: c for c in cases}

    def peer_time(name, m, l):
        floor = study_cases[name]["floor"] if name in study_cases else 0.0
        return time_to({"rows": peer[name], "floor": floor}, m, l)

    L.append("")
    L.append("### Target: the exponential method on the stiff cases")
    L.append("")
    L.append("From the CVODE peer's runs above (one process, fastest of three runs): dopri5's time "
             "over the exponential method's and CVODE's over the exponential method's, to reach "
             "each level (the floor of the study's references applies). The target: at least 3 "
             "and at least 1 (on the flagship, dopri5 / exponential at least 1).")
    L.append("")
    L.append("| case | ratio | " + " | ".join(f"{l:.0e}" for l in LEVELS) + " | met |")
    L.append("|---|---|" + "---|" * len(LEVELS) + "---|")
    for name in [n for n in STIFF_TARGET + ["flagship"] if n in peer]:
        for other, goal in (("dopri5", 3.0), ("cvode", 1.0)):
            # A level only the exponential method reached counts as met (shown as `only exp.`),
            # one only the other reached as missed (`not reached`).
            rs = []
            for l in LEVELS:
                te, to = peer_time(name, "exponential", l), peer_time(name, other, l)
                if isinstance(te, float) and isinstance(to, float):
                    rs.append(to / te)
                elif isinstance(te, float) and to is None:
                    rs.append(math.inf)
                elif te is None and isinstance(to, float):
                    rs.append(0.0)
                else:
                    rs.append(None)
            known = [r for r in rs if r is not None]
            met = f"{sum(r >= goal for r in known)} of {len(known)}"
            cells = ["-" if r is None else "only exp." if r == math.inf else
                     "not reached" if r == 0.0 else f"{r:.2g}" for r in rs]
            L.append(f"| {name} | {other} / exponential | " + " | ".join(cells) + f" | {met} |")
    L.append("")
    L.append("### Target: auto within 1.25x of the fastest and never slower than CVODE")
    L.append("")
    L.append("From the same runs: auto's time over the fastest of sled's other four methods, and "
             "over CVODE's, to reach each level. The target: at most 1.25 and at most 1.")
    L.append("")
    L.append("| case | ratio | " + " | ".join(f"{l:.0e}" for l in LEVELS) + " | met |")
    L.append("|---|---|" + "---|" * len(LEVELS) + "---|")
    for name in ordered:
        fastest = []
        for l in LEVELS:
            ts = [peer_time(name, m, l) for m in METHODS if m != "auto"]
            ts = [t for t in ts if isinstance(t, float)]
            fastest.append(min(ts) if ts else None)
        for label, base, goal in (("auto / fastest", fastest, 1.25),
                                  ("auto / cvode", [peer_time(name, "cvode", l) for l in LEVELS],
                                   1.0)):
            # A level auto missed where the other got there counts as missed (`not reached`);
            # one only auto reached as met (`only auto`).
            rs = []
            for l, b in zip(LEVELS, base):
                ta = peer_time(name, "auto", l)
                if isinstance(ta, float) and isinstance(b, float):
                    rs.append(ta / b)
                elif ta is None and isinstance(b, float):
                    rs.append(math.inf)
                elif isinstance(ta, float) and b is None:
                    rs.append(0.0)
                else:
                    rs.append(None)
            known = [r for r in rs if r is not None]
            met = f"{sum(r <= goal for r in known)} of {len(known)}"
            cells = ["-" if r is None else "not reached" if r == math.inf else
                     "only auto" if r == 0.0 else f"{r:.2g}" for r in rs]
            L.append(f"| {name} | {label} | " + " | ".join(cells) + f" | {met} |")
else:
    L.append("Not measured in this run: the CVODE peer was not built (configure with "
             "`-DSLED_BENCH=ON` and Debian `libsundials-dev`).")
ENERGY_TOLERANCES = ("1e-4", "1e-6", "1e-8")
energy_cases = [n for n in CONSERVATIVE
                if any(os.path.isdir(os.path.join(out, "energy", f"{n}_{m}_{t}"))
                       for m in METHODS for t in ENERGY_TOLERANCES)]
L.append("")
L.append("### Energy and momentum drift on the conservative cases")
L.append("")
L.append("`energy_balance.relative_residual` of `sled run` (the largest residual of kinetic + "
         "potential energy over the run, over the largest term), the scene run with each method "
         "and relative tolerance.")
L.append("")
L.append("| case | method | " + " | ".join(ENERGY_TOLERANCES) + " |")
L.append("|---|---|---|---|---|")
for name in energy_cases:
    for m in METHODS:
        cells = []
        for t in ENERGY_TOLERANCES:
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


def scene_text(name):
    return open(os.path.join(root, "examples", "numerics", f"{name}.sled")).read()


def vector(text, pattern):
    """The three numbers of the first `pattern` (a regex with one group around them)."""
    return [float(v) for v in re.search(pattern, text).group(1).split(",")]


def gravity(text):
    """The scene's gravity [m/s^2]: its `gravity =` line, or the default (0, 0, -1) g."""
    m = re.search(r"gravity = \(([^)]*)\) m/s\^2", text)
    return [float(v) for v in m.group(1).split(",")] if m else [0.0, 0.0, -9.80665]


def rotation(yaw, pitch, roll):
    """Segment axes to ground from the output's yaw, pitch and roll (about z, y, x)."""
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    cr, sr = math.cos(roll), math.sin(roll)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def channel(row, label, quantity, components):
    unit = {"position": "m", "velocity": "m/s", "angular_velocity": "rad/s",
            "orientation": "rad"}[quantity]
    return [float(row[f"{label}.{quantity}.{c} [{unit}]"]) for c in components]


XYZ = "xyz"


def free_body_linear(rows, text):
    """|v(t) - v(0) - g t| / |v(0)| of the centre of mass: the momentum balance with gravity's
    impulse, which a uniform field makes exact (the mass cancels)."""
    g = gravity(text)
    v0 = channel(rows[0], "box.block", "velocity", XYZ)
    t0 = float(rows[0]["time [s]"])
    worst = 0.0
    for r in rows:
        t = float(r["time [s]"]) - t0
        v = channel(r, "box.block", "velocity", XYZ)
        worst = max(worst, math.sqrt(sum((v[i] - v0[i] - g[i] * t) ** 2 for i in range(3))))
    return worst / math.sqrt(sum(c * c for c in v0))


def free_body_angular(rows, text):
    """|I w| (body axes, principal moments from the scene) is conserved in flight."""
    moments = vector(text, r"inertia = \(([^)]*)\) kg\*m\^2")
    norms = [math.sqrt(sum((i * w) ** 2 for i, w in
                           zip(moments, channel(r, "box.block", "angular_velocity", XYZ))))
             for r in rows]
    return max(abs(n - norms[0]) for n in norms) / norms[0]


def top_vertical(rows, text):
    """The heavy top's angular momentum about the vertical through its tip, R I w + m r x v
    (z component): gravity's torque about the tip and the tip's reaction have none."""
    mass = float(re.search(r"mass = ([0-9.e+-]+) kg", text).group(1))
    moments = vector(text, r"inertia = \(([^)]*)\) kg\*m\^2")
    tip = [v / 1000 for v in vector(text, r"at ground = \(([^)]*)\) mm")]
    values = []
    for r in rows:
        R = rotation(*channel(r, "top.disc", "orientation", ("yaw", "pitch", "roll")))
        w = channel(r, "top.disc", "angular_velocity", XYZ)
        p = channel(r, "top.disc", "position", XYZ)
        v = channel(r, "top.disc", "velocity", XYZ)
        spin = sum(R[2][i] * moments[i] * w[i] for i in range(3))
        orbit = mass * ((p[0] - tip[0]) * v[1] - (p[1] - tip[1]) * v[0])
        values.append(spin + orbit)
    return max(abs(x - values[0]) for x in values) / abs(values[0])


MOMENTA = [("free_body", "linear momentum (with gravity's impulse)", free_body_linear),
           ("free_body", "angular momentum \\|I w\\|", free_body_angular),
           ("spin_100", "angular momentum about the vertical through the tip", top_vertical)]
momenta = [m for m in MOMENTA if m[0] in energy_cases]
if momenta:
    L.append("")
    L.append("Momentum drift, from the same runs' output rows: the largest change over the run, "
             "over the initial value. `free_body` flies under gravity, so its linear momentum "
             "is compared with the initial one plus gravity's impulse m g t; `spin_100`'s "
             "momentum about the vertical through its tip is conserved because gravity's "
             "torque about the tip, and the tip's reaction, have no vertical component.")
    L.append("")
    L.append("| case | quantity | method | " + " | ".join(ENERGY_TOLERANCES) + " |")
    L.append("|---|---|---|---|---|---|")
    for name, quantity, measure in momenta:
        text = scene_text(name)
        for m in METHODS:
            cells = []
            for t in ENERGY_TOLERANCES:
                folder = os.path.join(out, "energy", f"{name}_{m}_{t}")
                path = os.path.join(folder, "timeseries.csv")
                if not os.path.exists(path):
                    cells.append("no run")
                    continue
                summary = os.path.join(folder, "summary.json")
                if os.path.exists(summary) and json.load(open(summary)).get("status") != "ok":
                    cells.append("failed")
                    continue
                with open(path) as f:
                    cells.append(f"{measure(list(csv.DictReader(f)), text):.1e}")
            L.append(f"| {name} | {quantity} | {m} | " + " | ".join(cells) + " |")

os.makedirs(plots, exist_ok=True)
for c in cases:
    svg = os.path.join(out, c["name"], "study.svg")
    if os.path.exists(svg):
        shutil.copy(svg, os.path.join(plots, c["name"] + ".svg"))


def table_spans(lines):
    """{(heading, header, count): (header index, end index)} of the tables of a block (count:
    how many tables with that heading and header came before it)."""
    spans, heading, i = {}, None, 0
    while i < len(lines):
        if lines[i].startswith("### "):
            heading = lines[i]
        if lines[i].startswith("| case |"):
            j = i + 2
            while j < len(lines) and lines[j].startswith("|"):
                j += 1
            count = sum(1 for key in spans if key[:2] == (heading, lines[i]))
            spans[(heading, lines[i], count)] = (i, j)
            i = j
            continue
        i += 1
    return spans


def row_case(row):
    return row.split("|")[1].strip()


def merge_partial(old, new, measured, order):
    """The earlier block `old` with the rows and lines of the `measured` cases from `new`."""
    rank = {name: k for k, name in enumerate(order)}
    merged = list(old)
    old_spans, new_spans = table_spans(old), table_spans(new)
    # Tables from the bottom up, so the spans above stay where they are.
    for key, (start, stop) in sorted(old_spans.items(), key=lambda item: -item[1][0]):
        if key not in new_spans:
            continue
        s, e = new_spans[key]
        rows = [r for r in merged[start + 2:stop] if row_case(r) not in measured]
        # Each new row goes before the first kept row of a later case in the suite's order (the
        # kept rows keep theirs).
        for row in new[s + 2:e]:
            later = [k for k, r in enumerate(rows)
                     if rank.get(row_case(r), len(rank)) > rank.get(row_case(row), len(rank))]
            rows.insert(later[0] if later else len(rows), row)
        merged[start + 2:stop] = rows
    for key, (s, e) in new_spans.items():
        if key not in old_spans:
            merged += ["", key[0] or "", ""] + new[s:e]
    names = ", ".join(sorted(measured))

    def patch(prefix, separator, entries):
        """A line `prefix ...SEPARATOR a, b, c.` whose entries are per case: the measured ones
        replaced."""
        old_line = next((k for k, l in enumerate(merged) if l.startswith(prefix)), None)
        new_line = next((l for l in new if l.startswith(prefix)), None)
        if old_line is None or new_line is None:
            return
        kept = [x for x in entries(merged[old_line]) if x[0] not in measured] + entries(new_line)
        kept.sort(key=lambda x: rank.get(x[0], len(rank)))
        merged[old_line] = (new_line.split(separator, 1)[0] + separator + " " +
                            ", ".join(x[1] for x in kept) + ".")

    patch("Plots:", ":", lambda l: [(re.search(r"\[([^]]+)\]", x).group(1), x.strip())
                                    for x in l.split(":", 1)[1].rstrip(".").split(",") if "[" in x])
    patch("Reference uncertainty", "):",
          lambda l: [(x.split()[0], x.strip()) for x in l.split("):", 1)[1].rstrip(".").split(",")
                     if x.strip()])
    # The failures: the earlier run's for the other cases and this run's.
    fails = [l for l in merged if l.startswith("- ") and l[2:].split(",")[0] not in measured
             and " at " in l and "failed at" in l]
    fails += [l for l in new if l.startswith("- ") and "failed at" in l]
    at = next((k for k, l in enumerate(merged) if l.startswith("Runs of the ladder that stopped")
               or l.startswith("No run of the ladder")), None)
    if at is not None:
        stop = at + 1
        while stop < len(merged) and (merged[stop] == "" or merged[stop].startswith("- ")):
            stop += 1
        block = (["Runs of the ladder that stopped with a failure (method, tolerance, where and "
                  "why):", ""] + sorted(fails, key=lambda l: rank.get(l[2:].split(",")[0], 99))
                 if fails else ["No run of the ladder stopped with a failure."])
        merged[at:stop] = block + [""]
    # Which run measured what.
    stamp = next(l for l in new if l.startswith("Measured by"))
    merged = [l for l in merged if not (l.startswith("Cases ") and "measured by" in l
                                        and set(l[6:l.index(":")].split(", ")) <= measured)]
    merged.insert(0, f"Cases {names}: measured by" + stamp[len("Measured by"):])
    merged.insert(1, "")
    return merged


text = open(doc).read()
begin, end = "<!-- numerics:begin -->", "<!-- numerics:end -->"
if begin not in text or end not in text:
    sys.exit("numerics.sh: docs/numerics.md has no numerics:begin / numerics:end markers")
head, rest = text.split(begin, 1)
previous, tail = rest.split(end, 1)
if only.strip():
    # SLED_NUMERICS_CASES: the page keeps every other case's rows and lines as the earlier run
    # left them, and this run's cases replace or join theirs.
    L = merge_partial(previous.strip("\n").split("\n"), L, set(only.replace(",", " ").split()),
                      suite_order + ["flagship"])
open(doc, "w").write(head + begin + "\n" + "\n".join(L) + "\n" + end + tail)
print(f"numerics.sh: {doc} updated", file=sys.stderr)
PY
