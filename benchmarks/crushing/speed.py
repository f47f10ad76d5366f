#!/usr/bin/env python3
"""The cost of crushing: each scene's median time with and without --compressive-strength, in one run.

    python3 benchmarks/crushing/speed.py [--ogive build/ogive] [--repeats 21] [--strength 3.924MPa]
                                         [--baseline OTHER_OGIVE]

Every scene (L = 10 m, rho = 2000 kg/m^3) is solved --repeats times in one process (`ogive limit
--repeats`, which times the analysis alone, on one core) without the option and with it, one scene
after the other; the script prints both medians, their ratio and the linear programs each solved
(`lp_solves`: the questions asked; with crushing each may take several programs or none). Timings
are noisy: compare ratios of one run. --baseline times the scenes with crushing by another build too
(each scene's four runs one after the other) and adds its median and ratio: before and after a change.
"""
import argparse
import csv
import io
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

BASE = ["--span", "10", "--density", "2000"]
POINT = ["--point-load", "2e4", "--point-load-at", "0.3"]
ACCELERATION = "a_c"  # a scene with it prints horizontal_load_factor too (a_c is solved for it)
WALLS = ["--thickness-ratio", "0.1", "--wall-height", "10", "--wall-thickness", "2"]
SCENES = {
    "semicircle, t/L 0.08": ["--curve", "semicircular"],
    "segmental rise 0.25, t/L 0.08, 20 kN/m at 0.3 L": ["--curve", "segmental", "--rise-ratio", "0.25"] + POINT,
    "segmental rise 0.2, t/L 0.06, 100 kN/m at 0.25 L": ["--curve", "segmental", "--rise-ratio", "0.2",
                                                         "--thickness-ratio", "0.06", "--point-load", "1e5",
                                                         "--point-load-at", "0.25"],
    "semicircle, t/L 0.1, walls h_w 10 m, b_w 2 m": ["--curve", "semicircular"] + WALLS,
    "the same walls, friction 0.6": ["--curve", "semicircular", "--friction", "0.6"] + WALLS,
    "semicircle, t/L 0.08, friction 0.6 (associative)": ["--curve", "semicircular", "--friction", "0.6",
                                                         "--friction-model", "associative"],
    "semicircle, t/L 0.08, friction 0.6 (non-associative)": ["--curve", "semicircular", "--friction", "0.6"],
    "segmental rise 0.25, 20 kN/m at 0.3 L, friction 0.6 (non-associative)":
        ["--curve", "segmental", "--rise-ratio", "0.25", "--friction", "0.6"] + POINT,
    "pointed eps 0.2, t/L 0.08, live load 10 kN/m^2 on the left half": ["--curve", "pointed", "--eccentricity", "0.2",
                                                                    "--live-load", "1e4", "--live-load-from", "0",
                                                                    "--live-load-to", "0.5"],
    "semicircle, t/L 0.08, and a_c": ["--curve", "semicircular", ACCELERATION],
}


def run(ogive, args, repeats):
    columns = "status,lp_solves,median_seconds" + (",horizontal_load_factor" if ACCELERATION in args else "")
    args = [a for a in args if a != ACCELERATION]
    out = subprocess.run([ogive, "limit", *BASE, *args, "--repeats", str(repeats), "--columns", columns],
                         check=False, capture_output=True, text=True)
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    if not rows:
        sys.exit(f"ogive limit {' '.join(args)}: {out.stderr.strip()}")
    return rows[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ogive", default=os.path.join(ROOT, "build", "ogive"))
    parser.add_argument("--baseline", help="another ogive to time with crushing too (before a change)")
    parser.add_argument("--repeats", type=int, default=21)
    parser.add_argument("--strength", default="3.924MPa")
    args = parser.parse_args()
    fc = ["--compressive-strength", args.strength]
    if args.baseline:
        print("| scene | without (ms) | with, baseline (ms) | ratio | with (ms) | ratio |")
        print("|---|---|---|---|---|---|")
    else:
        print("| scene | without (ms) | with (ms) | ratio | questions without | questions with | status with |")
        print("|---|---|---|---|---|---|---|")
    for name, scene in SCENES.items():
        plain = run(args.ogive, scene, args.repeats)
        a = 1e3 * float(plain["median_seconds"])
        if args.baseline:
            before = 1e3 * float(run(args.baseline, scene + fc, args.repeats)["median_seconds"])
        crushed = run(args.ogive, scene + fc, args.repeats)
        b = 1e3 * float(crushed["median_seconds"])
        if args.baseline:
            print(f"| {name} | {a:.2f} | {before:.2f} | {before / a:.1f} | {b:.2f} | {b / a:.1f} |", flush=True)
        else:
            print(f"| {name} | {a:.2f} | {b:.2f} | {b / a:.1f} | {plain['lp_solves']} | {crushed['lp_solves']} | "
                  f"{crushed['status']} |", flush=True)


if __name__ == "__main__":
    main()
