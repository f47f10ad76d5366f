#!/usr/bin/env python3
"""The limit analysis' time per scene over a fixed set of scenes, and its accuracy against 30 times the joints.

    python3 benchmarks/limit/speed.py [--ogive build/ogive] [--repeats 21] [--check] [--sweep]

The scenes: four curves (the semicircle, the equilateral pointed arch, a segmental arch of rise 0.25 L,
a parabolic arch of rise 0.4 L) at two thicknesses (0.08 L and 0.12 L), each under its self-weight
alone, with a fill to 0.3 L, with a point load of 20 kN/m at 0.3 L, and with both: 32 scenes, half of them with a point load (and so with the
collapse load factor). Each scene is solved --repeats times in one process (`ogive limit --repeats`,
which times analyse_limit alone, on one core) and its median taken; the script prints every scene's
median and the median over the scenes.

--check also solves every scene from 30 times the default joints and prints the largest relative
difference of any printed number (H_min, H_max, t_min, load_factor, load_factor_mechanism) from it.

--sweep times a sweep of 200 thicknesses with --threads 1 and --threads 2 (whole process, the best of
three runs each) and prints the ratio; the outputs must be the same bytes.
"""
import argparse
import csv
import io
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

CURVES = {
    "semicircle": ["--curve", "semicircular"],
    "pointed eps 0.5": ["--curve", "pointed", "--eccentricity", "0.5"],
    "segmental rise 0.25": ["--curve", "segmental", "--rise-ratio", "0.25"],
    "parabolic rise 0.4": ["--curve", "parabolic", "--rise-ratio", "0.4"],
}
THICKNESSES = ("0.08", "0.12")
POINT = ["--point-load", "2e4", "--point-load-at", "0.3"]
FILL = ["--fill-density", "1800", "--fill-height-ratio", "0.3"]
NUMBERS = ("H_min", "H_max", "thickness_min_ratio", "load_factor", "load_factor_mechanism")
FINE_JOINTS = 30 * (401 - 1) + 1


def scenes():
    for name, curve in CURVES.items():
        for t in THICKNESSES:
            for loads_name, loads in (("self-weight", []), ("fill", FILL), ("point load", POINT),
                                      ("point load + fill", POINT + FILL)):
                yield f"{name}, t/L {t}, {loads_name}", curve + ["--thickness-ratio", t] + loads


def run(ogive, args):
    out = subprocess.run([ogive, "limit", *args], check=False, capture_output=True, text=True).stdout
    return list(csv.DictReader(io.StringIO(out)))[0]


def relative(a, b):
    if a == "" or b == "":
        return 0.0 if a == b else float("inf")
    x, y = float(a), float(b)
    scale = max(abs(x), abs(y))
    return abs(x - y) / scale if scale > 0 else 0.0


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--ogive", default=os.path.join(ROOT, "build", "ogive"))
    p.add_argument("--repeats", type=int, default=21)
    p.add_argument("--check", action="store_true")
    p.add_argument("--sweep", action="store_true")
    p.add_argument("--joints-count", help="the starting joints (default: ogive's)")
    a = p.parse_args()
    start = ["--joints-count", a.joints_count] if a.joints_count else []
    columns = ",".join(("status",) + NUMBERS + ("lp_solves", "median_seconds"))
    times, worst = [], 0.0
    print("| scene | status | LPs | median ms |" + (" largest change against 30x joints |" if a.check else ""))
    print("|---|---|---|---|" + ("---|" if a.check else ""))
    for name, args in scenes():
        row = run(a.ogive, args + start + ["--repeats", str(a.repeats), "--columns", columns])
        seconds = float(row["median_seconds"])
        times.append(seconds)
        cells = [name, row["status"], row["lp_solves"], f"{1e3 * seconds:.2f}"]
        if a.check:
            fine = run(a.ogive, args + ["--joints-count", str(FINE_JOINTS), "--columns", columns])
            change = max(relative(row[k], fine[k]) for k in NUMBERS)
            worst = max(worst, change)
            cells.append(f"{change:.2g}")
        print("| " + " | ".join(cells) + " |", flush=True)
    print(f"\nmedian scene: {1e3 * statistics.median(times):.2f} ms over {len(times)} scenes "
          f"(fastest {1e3 * min(times):.2f} ms, slowest {1e3 * max(times):.2f} ms)")
    if a.check:
        print(f"largest relative change of a printed number against {FINE_JOINTS} joints: {worst:.2g}")
    if a.sweep:
        sweep = [a.ogive, "limit", "--thickness-ratio", "0.07:0.15:200", "--point-load", "2e4", "--point-load-at", "0.3"]
        best, outputs = {}, {}
        for threads in (1, 2):
            for _ in range(3):
                start = time.perf_counter()
                outputs[threads] = subprocess.run(sweep + ["--threads", str(threads)], check=True,
                                                  capture_output=True).stdout
                best[threads] = min(best.get(threads, float("inf")), time.perf_counter() - start)
        same = outputs[1] == outputs[2]
        print(f"sweep of 200 scenes: {best[1]:.2f} s on 1 thread, {best[2]:.2f} s on 2, ratio {best[1] / best[2]:.2f}; "
              f"outputs {'the same bytes' if same else 'DIFFER'}")
        if not same:
            sys.exit(1)


if __name__ == "__main__":
    main()
