#!/usr/bin/env bash
# The arch under a horizontal acceleration by limit analysis: the collapse acceleration a_c against t/R
# for the semicircle and two pointed arches (eccentricity 0.25 and 0.5, R = (0.5 + eps) L), and the
# thinnest semicircle that stands a given acceleration (radial and vertical joints), as
# docs/figures/earthquake-limit.png. From the repository's top, after the build: bash
# benchmarks/limit/acceleration.sh [OGIVE] (needs gnuplot: bash .ci/install_deps.sh --charts).
set -euo pipefail
cd "$(dirname "$0")/../.."
ogive=${1:-./build/ogive}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for eps in 0 0.25 0.5; do
  "$ogive" limit --eccentricity "$eps" --thickness-ratio 0.03:0.16:53 \
    --columns eccentricity,thickness_ratio,horizontal_load_factor |
    awk -F, -v eps="$eps" 'NR > 1 && $4 != "" { print $3 / (0.5 + eps), $4 }' >"$work/ac-$eps.dat"
done
for joints in radial vertical; do
  "$ogive" limit --eccentricity 0 --thickness-ratio 0.15 --joints "$joints" --horizontal-acceleration 0:0.4:41 \
    --columns horizontal_acceleration,thickness_min_ratio |
    awk -F, 'NR > 1 && $3 != "" { print $2, 2 * $3 }' >"$work/tmin-$joints.dat"
done
gnuplot <<GNUPLOT
set terminal pngcairo size 1200,500 font "DejaVu Sans,11"
set output "docs/figures/earthquake-limit.png"
set multiplot layout 1,2
set grid
set key top left
set xlabel "t / R"
set ylabel "collapse acceleration a_c / g"
set title "a_c against thickness (radial joints, voussoir weights)"
plot "$work/ac-0.dat" with lines lw 2 title "semicircle", \
     "$work/ac-0.25.dat" with lines lw 2 title "pointed, eccentricity 0.25", \
     "$work/ac-0.5.dat" with lines lw 2 title "equilateral (eccentricity 0.5)"
set xlabel "horizontal acceleration a / g"
set ylabel "t_{min} / R"
set title "the thinnest semicircle that stands a"
plot "$work/tmin-radial.dat" with lines lw 2 title "radial joints", \
     "$work/tmin-vertical.dat" with lines lw 2 title "vertical joints"
unset multiplot
GNUPLOT
echo "wrote docs/figures/earthquake-limit.png"
