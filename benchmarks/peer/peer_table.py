#!/usr/bin/python3
"""The comparison with scipy's solve_bvp (benchmarks/peer/README.md, docs/methods.md), from the CSV that benchmarks/work_precision/charts.sh writes.

    /usr/bin/python3 benchmarks/peer/peer_table.py [benchmarks/work_precision/paper.csv] [--eccentricity 0.5]

paper.csv holds `ogive bench` rows (two header lines: the CVODE methods and auto, then the quadrature
method) and then benchmarks/peer/scipy_peer.py's rows (a header starting with `curve`). For each solve_bvp
tolerance, on the scene of the given eccentricity, the table gives solve_bvp's error (the larger of
H/V's and the profile's) and time, and for each ogive method (the closed form as auto chose it, the
quadrature method, raw Adams single shooting) the fastest run whose H/V and profile errors are both no
larger than solve_bvp's, with its time, its error and the ratio of the times ("-" if none is). Then,
over every scene and tolerance, the range of those ratios per method.
"""
import argparse
import csv
import io
import sys


def sections(path):
    """The CSV's blocks, each a list of dict rows under its own header line."""
    blocks, lines = [], []
    with open(path) as f:
        for line in f:
            if line.startswith(("scene,", "curve,")) and lines:
                blocks.append(lines)
                lines = []
            lines.append(line)
    if lines:
        blocks.append(lines)
    return [list(csv.DictReader(io.StringIO("".join(b)))) for b in blocks]


def duration(seconds):
    return f"{seconds * 1e6:.3g} µs" if seconds < 1e-3 else f"{seconds * 1e3:.3g} ms"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="?", default="benchmarks/work_precision/paper.csv")
    parser.add_argument("--eccentricity", type=float, default=0.5)
    opts = parser.parse_args()

    ogive, peer = [], []
    for block in sections(opts.csv):
        (peer if block and "curve" in block[0] else ogive).extend(block)
    if not peer:
        sys.exit(f"peer_table.py: {opts.csv} has no solve_bvp rows (benchmarks/peer/scipy_peer.py)")

    def err(row):
        return max(float(row["error_H_over_V"]), float(row["error_profile"]))

    methods = {
        "closed form (auto)": lambda r: r["method"] == "auto" and r["chosen_method"] == "closed-form",
        "quadrature": lambda r: r["method"] == "quadrature",
        "shooting, Adams, raw": lambda r: r["method"] == "shooting" and r["integrator"] == "adams",
    }
    ratios = {name: [] for name in methods}
    table = []
    for p in peer:
        if p["status"] != "success":
            continue
        e = float(p["eccentricity"])
        line = [p["rtol"], f"{err(p):.1e}", duration(float(p["median_seconds"]))]
        for name, chosen in methods.items():
            fits = [r for r in ogive if float(r["eccentricity"]) == e and chosen(r) and r["error_H_over_V"]
                    and float(r["error_H_over_V"]) <= float(p["error_H_over_V"])
                    and float(r["error_profile"]) <= float(p["error_profile"])]
            if not fits:
                line += ["-", "-"]
                continue
            best = min(fits, key=lambda r: float(r["median_seconds"]))
            ratio = float(p["median_seconds"]) / float(best["median_seconds"])
            ratios[name].append(ratio)
            line += [f"{duration(float(best['median_seconds']))}, {err(best):.1e}", f"{ratio:.0f}x"]
        if e == opts.eccentricity:
            table.append(line)

    print("| solve_bvp tol | its error | its time | " + " | ".join(f"ogive {n} | ratio" for n in methods) + " |")
    print("|---" * (3 + 2 * len(methods)) + "|")
    for line in table:
        print("| " + " | ".join(line) + " |")
    print()
    for name, values in ratios.items():
        if values:
            print(f"{name}: {min(values):.0f} to {max(values):.0f} times faster over {len(values)} scene-tolerance pairs")


if __name__ == "__main__":
    main()
