#!/usr/bin/env bash
# The README's pictures, from the commands the README names (about 10 s):
#
#   bash docs/figures/make_figures.sh [OGIVE]        # OGIVE defaults to build/ogive
#
# docs/figures/semicircle.png, equilateral.png (and -limit, with --limit): `ogive draw` (SVG) rendered
# by rsvg-convert;
# docs/figures/influence-line.png: the README's influence line (thrust --point-load-at 0:1:101);
# docs/figures/figure-7.png .. figure-12.png: the paper's Figures 7-12 from the calls of the README's
# table "The paper's figures, one call each", drawn by gnuplot (pngcairo terminal, which gnuplot-nox has).
# Needs gnuplot-nox and librsvg2-bin: bash .ci/install_deps.sh --charts.
set -euo pipefail
cd "$(dirname "$0")/../.."
ogive=${1:-build/ogive}
[[ -x $ogive ]] || { echo "figures.sh: no ogive executable at '$ogive' (build first)" >&2; exit 2; }
for tool in gnuplot rsvg-convert; do
  command -v $tool >/dev/null || { echo "figures.sh: $tool not found (bash .ci/install_deps.sh --charts)" >&2; exit 2; }
done
out=docs/figures
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The arches with their thrust lines.
"$ogive" draw --curve semicircular --output "$tmp/semicircle.svg" >/dev/null
"$ogive" draw --eccentricity 0.5 --output "$tmp/equilateral.svg" >/dev/null
"$ogive" draw --curve semicircular --support-displacement-ratio 0.0001 --output "$tmp/semicircle-spreading.svg" >/dev/null
# With the limit analysis' minimum and maximum thrust lines (t = 0.10 L).
"$ogive" draw --curve semicircular --thickness-ratio 0.1 --limit --output "$tmp/semicircle-limit.svg" >/dev/null
"$ogive" draw --eccentricity 0.5 --thickness-ratio 0.1 --limit --output "$tmp/equilateral-limit.svg" >/dev/null
for f in semicircle equilateral semicircle-spreading semicircle-limit equilateral-limit; do
  rsvg-convert --width 800 "$tmp/$f.svg" -o "$out/$f.png"
done

# blocks X Y KEY... < CSV: the columns X and Y (named as in the header) as gnuplot data, one data set
# (sets separated by two blank lines) per value of the KEY columns, in order of first appearance; each
# set's key goes to $tmp/keys, one a line. An empty field (no number) becomes NaN, which gnuplot skips.
blocks() {
  local x=$1 y=$2; shift 2
  awk -F, -v x="$x" -v y="$y" -v keys="$*" -v keyfile="$tmp/keys" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; nk = split(keys, k, " "); next }
    {
      key = ""; for (i = 1; i <= nk; i++) key = key (i > 1 ? ", " : "") k[i] " " $(col[k[i]])
      if (!(key in data)) order[n++] = key
      data[key] = data[key] $(col[x]) " " ($(col[y]) == "" ? "NaN" : $(col[y])) "\n"
    }
    END { for (i = 0; i < n; i++) { printf "%s%s", (i > 0 ? "\n\n" : ""), data[order[i]]; print order[i] > keyfile } }'
}

# For the profiles: one data set per scene, e against s/S over the left half (station s <= S).
half_blocks() {
  awk -F, -v keys="$*" -v keyfile="$tmp/keys" '
    function flush(  i, S) { if (n == 0) return; S = s[n - 1] / 2
      if (sets++ > 0) printf "\n\n"
      for (i = 0; i < n && s[i] <= S * (1 + 1e-12); i++) print s[i] / S, e[i]
      n = 0 }
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; nk = split(keys, k, " "); next }
    {
      key = ""; for (i = 1; i <= nk; i++) key = key (i > 1 ? ", " : "") k[i] " " $(col[k[i]])
      if (key != last) { flush(); print key > keyfile; last = key }
      s[n] = $(col["s"]); e[n] = $(col["thrust_eccentricity"]) == "" ? "NaN" : $(col["thrust_eccentricity"]); n++
    }
    END { flush() }'
}

# plot NAME TITLE XLABEL YLABEL [gnuplot settings]: draws $tmp/NAME.dat, one line per data set titled
# by $tmp/keys, into docs/figures/NAME.png.
plot() {
  local name=$1 title=$2 xlabel=$3 ylabel=$4 extra=${5:-}
  local n; n=$(wc -l < "$tmp/keys")
  local titles; titles=$(awk '{ gsub(/support_displacement_ratio/, "d/L"); gsub(/thickness_ratio/, "t/L"); gsub(/youngs_modulus/, "E (Pa)")
                  gsub(/_/, " "); printf("%s\"%s\"", (NR > 1 ? ", " : ""), $0) }' "$tmp/keys")
  gnuplot <<GP
set terminal pngcairo enhanced size 900,640 font 'sans,11' background rgb 'white'
set output "$out/$name.png"
set datafile missing "NaN"
set title "$title" noenhanced
set xlabel "$xlabel" noenhanced
set ylabel "$ylabel" noenhanced
set grid
set key below noenhanced
array t[$n] = [$titles]
$extra
plot for [i=0:$((n - 1))] '$tmp/$name.dat' index i using 1:2 with linespoints lw 2 pt 7 ps 0.6 title t[i+1]
GP
}

"$ogive" thrust --youngs-modulus 1e8,1e9,1e10,1e11,1e12 --poisson-ratio 0:0.5:6 --all-columns | blocks poisson_ratio H_over_V youngs_modulus > "$tmp/figure-7.dat"
plot figure-7 "Figure 7: H/V of the semicircle (t = 0.08 L) against nu, for E = 1e8 .. 1e12 Pa (the lines coincide)" \
  "Poisson's ratio nu" "H/V" "set yrange [0.39:0.40]"
rm "$tmp/keys"
"$ogive" thrust --eccentricity 0:1:11 --all-columns | blocks eccentricity H_over_V thickness_ratio > "$tmp/figure-8.dat"
plot figure-8 "Figure 8: H/V against eccentricity, t = 0.08 L, fixed supports" "eccentricity (0 semicircle, 0.5 equilateral)" "H/V" "set yrange [0:*]"
rm "$tmp/keys"
"$ogive" thrust --thickness-ratio 0.06,0.08,0.10,0.15,0.20 --eccentricity 0:1:11 --all-columns | blocks eccentricity H_over_V thickness_ratio > "$tmp/figure-9.dat"
plot figure-9 "Figure 9: H/V against eccentricity and thickness, fixed supports" "eccentricity" "H/V" "set yrange [0:*]"
rm "$tmp/keys"
"$ogive" thrust --eccentricity 0,0.25,0.5,0.75,1 --support-displacement-ratio 0:0.0003:7 --all-columns | blocks support_displacement_ratio H_over_V eccentricity \
  | awk 'NF == 2 { $1 = $1 * 100 } { print }' > "$tmp/figure-10.dat"
plot figure-10 "Figure 10: H/V against the outward support displacement d, t = 0.08 L" "d/L (%)" "H/V" "set xzeroaxis lw 2"
rm "$tmp/keys"
"$ogive" profile --thickness-ratio 0.08,0.20 --eccentricity 0,0.5,1 --stations 101 --all-columns | half_blocks thickness_ratio eccentricity > "$tmp/figure-11.dat"
plot figure-11 "Figure 11: eccentricity e of the compression, springing (0) to crown (1), fixed supports" "s / S (arc length over the half arch)" "e (% of the kern, t/6)" \
  "set yrange [-600:600]; set ytics 100; set arrow from 0,100 to 1,100 nohead dt 2 lc rgb 'black'; set arrow from 0,-100 to 1,-100 nohead dt 2 lc rgb 'black'"
rm "$tmp/keys"
"$ogive" profile --support-displacement-ratio 0,0.0001,0.0002,0.0003 --stations 101 --all-columns | half_blocks support_displacement_ratio > "$tmp/figure-12.dat"
plot figure-12 "Figure 12: e along the semicircle, t = 0.08 L, outward support displacement d" "s / S (arc length over the half arch)" "e (% of the kern, t/6)" \
  "set yrange [-1000:4000]; set arrow from 0,100 to 1,100 nohead dt 2 lc rgb 'black'; set arrow from 0,-100 to 1,-100 nohead dt 2 lc rgb 'black'"
# The influence line of a point load (the README's call): what the load adds to the self-weight's
# reactions, against where it acts.
"$ogive" thrust --point-load 1e4 --point-load-at 0:1:101 --all-columns > "$tmp/influence.csv"
read -r H0 V0 M0 < <("$ogive" thrust --columns H_left,V_left,M_left | awk -F, 'NR == 2 { print $2, $3, $4 }')
gnuplot <<GP
set terminal pngcairo size 900,560 font ',11'
set output '$out/influence-line.png'
set datafile separator ','
set title "Influence lines: what P = 10 kN/m at x = a L adds to the semicircle's reactions (t = 0.08 L)" noenhanced
set xlabel 'a = x / L'
set ylabel 'added reaction / P  (M: / (P L))'
set grid
set key below
P = 1e4; L = 10
plot '$tmp/influence.csv' using 'point_load_at':((column('H_left') - $H0) / P) with lines lw 2 title 'H (both springings)', \
     '' using 'point_load_at':((column('V_left') - $V0) / P) with lines lw 2 title 'V left', \
     '' using 'point_load_at':((column('V_right') - $V0) / P) with lines lw 2 title 'V right', \
     '' using 'point_load_at':((column('M_left') - $M0) / (P * L)) with lines lw 2 dt 2 title 'M left'
GP
ls "$out"
