#!/usr/bin/env python3
"""The stability map: where each method loses accuracy or fails, and whether ogive notices.

    python3 benchmarks/stability_map/stability_map.py [--ogive build/ogive] [--csv benchmarks/stability_map/stability-map.csv]

Runs `ogive bench` (one solve per row, no timing repeats) over six sweeps:

  slenderness   t/L 0.2 .. 1e-5, semicircular and pointed (eps 1)
  pointedness   eccentricity 0 .. 5
  flatness      segmental arches, rise/L 0.5 .. 0.02
  jumps         three- and four-centred arches (curvature jumps), with and without restarts there
  surveys       the points files of data/curves/
  whole arches  point, live and fill loads, a pinned and a settling springing, a hinge, a whole survey

for single and multiple shooting, Adams and BDF, and the quadrature method, and rtol 1e-4 .. 1e-12, twice: with `--no-verify`
(the raw method: how far its true error strays from rtol) and verified, as ogive runs by default (the
a-posteriori estimate: does the status notice?). The true error is against the closed form on circular arcs, else
against verified multiple shooting at rtol 1e-12 with 32 segments (see README). A verified row that says
success with a true error above rtol is a miss; the script exits 1 if there is any. A third pass checks the closed
form's own matrix exponentials against CVODE at rtol 1e-12 on the extreme scenes (`ogive check`).

Writes every row to the CSV (with the sweep and the verify mode in front) and prints the map as
Markdown tables on stdout. Standard library only.
"""
import argparse
import csv
import io
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CURVES = os.path.join(ROOT, "data", "curves")

RTOLS = "1e-4,1e-6,1e-8,1e-10,1e-12"
# The quadrature has no integrator (bench prints an empty field; it runs with the first one given) and
# always estimates its own error: its "raw" and "verified" runs are the same solve.
COMBOS = [("shooting", "adams"), ("shooting", "bdf"), ("multiple-shooting", "adams"), ("multiple-shooting", "bdf"),
          ("quadrature", "adams")]


def combo_label(method, integrator):
    return method if method == "quadrature" else f"{method} {integrator}"

# (sweep, label, scene options)
SCENES = []
for t in ["0.2", "0.08", "0.02", "0.005", "1e-3", "1e-4", "1e-5"]:
    SCENES.append(("slenderness", f"semicircular t/L {t}", ["--curve", "semicircular", "--thickness-ratio", t]))
for t in ["0.2", "0.02", "1e-3", "1e-5"]:
    SCENES.append(("slenderness", f"pointed eps 1 t/L {t}", ["--eccentricity", "1", "--thickness-ratio", t]))
for eps in ["0", "0.25", "0.5", "1", "2", "3", "5"]:
    SCENES.append(("pointedness", f"pointed eps {eps}", ["--eccentricity", eps]))
for rise in ["0.45", "0.3", "0.2", "0.1", "0.05", "0.02"]:
    SCENES.append(("flatness", f"segmental rise/L {rise}", ["--curve", "segmental", "--rise-ratio", rise]))
for label, opts in [("three-centred rise/L 0.25", ["--curve", "three-centred", "--rise-ratio", "0.25"]),
                    ("three-centred rise/L 0.4", ["--curve", "three-centred", "--rise-ratio", "0.4"]),
                    ("four-centred rise/L 0.5", ["--curve", "four-centred", "--rise-ratio", "0.5"])]:
    SCENES.append(("jumps", label + " restarts", opts))
    SCENES.append(("jumps", label + " no restarts", opts + ["--ignore-breakpoints"]))
for name in ["parabola-40.csv", "semicircle-24.csv", "catenary-survey.csv"]:
    SCENES.append(("surveys", f"points {name}", ["--curve", "points", "--curve-file", os.path.join(CURVES, name)]))
    SCENES.append(("surveys", f"points {name} no restarts",
                   ["--curve", "points", "--curve-file", os.path.join(CURVES, name), "--ignore-breakpoints"]))

# Whole arches: loads, supports and hinges that make a scene asymmetric, solved over the whole
# arch (a fill, symmetric, with --whole-arch). The reference is the closed form where it applies (point
# loads, supports, hinges on circular arcs), else verified multiple shooting at rtol 1e-12.
LOADS = os.path.join(ROOT, "data", "loads")
for label, opts in [
        ("semicircular point load at L/4", ["--curve", "semicircular", "--point-load", "2e4", "--point-load-at", "0.25"]),
        ("semicircular live load on the left half", ["--curve", "semicircular", "--live-load", "5e3", "--live-load-to", "0.5"]),
        ("catenary rise 0.4 point and live loads file", ["--curve", "catenary", "--rise-ratio", "0.4", "--loads-file",
                                                         os.path.join(LOADS, "quarter-point-and-half-live.csv")]),
        ("parabola rise 0.3 left pinned, right settles 1e-4 L", ["--curve", "parabolic", "--rise-ratio", "0.3",
                                                                 "--left-support", "pinned",
                                                                 "--right-settlement-ratio", "1e-4"]),
        ("pointed eps 0.5 three-hinged, point load at 0.3 L", ["--eccentricity", "0.5", "--supports", "pinned",
                                                               "--crown-hinge", "--point-load", "1e4",
                                                               "--point-load-at", "0.3"]),
        ("ellipse rise 0.4 fill 0.5 L, whole domain", ["--curve", "elliptical", "--rise-ratio", "0.4", "--fill-density",
                                                       "1800", "--fill-height-ratio", "0.5", "--whole-arch"]),
        ("whole points rampant-survey.csv", ["--curve", "whole-points", "--curve-file",
                                             os.path.join(CURVES, "rampant-survey.csv")])]:
    SCENES.append(("whole arches", label, opts))

# The cracking arch (--cracking): the no-tension section as hinges form (d/L 1e-4) and once they have
# (1e-2), each scene solved on its own (no continuation: the path of smaller movements inside the solve).
CRACKING_RTOLS = "1e-4,1e-6,1e-8"
CRACKING_COMBOS = [("quadrature", "adams"), ("shooting", "adams"), ("multiple-shooting", "adams"),
                   ("multiple-shooting", "bdf")]
CRACKING = []
for eps, t in [("0", "0.06"), ("0", "0.1"), ("0.5", "0.06")]:
    for d in ["1e-4", "1e-2"]:
        CRACKING.append(("cracking", f"no-tension eps {eps} t/L {t} d/L {d}",
                         ["--section", "no-tension", "--eccentricity", eps, "--thickness-ratio", t,
                          "--support-displacement-ratio", d]))

EXTREMES = [["--curve", "semicircular", "--thickness-ratio", "1e-5"], ["--eccentricity", "5"],
            ["--eccentricity", "1", "--thickness-ratio", "1e-5"], ["--curve", "segmental", "--rise-ratio", "0.02"],
            ["--curve", "four-centred", "--rise-ratio", "0.5"], ["--curve", "semicircular", "--thickness-ratio", "0.2"]]


def run(ogive, args):
    proc = subprocess.run([ogive] + args, capture_output=True, text=True)
    if proc.returncode not in (0, 3):
        sys.exit(f"stability_map: {' '.join(args)}: exit {proc.returncode}: {proc.stderr.strip()}")
    return list(csv.DictReader(io.StringIO(proc.stdout)))


def num(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ogive", default=os.path.join(ROOT, "build", "ogive"))
    parser.add_argument("--csv", default=os.path.join(HERE, "stability-map.csv"))
    parser.add_argument("--cracking", action="store_true",
                        help="the no-tension section's map instead (about 3 minutes; its own CSV)")
    args = parser.parse_args()
    scenes, combos, rtols = (CRACKING, CRACKING_COMBOS, CRACKING_RTOLS) if args.cracking else (SCENES, COMBOS, RTOLS)
    if args.cracking and args.csv == parser.get_default("csv"):
        args.csv = os.path.join(HERE, "stability-map-cracking.csv")

    rows = []
    for sweep, label, opts in scenes:
        for verify in ["never", "always"]:
            flag = ["--no-verify"] if verify == "never" else []
            for method, integrator in combos:
                out = run(args.ogive, ["bench"] + opts + ["--methods", method, "--integrators", integrator,
                                                          "--rtols", rtols, "--repeats", "1"] + flag)
                for r in out:
                    rows.append({**r, "sweep": sweep, "scene": label, "verify": verify})
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)

    # The map. Per scene and method: the worst raw error over the tolerances, in units of rtol (with
    # the statuses the raw runs returned), and what the verified runs said.
    print("| sweep | scene | " + " | ".join(combo_label(m, i) for m, i in combos) + " |")
    print("|---|---|" + "---|" * len(combos))
    misses = 0
    for sweep, label, _ in scenes:
        cells = []
        for method, integrator in combos:
            sel = [r for r in rows if r["scene"] == label and r["method"] == method
                   and r["integrator"] == ("" if method == "quadrature" else integrator)]
            raw = [r for r in sel if r["verify"] == "never"]
            ver = [r for r in sel if r["verify"] == "always"]
            worst = 0.0
            raw_flags = set()
            for r in raw:
                # What a raw solve that ran to the end says: unverified (CVODE), success (the quadrature,
                # whose estimate is its own).
                if r["status"] not in ("unverified", "success"):
                    raw_flags.add(r["status"])
                    continue
                err = max(num(r["error_H_over_V"]), num(r["error_profile"]))
                worst = max(worst, err / num(r["rtol"])) if not math.isnan(err) else math.inf
            flagged = {}
            for r in ver:
                if r["status"] != "success":
                    flagged[r["status"]] = flagged.get(r["status"], 0) + 1
            missed = unknown = 0
            for r in ver:
                err = max(num(r["error_H_over_V"]), num(r["error_profile"]))
                if r["status"] == "success" and math.isnan(err):
                    unknown += 1  # the reference itself has no numbers: the true error is unknown
                # within_tolerance (solve.hpp): success promises an error of at most rtol.
                elif r["status"] == "success" and not err <= num(r["rtol"]):
                    missed += 1
            misses += missed
            cell = f"{worst:.2g}" if math.isfinite(worst) else "inf"
            if raw_flags:
                cell += " (" + ", ".join(sorted(raw_flags)) + ")"
            cell += ("; verified: " + ", ".join(f"{n} {st}" for st, n in sorted(flagged.items()))
                     if flagged else "; verified: all success")
            if missed:
                cell += f", **{missed} MISSED**"
            if unknown:
                cell += f" ({unknown} without a reference)"
            cells.append(cell)
        print(f"| {sweep} | {label} | " + " | ".join(cells) + " |")
    print()
    print(f"Rows: {len(rows)}. Verified rows printed as success whose true error exceeds rtol: {misses}.")
    print()
    if args.cracking:
        return 1 if misses else 0
    print("The closed form against CVODE (multiple shooting, rtol 1e-11): largest relative difference of H/V")
    print()
    print("| scene | closed form H/V | relative difference | CVODE status |")
    print("|---|---|---|---|")
    for opts in EXTREMES:
        out = run(args.ogive, ["check"] + opts + ["--rtol", "1e-11"])
        ms = [r for r in out if r["method"] == "multiple-shooting"]
        cf = [r for r in out if r["method"] == "closed-form"]
        print(f"| `{' '.join(opts)}` | {cf[0]['H_over_V']} | "
              f"{num(ms[0]['relative_difference']):.2g} | {ms[0]['status']} |")
    return 1 if misses else 0


if __name__ == "__main__":
    sys.exit(main())
