#!/usr/bin/env bash
# docs/figures/spreading-path.png: H/V of the semicircle against the span's increase, from d = 0 to
# collapse, at three thicknesses (`ogive spread --path`; a few seconds):
#
#   bash docs/figures/make_spreading_figure.sh [OGIVE]        # OGIVE defaults to build/ogive
#
# Left, on a logarithmic axis of the movement: the cracking arch (no-tension section) falling from the
# elastic thrust to the plateau. Right, on a linear one: the mechanism of rigid voussoirs from the
# plateau (the minimum thrust) to collapse. Needs gnuplot (bash .ci/install_deps.sh --charts).
set -euo pipefail
cd "$(dirname "$0")/../.."
ogive=${1:-build/ogive}
[[ -x $ogive ]] || { echo "make_spreading_figure.sh: no ogive executable at '$ogive' (build first)" >&2; exit 2; }
command -v gnuplot >/dev/null || { echo "make_spreading_figure.sh: no gnuplot" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
thicknesses=(0.065 0.075 0.085)
for t in "${thicknesses[@]}"; do
  "$ogive" spread --curve semicircular --thickness-ratio "$t" --path --columns part,spread_ratio,H_over_V \
    >"$tmp/path-$t.csv"
  grep ',cracking,' "$tmp/path-$t.csv" | awk -F, '$3 > 0 {print $3, $4}' >"$tmp/cracking-$t.dat"
  grep ',elastic,' "$tmp/path-$t.csv" | awk -F, '{print 1e-7, $4}' >"$tmp/elastic-$t.dat"
  grep ',mechanism,' "$tmp/path-$t.csv" | awk -F, '{print $3, $4}' >"$tmp/mechanism-$t.dat"
done
colors=("#1f77b4" "#d62728" "#2ca02c")
left="" right=""
for i in "${!thicknesses[@]}"; do
  t=${thicknesses[$i]} c=${colors[$i]}
  left+="'$tmp/cracking-$t.dat' with lines lw 2 lc rgb '$c' title 't/L = $t', "
  left+="'$tmp/elastic-$t.dat' with points pt 7 ps 1.2 lc rgb '$c' notitle, "
  right+="'$tmp/mechanism-$t.dat' with lines lw 2 lc rgb '$c' title 't/L = $t', "
done
gnuplot <<GNUPLOT
set terminal pngcairo size 1100,450 font 'sans,11'
set output 'docs/figures/spreading-path.png'
set datafile separator ' '
set multiplot layout 1,2
set grid
set ylabel 'H / V'
set yrange [0.32:0.48]
set title 'cracking arch: elastic thrust (dot) down to the plateau'
set xlabel 'span increase / L (both springings moving)'
set logscale x
set format x '10^{%L}'
set xrange [1e-7:0.03]
plot ${left%, }
unset logscale x
set format x '%g'
set xrange [0:*]
set title 'rigid voussoirs: from the plateau up to collapse'
plot ${right%, }
unset multiplot
GNUPLOT
echo "make_spreading_figure.sh: wrote docs/figures/spreading-path.png"
