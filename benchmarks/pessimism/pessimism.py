#!/usr/bin/env python3
"""The pessimism table: how far each method's error_estimate lies from its true error, and whether
its status says so.

    /usr/bin/python3 benchmarks/pessimism/pessimism.py [--ogive build/ogive] [--csv benchmarks/pessimism/pessimism.csv] [--quick]

For every scene, method (closed form, quadrature, single and multiple shooting with Adams and BDF)
and rtol 1e-3 .. 1e-12, two rows as ogive prints them: `thrust` (the six reactions) and `profile`
(41 stations). Each row's true error is measured as docs/methods.md defines what `success` promises:

  thrust   reaction_difference: each force relative to max(|its reference|, F / 100), F the largest
           reference force; each couple relative to max(|M_left|, |M_right|, F t / 6)
  profile  the larger of H/V's error (relative to max(|H/V|, 1/100), as H above) and
           profile_difference at the printed stations: U relative to max |U|, psi to max |psi|, (N, V)
           to the largest resultant, M to max(max |M|, max |N| t / 6), every scale the reference's
           largest along the arch

References, none of them the method measured:
  decimal  benchmarks/pessimism/reference.py: the symmetric clamped circular arch under self-weight and
           spreading supports in 40-digit decimal arithmetic (exact for this purpose): every method
  closed   the closed form (round-off, ~1e-14) on circular arcs with point loads, pins, hinges and
           settlements: the CVODE methods and auto's CVODE rows only
  cracked  the no-tension section: quadrature Newton at rtol 1e-12 for the shooting rows, multiple
           shooting (BDF) at rtol 3e-10 for the quadrature rows (below 2.56e-10 its tighter solve would
           run within 16 times CVODE's floor, and it is unverified)

A row is a false alarm when it says anything but success (tolerance_not_met, unverified, ill_conditioned)
with a true error within rtol, a false success when it says success with a true error above rtol. The ratio is error_estimate / true error (rows with
both finite; a true error below 1e-16, the decimal reference's noise, counts as 1e-16; one below the
error_estimate of an ogive reference, closed or cracked, cannot be measured and has no ratio). Prints the summary per
method (median and worst ratio, false alarms, false successes) as Markdown; exits 1 on any false
success. Standard library only.
"""
import argparse
import csv
import io
import math
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import reference  # noqa: E402

RTOLS = ["1e-3", "1e-4", "1e-5", "1e-6", "1e-7", "1e-8", "1e-9", "1e-10", "1e-11", "1e-12"]
STATIONS = 41
CVODE = ["shooting", "multiple-shooting"]
NOISE = 1e-16

# (label, reference kind, ogive options, decimal reference arguments)
DECIMAL = [
    ("semicircular t/L 0.08", ["--curve", "semicircular"], dict(curve="semicircular")),
    ("semicircular t/L 0.01 d/L 3e-3", ["--curve", "semicircular", "--thickness-ratio", "0.01",
                                        "--support-displacement-ratio", "0.003"],
     dict(curve="semicircular", thickness_ratio=0.01, d_ratio=0.003)),
    ("semicircular t/L 0.06 d/L 2e-4", ["--curve", "semicircular", "--thickness-ratio", "0.06",
                                        "--support-displacement-ratio", "2e-4"],
     dict(curve="semicircular", thickness_ratio=0.06, d_ratio=2e-4)),
    ("pointed eps 0.5", ["--eccentricity", "0.5"], dict(curve="pointed", eccentricity=0.5)),
    ("pointed eps 1 t/L 0.2 d/L 1e-4", ["--eccentricity", "1", "--thickness-ratio", "0.2",
                                        "--support-displacement-ratio", "1e-4"],
     dict(curve="pointed", eccentricity=1.0, thickness_ratio=0.2, d_ratio=1e-4)),
    ("pointed eps 2 t/L 0.02", ["--eccentricity", "2", "--thickness-ratio", "0.02"],
     dict(curve="pointed", eccentricity=2.0, thickness_ratio=0.02)),
    ("segmental rise 0.2", ["--curve", "segmental", "--rise-ratio", "0.2"], dict(curve="segmental", rise=0.2)),
    ("segmental rise 0.05 t/L 0.03 d/L 1e-4", ["--curve", "segmental", "--rise-ratio", "0.05", "--thickness-ratio",
                                               "0.03", "--support-displacement-ratio", "1e-4"],
     dict(curve="segmental", rise=0.05, thickness_ratio=0.03, d_ratio=1e-4)),
]
CLOSED = [
    ("semicircular point load 2e4 at L/4", ["--curve", "semicircular", "--point-load", "2e4", "--point-load-at", "0.25"]),
    ("pointed eps 0.5 pinned, right settles 1e-4 L", ["--eccentricity", "0.5", "--supports", "pinned",
                                                      "--right-settlement-ratio", "1e-4"]),
    ("pointed eps 0.5 three-hinged, point load at 0.3 L", ["--eccentricity", "0.5", "--supports", "pinned",
                                                           "--crown-hinge", "--point-load", "1e4",
                                                           "--point-load-at", "0.3"]),
    ("semicircular left rotation 1e-4, right spreads 2e-4", ["--curve", "semicircular", "--left-rotation", "1e-4",
                                                             "--right-spread-ratio", "2e-4"]),
]
CRACKED = [
    ("no-tension semicircular d/L 2e-4", ["--section", "no-tension", "--curve", "semicircular",
                                          "--support-displacement-ratio", "2e-4"]),
]

REACTIONS = ["H_left", "V_left", "M_left", "H_right", "V_right", "M_right"]
STATE = ["Ux", "Uy", "psi", "N", "shear_force", "M"]


def run(ogive, command, opts, methods, integrators, rtols, stations=None):
    cols = ["method", "integrator", "rtol", "status", "error_estimate", "H_over_V"]
    cols += REACTIONS if command == "thrust" else ["s"] + STATE
    args = [ogive, command] + opts + ["--method", ",".join(methods), "--integrator", ",".join(integrators),
                                      "--rtol", ",".join(rtols), "--columns", ",".join(cols), "--threads", "2"]
    if stations:
        args += ["--stations", str(stations)]
    out = subprocess.run(args, capture_output=True, text=True)
    if out.returncode not in (0, 3):
        sys.exit(f"{' '.join(args)}: exit {out.returncode}: {out.stderr}")
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    # One solve per (method, integrator, rtol): the profile's stations are consecutive rows.
    solves = {}
    for r in rows:
        integ = r["integrator"] if r["method"] in CVODE else ""
        key = (r["method"], integ, r["rtol"])
        solves.setdefault(key, []).append(r)
    if command == "profile":  # the method column says what auto chose; several integrators repeat rows
        for key, rs in solves.items():
            n = len(rs) // stations
            solves[key] = rs[:stations] if n >= 1 else rs
    return rows, solves


def f(x):
    return float(x) if x not in ("", None) else math.nan


def reaction_error(row, ref, thickness):
    F = max(abs(ref["H_left"]), abs(ref["V_left"]), abs(ref["V_right"]))
    couple = max(abs(ref["M_left"]), abs(ref["M_right"]), F * thickness / 6)
    worst = 0.0
    for k in ["H_left", "H_right", "V_left", "V_right"]:
        worst = max(worst, abs(f(row[k]) - ref[k]) / max(abs(ref[k]), F / 100))
    for k in ["M_left", "M_right"]:
        worst = max(worst, abs(f(row[k]) - ref[k]) / couple)
    return worst if not any(math.isnan(f(row[k])) for k in REACTIONS) else math.inf


def profile_error(rows, ref_profile, ref_hv, thickness):
    hv = f(rows[0]["H_over_V"])
    worst = abs(hv - ref_hv) / max(abs(ref_hv), 0.01)
    U = max(math.hypot(r["Ux"], r["Uy"]) for r in ref_profile)
    psi = max(abs(r["psi"]) for r in ref_profile)
    F = max(math.hypot(r["N"], r["shear_force"]) for r in ref_profile)
    M = max(max(abs(r["M"]) for r in ref_profile), max(abs(r["N"]) for r in ref_profile) * thickness / 6)
    for a, r in zip(rows, ref_profile):
        if any(math.isnan(f(a[k])) for k in STATE):
            return math.inf  # a station without numbers (max() would drop a NaN)
        worst = max(worst,
                    math.hypot(f(a["Ux"]) - r["Ux"], f(a["Uy"]) - r["Uy"]) / U,
                    abs(f(a["psi"]) - r["psi"]) / psi,
                    math.hypot(f(a["N"]) - r["N"], f(a["shear_force"]) - r["shear_force"]) / F,
                    abs(f(a["M"]) - r["M"]) / M)
    return worst


def as_reference(thrust_rows, profile_rows):
    """(reactions, profile, H/V, noise): noise the reference's own error estimate, below which no true
    error can be measured against it."""
    for rows in (thrust_rows, profile_rows):
        if rows[0]["status"] != "success":
            sys.exit(f"reference {rows[0]['method']} at rtol {rows[0]['rtol']}: {rows[0]['status']}, not success")
    reactions = {k: f(thrust_rows[0][k]) for k in REACTIONS}
    profile = [{k: f(r[k]) for k in STATE} for r in profile_rows]
    noise = max(f(thrust_rows[0]["error_estimate"]), f(profile_rows[0]["error_estimate"]), NOISE)
    return reactions, profile, f(thrust_rows[0]["H_over_V"]), noise


def thickness_of(opts):
    span = 10.0
    t = float(opts[opts.index("--thickness-ratio") + 1]) if "--thickness-ratio" in opts else 0.08
    return t * span


def measure(ogive, label, kind, opts, methods, integrators, rtols, refs):
    """Rows of one scene: refs(method) -> (reactions, profile, H/V) of the reference for that method."""
    out = []
    t = thickness_of(opts)
    for command in ["thrust", "profile"]:
        _, solves = run(ogive, command, opts, methods, integrators, rtols, STATIONS if command == "profile" else None)
        for (method, integ, rtol), rs in solves.items():
            shown = method if method != "auto" else "auto"
            ref = refs(method)
            if ref is None:
                continue
            reactions, profile, hv, noise = ref
            if command == "thrust":
                err = reaction_error(rs[0], reactions, t)
            else:
                err = profile_error(rs, profile, hv, t)
            out.append(dict(scene=label, reference=kind, command=command, method=shown, integrator=integ,
                            rtol=float(rtol), status=rs[0]["status"], error_estimate=f(rs[0]["error_estimate"]),
                            true_error=err, reference_noise=noise))
    return out


def decimal_ref(args):
    reactions, profile = reference.solve(stations=STATIONS, **args)
    return reactions, profile, reactions["H_left"] / reactions["V_left"], NOISE


def ogive_ref(ogive, opts, method, rtol, extra=()):
    _, t = run(ogive, "thrust", opts + list(extra), [method], ["bdf"], [rtol])
    _, p = run(ogive, "profile", opts + list(extra), [method], ["bdf"], [rtol], STATIONS)
    return as_reference(next(iter(t.values())), next(iter(p.values())))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ogive", default=os.path.join(HERE, "..", "..", "build", "ogive"))
    ap.add_argument("--csv", default=os.path.join(HERE, "pessimism.csv"))
    ap.add_argument("--quick", action="store_true", help="every third rtol, no no-tension scene")
    a = ap.parse_args()
    rtols = RTOLS[::3] if a.quick else RTOLS
    rows = []
    all_methods = ["closed-form", "quadrature", "shooting", "multiple-shooting"]
    for label, opts, args in DECIMAL:
        ref = decimal_ref(args)
        rows += measure(a.ogive, label, "decimal", opts, all_methods, ["adams", "bdf"], rtols, lambda m: ref)
        print(f"{label}: {len(rows)} rows", file=sys.stderr)
    for label, opts in CLOSED:
        ref = ogive_ref(a.ogive, opts, "closed-form", "1e-8")
        rows += measure(a.ogive, label, "closed", opts, ["shooting", "multiple-shooting"], ["adams", "bdf"],
                        rtols, lambda m: None if m == "closed-form" else ref)
        print(f"{label}: {len(rows)} rows", file=sys.stderr)
    if not a.quick:
        for label, opts in CRACKED:
            by_quadrature = ogive_ref(a.ogive, opts, "quadrature", "1e-12")
            by_shooting = ogive_ref(a.ogive, opts, "multiple-shooting", "3e-10")
            crack_rtols = [r for r in rtols if float(r) >= 1e-10]
            rows += measure(a.ogive, label, "cracked", opts, ["quadrature", "shooting"], ["bdf"], crack_rtols,
                            lambda m: by_shooting if m == "quadrature" else by_quadrature)
            print(f"{label}: {len(rows)} rows", file=sys.stderr)

    for r in rows:
        # Below the reference's own error estimate a true error cannot be measured: no ratio.
        measurable = r["true_error"] >= r["reference_noise"] or r["reference_noise"] <= NOISE
        r["ratio"] = r["error_estimate"] / max(r["true_error"], NOISE) if measurable else math.nan
        r["false_alarm"] = r["status"] != "success" and r["true_error"] <= r["rtol"]
        r["false_success"] = r["status"] == "success" and r["true_error"] > r["rtol"]
    with open(a.csv, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.3e}" if isinstance(v, float) else v) for k, v in r.items()})
    summarize(rows)
    return 1 if any(r["false_success"] for r in rows) else 0


def label_of(r):
    return r["method"] + (f" {r['integrator']}" if r["integrator"] else "")


def summarize(rows):
    print("| method | rows | median estimate/true | worst (largest) | smallest | tolerance_not_met | false alarms | "
          "false successes |")
    print("|---|---|---|---|---|---|---|---|")
    groups = {}
    for r in rows:
        groups.setdefault(label_of(r), []).append(r)
    for name in sorted(groups) + ["all"]:
        g = rows if name == "all" else groups[name]
        ratios = [r["ratio"] for r in g if math.isfinite(r["ratio"])]
        med = statistics.median(ratios) if ratios else math.nan
        tnm = sum(r["status"] == "tolerance_not_met" for r in g)
        fa = sum(r["false_alarm"] for r in g)
        fs = sum(r["false_success"] for r in g)
        print(f"| {name} | {len(g)} | {med:.3g} | {max(ratios, default=math.nan):.3g} | "
              f"{min(ratios, default=math.nan):.3g} | {tnm} | {fa} ({100 * fa / len(g):.1f} %) | {fs} |")
    print()
    print("Per rtol (all methods): median estimate/true")
    by_rtol = {}
    for r in rows:
        if math.isfinite(r["ratio"]):
            by_rtol.setdefault(r["rtol"], []).append(r["ratio"])
    print("| rtol | " + " | ".join(f"{k:.0e}" for k in sorted(by_rtol, reverse=True)) + " |")
    print("|---|" + "---|" * len(by_rtol))
    print("| median | " + " | ".join(f"{statistics.median(by_rtol[k]):.3g}" for k in sorted(by_rtol, reverse=True)) + " |")
    for r in rows:
        if r["false_success"]:
            print(f"FALSE SUCCESS: {r}")


if __name__ == "__main__":
    sys.exit(main())
