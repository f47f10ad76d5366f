#!/usr/bin/env python3
"""The README's limit-analysis tables and chart, from ogive itself (about a minute on 2 cores).

    python3 benchmarks/limit/limit_tables.py [--ogive build/ogive]

Prints the markdown tables (convergence, the paper's comparison, minimum thickness against eccentricity)
and writes benchmarks/limit/{convergence,paper,thickness}.csv and docs/charts/limit-thickness.{png,svg}
(gnuplot, from install-deps.sh --charts).
"""
import argparse
import csv
import io
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def run(ogive, *args):
    out = subprocess.run([ogive, *args], check=True, capture_output=True, text=True).stdout
    return out, list(csv.DictReader(io.StringIO(out)))


def save(name, text):
    path = os.path.join(HERE, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--ogive", default=os.path.join(ROOT, "build", "ogive"))
    ogive = p.parse_args().ogive

    # Convergence under joint refinement.
    print("| joints | eps 0: H_min/V | H_max/V | t_min/L | eps 0.5: H_min/V | H_max/V | t_min/L | eps 1.5: H_min/V | H_max/V | t_min/L |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    text = ""
    for n in (21, 51, 101, 201, 401, 801, 1601, 3201):
        out, rows = run(ogive, "limit", "--eccentricity", "0,0.5,1.5", "--thickness-ratio", "0.1", "--joints-count", str(n))
        text += out if not text else out.split("\n", 1)[1]
        cells = []
        for r in rows:
            cells += [f"{float(r['H_min_over_V']):.6f}", f"{float(r['H_max_over_V']):.6f}", f"{float(r['thickness_min_ratio']):.6f}"]
        print(f"| {n} | " + " | ".join(cells) + " |")
    save("convergence.csv", text)
    print()

    # The paper's comparison: limit range next to the elastic H/V and the DEM residuals.
    dem = {(0.06, 0.0): "0.40", (0.06, 0.5): "0.23", (0.10, 0.0): "0.30", (0.10, 0.5): "0.17"}
    eps = "0,0.25,0.5,0.75,1"
    print("| t/L | eps | H_min/V | H_max/V | elastic H/V (`ogive thrust`) | DEM residual H/V (paper) |")
    print("|---|---|---|---|---|---|")
    text = ""
    for t in (0.06, 0.08, 0.10, 0.15):
        out, limit = run(ogive, "limit", "--eccentricity", eps, "--thickness-ratio", str(t))
        _, elastic = run(ogive, "thrust", "--eccentricity", eps, "--thickness-ratio", str(t))
        text += out if not text else out.split("\n", 1)[1]
        for lr, er in zip(limit, elastic):
            e = float(lr["eccentricity"])
            print(f"| {t} | {e:g} | {float(lr['H_min_over_V']):.3f} | {float(lr['H_max_over_V']):.3f} | "
                  f"{float(er['H_over_V']):.3f} | {dem.get((t, e), '')} |")
    save("paper.csv", text)
    print()

    # Minimum thickness against eccentricity.
    out, rows = run(ogive, "limit", "--eccentricity", "0:1.5:16", "--thickness-ratio", "0.15")
    _, vertical = run(ogive, "limit", "--eccentricity", "0:1.5:16", "--thickness-ratio", "0.15", "--joints", "vertical")
    _, axis = run(ogive, "limit", "--eccentricity", "0:1.5:16", "--thickness-ratio", "0.15", "--weight", "axis")
    save("thickness.csv", out)
    print("| eps | t_min/L radial joints | t_min/L vertical joints | t_min/L radial, axis weight | t_min/R radial |")
    print("|---|---|---|---|---|")
    for r, v, a in zip(rows, vertical, axis):
        e = float(r["eccentricity"])
        t = float(r["thickness_min_ratio"])
        print(f"| {e:g} | {t:.4f} | {float(v['thickness_min_ratio']):.4f} | {float(a['thickness_min_ratio']):.4f} | {t / (0.5 + e):.4f} |")
    charts = os.path.join(ROOT, "docs", "charts")
    os.makedirs(charts, exist_ok=True)
    # The chart on a finer grid: t_min has kinks where the collapse mechanism changes.
    fine = "0:1.5:61"
    _, rows = run(ogive, "limit", "--eccentricity", fine, "--thickness-ratio", "0.15")
    _, vertical = run(ogive, "limit", "--eccentricity", fine, "--thickness-ratio", "0.15", "--joints", "vertical")
    _, axis = run(ogive, "limit", "--eccentricity", fine, "--thickness-ratio", "0.15", "--weight", "axis")
    data = os.path.join(HERE, "thickness-joints.dat")
    with open(data, "w") as f:
        for r, v, a in zip(rows, vertical, axis):
            f.write(f"{r['eccentricity']} {r['thickness_min_ratio']} {v['thickness_min_ratio']} {a['thickness_min_ratio']}\n")
    for term, ext in (("pngcairo size 800,500", "png"), ("svg size 800,500", "svg")):
        script = f"""set terminal {term}
set output '{charts}/limit-thickness.{ext}'
set xlabel 'eccentricity eps (0: semicircle, 0.5: equilateral)'
set ylabel 'minimum thickness t_min / L'
set key bottom right
set termoption noenhanced
set grid
plot '{data}' using 1:2 with lines lw 2 title 'radial joints, true weight', \\
     '' using 1:3 with lines lw 2 title 'vertical joints, true weight', \\
     '' using 1:4 with lines lw 2 title 'radial joints, weight on the axis'
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
    os.remove(data)


if __name__ == "__main__":
    sys.exit(main())
