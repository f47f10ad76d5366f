#!/usr/bin/env python3
"""The cracking arch along support spreading: for the pointed family at t/L = 0.06, 0.08,
0.10, H/V of the no-tension model against d/L from 1e-6 to 1e-2 (50 log-spaced movements and d = 0),
the limit analysis' minimum thrust of the same arch (--weight axis, this model's convention) and where
the curve comes within 10, 5 and 2 % of it; the paper's DEM residuals beside them. Prints a markdown
table and writes docs/figures/cracking.png (gnuplot), with the time of each 51-point curve.

    /usr/bin/python3 benchmarks/cracking/cracking_study.py [OGIVE]
"""
import csv
import io
import subprocess
import sys
import time

OGIVE = sys.argv[1] if len(sys.argv) > 1 else "build/ogive"
ECCENTRICITIES = [0.0, 0.25, 0.5]
THICKNESSES = [0.06, 0.08, 0.10]
MOVEMENTS = [0.0] + [10 ** (-6 + 4 * i / 49) for i in range(50)]
DEM = {(0.06, 0.0): "0.40", (0.06, 0.5): "0.23", (0.10, 0.0): "0.30", (0.10, 0.5): "0.17"}


def run(args):
    out = subprocess.run([OGIVE] + args, capture_output=True, text=True)
    if out.returncode not in (0, 3):
        sys.exit(f"cracking_study.py: {' '.join(args)}: {out.stderr.strip()}")
    return list(csv.DictReader(io.StringIO(out.stdout)))


rows, curves = [], []
for t in THICKNESSES:
    for eps in ECCENTRICITIES:
        limit = run(["limit", "--weight", "axis", "--eccentricity", str(eps), "--thickness-ratio", str(t),
                     "--columns", "H_min_over_V,status"])[0]
        floor = float(limit["H_min_over_V"]) if limit["status"] == "success" else float("nan")
        d_list = ",".join(f"{d:.6g}" for d in MOVEMENTS)
        t0 = time.perf_counter()
        curve = run(["thrust", "--section", "no-tension", "--eccentricity", str(eps), "--thickness-ratio", str(t),
                     "--support-displacement-ratio", d_list, "--columns",
                     "support_displacement_ratio,status,H_over_V"])
        seconds = time.perf_counter() - t0
        ok = [r for r in curve if r["status"] == "success"]
        hv = [(float(r["support_displacement_ratio"]), float(r["H_over_V"])) for r in ok]
        within = {}
        for pct in (10, 5, 2):
            hit = [d for d, h in hv if d > 0 and h <= floor * (1 + pct / 100)]
            within[pct] = ("<= 1e-6" if min(hit) <= MOVEMENTS[1] else f"{min(hit):.2g}") if hit else "> 1e-2"
        linear = run(["thrust", "--eccentricity", str(eps), "--thickness-ratio", str(t), "--columns", "H_over_V"])[0]
        h0 = hv[0][1] if hv and hv[0][0] == 0 else float("nan")
        rows.append((t, eps, float(linear["H_over_V"]), h0, hv[-1][1] if hv else float("nan"), floor, within,
                     len(ok), len(curve), seconds))
        curves.append((t, eps, hv, floor))

print("| t/L | eps | linear H/V (d = 0) | no-tension H/V, d = 0 | at d/L = 1e-2 | minimum thrust (limit, axis) | "
      "within 10 % at d/L | 5 % | 2 % | success | time (51 points) | DEM residual (paper) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for t, eps, lin, h0, hend, floor, within, n_ok, n, seconds in rows:
    dem = DEM.get((t, eps), "")
    print(f"| {t} | {eps} | {lin:.4f} | {h0:.4f} | {hend:.4f} | {floor:.4f} | {within[10]} | {within[5]} | "
          f"{within[2]} | {n_ok}/{n} | {seconds * 1000:.0f} ms | {dem} |")

with open("/tmp/cracking.dat", "w") as f:
    for t, eps, hv, floor in curves:
        for d, h in hv:
            if d > 0:
                f.write(f"{d} {h}\n")
        f.write("\n\n")
titles = " ".join(f'"t/L {t}, eps {eps}"' for t, eps, _, _ in curves)
floors = "; ".join(f"set arrow from 1e-6,{fl} to 1e-2,{fl} nohead dt 3 lc {i + 1}"
                   for i, (_, _, _, fl) in enumerate(curves))
gp = f"""
set terminal pngcairo size 1000,640 font ',11'
set output 'docs/figures/cracking.png'
set logscale x
set format x '10^{{%T}}'
set xlabel 'outward movement of each springing d / L'
set ylabel 'H / V'
set title 'The no-tension arch along support spreading; dotted: the limit analysis minimum thrust (weight on the axis)' noenhanced
set key outside right
set grid
{floors}
array t[{len(curves)}] = [{titles.replace('" "', '", "')}]
plot for [i=0:{len(curves) - 1}] '/tmp/cracking.dat' index i using 1:2 with lines lw 2 lc i+1 title t[i+1]
"""
subprocess.run(["gnuplot"], input=gp, text=True, check=True)
print("\nwrote docs/figures/cracking.png", file=sys.stderr)
