#!/usr/bin/env bash
# docs/figures/spreading-path.png: H/V of the semicircle and the equilateral arch against the span's
# increase, from d = 0 to collapse, at three thicknesses each (`ogive spread --path`; a few seconds);
# docs/figures/spreading-stage-{semicircle,equilateral}-{0.5,1}.png: the two arches at t/L = 0.075,
# half-way to collapse and at collapse (`ogive draw --spread-stage`, rendered by rsvg-convert):
#
#   bash docs/figures/make_spreading_figure.sh [OGIVE]        # OGIVE defaults to build/ogive
#
# One row per arch. Left, on a logarithmic axis of the movement: the cracking arch (no-tension section) falling from the
# elastic thrust to the plateau. Right, on a linear one: the mechanism of rigid voussoirs from the
# plateau (the minimum thrust) to collapse. Needs gnuplot (bash .ci/install_deps.sh --charts).
set -euo pipefail
cd "$(dirname "$0")/../.."
ogive=${1:-build/ogive}
[[ -x $ogive ]] || { echo "make_spreading_figure.sh: no ogive executable at '$ogive' (build first)" >&2; exit 2; }
for tool in gnuplot rsvg-convert; do
  command -v $tool >/dev/null || { echo "make_spreading_figure.sh: no $tool (bash .ci/install_deps.sh --charts)" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Each arch: its curve options, a label, three thicknesses.
arches=("--curve semicircular" "--eccentricity 0.5")
labels=("semicircle" "equilateral arch")
thicknesses=("0.065 0.075 0.085" "0.05 0.075 0.1")
colors=("#1f77b4" "#d62728" "#2ca02c")
plots=()
for a in 0 1; do
  left="" right=""
  i=0
  for t in ${thicknesses[$a]}; do
    f="$tmp/$a-$t"
    # shellcheck disable=SC2086  # the curve options are two words
    "$ogive" spread ${arches[$a]} --thickness-ratio "$t" --path --columns part,spread_ratio,H_over_V >"$f.csv"
    grep ',cracking,' "$f.csv" | awk -F, '$3 > 0 {print $3, $4}' >"$f-cracking.dat"
    grep ',elastic,' "$f.csv" | awk -F, '{print 1e-7, $4}' >"$f-elastic.dat"
    grep ',mechanism,' "$f.csv" | awk -F, '{print $3, $4}' >"$f-mechanism.dat"
    c=${colors[$i]}
    left+="'$f-cracking.dat' with lines lw 2 lc rgb '$c' title 't/L = $t', "
    left+="'$f-elastic.dat' with points pt 7 ps 1.2 lc rgb '$c' notitle, "
    right+="'$f-mechanism.dat' with lines lw 2 lc rgb '$c' title 't/L = $t', "
    i=$((i + 1))
  done
  plots+=("${left%, }" "${right%, }")
done
gnuplot <<GNUPLOT
set terminal pngcairo size 1100,820 font 'sans,11'
set output 'docs/figures/spreading-path.png'
set datafile separator ' '
set multiplot layout 2,2
set grid
set ylabel 'H / V'
set key top right
set title '${labels[0]}, cracking arch: elastic thrust (dot) down to the plateau'
set xlabel 'span increase / L (both springings moving)'
set logscale x
set format x '10^{%L}'
set xrange [1e-7:0.03]
plot ${plots[0]}
unset logscale x
set format x '%g'
set xrange [0:*]
set title '${labels[0]}, rigid voussoirs: from the plateau up to collapse'
set key top left
plot ${plots[1]}
set key top right
set title '${labels[1]}, cracking arch'
set logscale x
set format x '10^{%L}'
set xrange [1e-7:0.03]
plot ${plots[2]}
unset logscale x
set format x '%g'
set xrange [0:*]
set title '${labels[1]}, rigid voussoirs'
set key top left
plot ${plots[3]}
unset multiplot
GNUPLOT
# The stages: half-way to collapse and at collapse.
for a in 0 1; do
  name=$([[ $a == 0 ]] && echo semicircle || echo equilateral)
  for stage in 0.5 1; do
    # shellcheck disable=SC2086  # the curve options are two words
    "$ogive" draw ${arches[$a]} --thickness-ratio 0.075 --spread-stage $stage --output "$tmp/$name-$stage.svg" >/dev/null
    rsvg-convert --width 560 "$tmp/$name-$stage.svg" -o "docs/figures/spreading-stage-$name-$stage.png"
  done
done
echo "make_spreading_figure.sh: wrote docs/figures/spreading-path.png and spreading-stage-*.png"
