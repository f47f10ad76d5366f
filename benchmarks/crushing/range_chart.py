#!/usr/bin/python3
"""The admissible thrust range against the compressive strength, for the material-strength guide.

For the semicircle (t/L = 0.08) and a flat segmental arch (rise L/8, t/L = 0.05), both L = 10 m and
rho = 2000 kg/m^3 under their own weight: the strength f_c* at which the arch just stands (bisection on
ogive limit's status, to 1e-6 relative), then H_min / V and H_max / V from f_c* to 10^4 rho g L. Writes
benchmarks/crushing/range.csv and docs/charts/crushing-range.{png,svg} (gnuplot).

Run from the repository's top after the build:  /usr/bin/python3 benchmarks/crushing/range_chart.py
"""
import csv
import io
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
OGIVE = os.path.join(ROOT, "build", "ogive")
RHO_G_L = 2000 * 9.81 * 10

ARCHES = {
    "semicircle": ["--curve", "semicircular", "--thickness-ratio", "0.08"],
    "segmental": ["--curve", "segmental", "--rise-ratio", "0.125", "--thickness-ratio", "0.05"],
}


def limit(arch, f_c):
    args = [OGIVE, "limit", "--span", "10", "--density", "2000", *ARCHES[arch], "--columns",
            "status,H_min_over_V,H_max_over_V,thickness_min_ratio"]
    if math.isfinite(f_c):
        args += ["--compressive-strength", repr(f_c)]
    out = subprocess.run(args, capture_output=True, text=True).stdout
    return next(csv.DictReader(io.StringIO(out)))


def just_standing(arch):
    lo, hi = 0.1 * RHO_G_L, 1e4 * RHO_G_L
    assert limit(arch, lo)["status"] == "inadmissible" and limit(arch, hi)["status"] == "success"
    while hi - lo > 1e-6 * hi:
        mid = math.sqrt(lo * hi)
        if limit(arch, mid)["status"] == "success":
            hi = mid
        else:
            lo = mid
    return hi


def main():
    rows = []
    for arch in ARCHES:
        star = just_standing(arch)
        ratios = [star * (1 + d) for d in (0, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1)]
        ratios += [star * 10 ** (k / 8) for k in range(2, 40) if star * 10 ** (k / 8) <= 1e4 * RHO_G_L]
        for f_c in ratios + [math.inf]:
            r = limit(arch, f_c)
            rows.append({"arch": arch, "compressive_strength_over_rho_g_L": f_c / RHO_G_L, "status": r["status"],
                         "H_min_over_V": r["H_min_over_V"], "H_max_over_V": r["H_max_over_V"],
                         "thickness_min_ratio": r["thickness_min_ratio"]})
        print(f"{arch}: just stands at f_c = {star / RHO_G_L:.5g} rho g L ({star / 1e6:.4g} MPa)")
    with open(os.path.join(HERE, "range.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    charts = os.path.join(ROOT, "docs", "charts")
    data = {}
    for arch in ARCHES:
        path = os.path.join(HERE, f"{arch}.dat")
        with open(path, "w") as f:
            for r in rows:
                if r["arch"] == arch and math.isfinite(r["compressive_strength_over_rho_g_L"]):
                    f.write(f"{r['compressive_strength_over_rho_g_L']} {r['H_min_over_V']} {r['H_max_over_V']}\n")
        data[arch] = path
    heyman = {a: next(r for r in rows if r["arch"] == a and math.isinf(r["compressive_strength_over_rho_g_L"]))
              for a in ARCHES}
    for term, ext in (("pngcairo size 900,420", "png"), ("svg size 900,420", "svg")):
        panels = ""
        for arch, title in (("semicircle", "semicircle, t/L 0.08"), ("segmental", "segmental, rise L/8, t/L 0.05")):
            h = heyman[arch]
            panels += f"""set title '{title}'
plot '{data[arch]}' using 1:2 with linespoints pt 7 ps 0.5 lw 2 title 'H_min / V', \\
     '' using 1:3 with linespoints pt 7 ps 0.5 lw 2 title 'H_max / V', \\
     {h['H_min_over_V']} with lines dt 2 lc rgb 'gray' title 'infinite strength', \\
     {h['H_max_over_V']} with lines dt 2 lc rgb 'gray' notitle
"""
        script = f"""set terminal {term}
set output '{charts}/crushing-range.{ext}'
set termoption noenhanced
set multiplot layout 1,2
set logscale x
set grid
set key center right
set xlabel 'compressive strength f_c / (rho g L)'
set ylabel 'admissible H / V'
{panels}unset multiplot
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
    for path in data.values():
        os.remove(path)


if __name__ == "__main__":
    sys.exit(main())
