#!/usr/bin/env python3
"""Calibration of the quadrature's estimate and of the CVODE round-off term on random arches, none of
them the pessimism table's scenes.

    /usr/bin/python3 benchmarks/pessimism/calibration.py [--ogive build/ogive] [--arches 40] [--seed 1]

Draws symmetric clamped circular arches (semicircular, pointed with eccentricity 0 .. 2, segmental with
rise 0.05 .. 0.5; t/L 0.005 .. 0.25 log-uniform; each springing moved out by 0 or d/L 1e-5 .. 3e-3),
solves them with the quadrature at every rtol 1e-3 .. 1e-12 and with single and multiple shooting,
Adams and BDF, at rtol 1e-9 .. 1e-12 (where round-off is what is left), and measures every row's true
error against benchmarks/pessimism/reference.py (40 digits) as pessimism.py does. Prints, per method,
the smallest and the median error_estimate / true error over the `success` rows and the rows below 1;
the smallest ratio is the margin by which the estimate covers round-off on scenes it was not fitted to.
Standard library only.
"""
import argparse
import math
import os
import random
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import pessimism  # noqa: E402
import reference  # noqa: E402

QUADRATURE_RTOLS = pessimism.RTOLS
CVODE_RTOLS = ["1e-9", "1e-10", "1e-11", "1e-12"]


def random_arch(rng):
    curve = rng.choice(["semicircular", "pointed", "segmental"])
    t = math.exp(rng.uniform(math.log(0.005), math.log(0.25)))
    d = 0.0 if rng.random() < 0.3 else math.exp(rng.uniform(math.log(1e-5), math.log(3e-3)))
    opts = ["--thickness-ratio", f"{t:.4g}", "--support-displacement-ratio", f"{d:.4g}"]
    args = dict(curve=curve, thickness_ratio=float(f"{t:.4g}"), d_ratio=float(f"{d:.4g}"))
    if curve == "semicircular":
        opts += ["--curve", "semicircular"]
    elif curve == "pointed":
        e = round(rng.uniform(0.05, 2.0), 3)
        opts += ["--eccentricity", str(e)]
        args["eccentricity"] = e
    else:
        rise = round(rng.uniform(0.05, 0.5), 3)
        opts += ["--curve", "segmental", "--rise-ratio", str(rise)]
        args["rise"] = rise
    return " ".join(opts), opts, args


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ogive", default=os.path.join(HERE, "..", "..", "build", "ogive"))
    ap.add_argument("--arches", type=int, default=40)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--csv", default=None, help="write every row here")
    ap.add_argument("--quadrature-only", action="store_true", help="no CVODE rows (a few seconds per arch less)")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    rows = []
    for i in range(a.arches):
        label, opts, args = random_arch(rng)
        ref = pessimism.decimal_ref(args)
        rows += [dict(r, arch=label) for r in
                 pessimism.measure(a.ogive, label, "decimal", opts, ["quadrature"], ["bdf"], QUADRATURE_RTOLS,
                                   lambda m: ref)]
        if not a.quadrature_only:
            rows += [dict(r, arch=label) for r in
                     pessimism.measure(a.ogive, label, "decimal", opts, ["shooting", "multiple-shooting"],
                                       ["adams", "bdf"], CVODE_RTOLS, lambda m: ref)]
        print(f"{i + 1}/{a.arches} {label}", file=sys.stderr)
    for r in rows:
        r["ratio"] = r["error_estimate"] / max(r["true_error"], pessimism.NOISE)
    if a.csv:
        import csv
        with open(a.csv, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    print("| method | success rows | smallest estimate/true | median | rows below 1 | tolerance_not_met within rtol |")
    print("|---|---|---|---|---|---|")
    groups = {}
    for r in rows:
        groups.setdefault(pessimism.label_of(r), []).append(r)
    for name in sorted(groups):
        ok = [r for r in groups[name] if r["status"] == "success" and math.isfinite(r["ratio"])]
        ratios = [r["ratio"] for r in ok]
        alarms = sum(r["status"] == "tolerance_not_met" and r["true_error"] <= r["rtol"] for r in groups[name])
        print(f"| {name} | {len(ok)} | {min(ratios, default=math.nan):.3g} | "
              f"{statistics.median(ratios) if ratios else math.nan:.3g} | {sum(x < 1 for x in ratios)} | {alarms} |")
    below = [r for r in rows if r["status"] == "success" and r["ratio"] < 1]
    for r in below:
        print(f"BELOW 1: {r['arch']} {r['command']} {pessimism.label_of(r)} rtol {r['rtol']:.0e}: "
              f"estimate {r['error_estimate']:.3e} true {r['true_error']:.3e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
