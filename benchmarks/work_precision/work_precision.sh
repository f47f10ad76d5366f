#!/usr/bin/env bash
# Work-precision charts from `ogive bench` and/or benchmarks/peer/scipy_peer.py CSV output.
#
#   benchmarks/work_precision/work_precision.sh INPUT.csv OUTPUT_PREFIX [TITLE]
#
# Writes OUTPUT_PREFIX.png and OUTPUT_PREFIX.svg: log-log, x = error_H_over_V (relative error of H/V
# against the closed form), y = median_seconds.  One colour/mark per (method, integrator); one polyline
# per scene inside a series (dash type = scene), ordered by rtol.  Errors below 1e-17 (the closed
# form's 0) are drawn at 1e-17, marked by a dotted line and a key entry.  Rows whose status is not
# "success" (or "unverified", a raw --no-verify run) are drawn as red crosses ("failed / flagged runs")
# and are not joined to their series.
# If the error_profile column has finite values anywhere, also writes OUTPUT_PREFIX-profile.{png,svg}
# with x = error_profile.
#
# The input may be several CSVs concatenated: every line whose first field is "scene" (ogive) or "curve"
# (the scipy peer) is a header
# and (re)defines the columns by name, so blocks with different columns (e.g. with and without
# error_profile) mix fine.  Only the last column, message, may hold a quoted comma; the columns read
# here come before it.
#
# Needs: bash, awk (mawk or gawk), sort, gnuplot >= 5.4 (Debian: apt-get install -y gnuplot-nox).
set -euo pipefail

prog=${0##*/}
usage() { echo "usage: $prog INPUT.csv OUTPUT_PREFIX [TITLE]" >&2; exit 2; }
[[ $# -eq 2 || $# -eq 3 ]] || usage
input=$1
prefix=$2
[[ -r $input && -f $input ]] || { echo "$prog: cannot read '$input'" >&2; exit 2; }
[[ -n $prefix ]] || usage
title=${3:-"Work-precision: ${input##*/}"}
command -v gnuplot >/dev/null || { echo "$prog: gnuplot not found (apt-get install -y gnuplot-nox)" >&2; exit 1; }
outdir=$(dirname -- "$prefix")
[[ -d $outdir && -w $outdir ]] || { echo "$prog: output directory '$outdir' is not writable" >&2; exit 2; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/work_precision.XXXXXX")
trap 'rm -rf -- "$tmp"' EXIT

readonly CLAMP=1e-17

# 1. (Two passes over the input: the first only reads the header lines.)  Normalise every data row to TAB-separated fields:
#    series_no  series_label  scene_no  rtol  ok  err  eprof  seconds
#    (err/eprof: clamped number, or "nan" when missing/non-finite).  Scene and series numbers follow
#    the order of first appearance.  Also writes scenes.tsv: scene_no, label of the varying columns.
awk -F',' -v OFS='\t' -v clamp="$CLAMP" -v tmp="$tmp" -v prog="$prog" '
function isnum(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
function absval(x) { return x < 0 ? -x : x }
function cleanerr(s,   v) {
  if (!isnum(s)) return "nan"
  v = absval(s + 0)
  if (v < clamp) { nclamped++; return clamp }
  return v
}
BEGIN { nseries = 0; nscenes = 0; nrows = 0; nclamped = 0; nheaders = 0 }
{ sub(/\r$/, "") }
/^[ \t]*$/ { next }
# first pass over the file: which scene columns (those before "method") do all header blocks share?
NR == FNR {
  if ($1 == "curve" || $1 == "scene") {
    nheaders++
    for (i = 1; i <= NF && $i != "method"; i++) ncommon[$i]++
  }
  next
}
$1 == "curve" || $1 == "scene" {
  delete col; nscene_cols = 0
  for (i = 1; i <= NF; i++) col[$i] = i
  for (k = split("method rtol status error_H_over_V median_seconds", need, " "); k > 0; k--)
    if (!(need[k] in col)) { printf "%s: line %d: header lacks column %s\n", prog, NR, need[k] > "/dev/stderr"; bad = 1; exit 2 }
  # scene columns: everything before "method"
  # scene columns: those before "method" that every header block has (a column only some blocks
  # carry, e.g. a derived rise_ratio, must not split one scene into two)
  for (i = 1; i < col["method"]; i++) if (ncommon[$i] == nheaders) scene_col[++nscene_cols] = $i
  header = 1
  next
}
!header { printf "%s: line %d: data before any header line (first field \"scene\" or \"curve\")\n", prog, NR > "/dev/stderr"; bad = 1; exit 2 }
{
  method = $(col["method"])
  integ = ("integrator" in col) ? $(col["integrator"]) : "none"
  label = method (integ != "" && integ != "none" ? " (" integ ")" : "")
  if (!(label in series)) { series[label] = ++nseries }
  key = ""
  for (i = 1; i <= nscene_cols; i++) {
    name = scene_col[i]; v = $(col[name]); if (isnum(v)) v = sprintf("%.12g", v + 0); key = key name "=" v ";"
    if (!((name SUBSEP v) in seen_val)) { seen_val[name SUBSEP v] = 1; nvals[name]++ }
    if (!(name in colorder)) { colorder[name] = ++ncolnames; colname[ncolnames] = name }
  }
  if (!(key in scene)) { scene[key] = ++nscenes; scenekey[nscenes] = key }
  t = $(col["median_seconds"])
  if (!isnum(t) || t + 0 <= 0) { nbadtime++; next }
  err = cleanerr($(col["error_H_over_V"]))
  eprof = ("error_profile" in col) ? cleanerr($(col["error_profile"])) : "nan"
  rt = $(col["rtol"]); if (!isnum(rt)) rt = 0
  # A raw (--no-verify) run that ran to the end says "unverified": drawn as a point of its series.
  st = $(col["status"]); ok = (st == "success" || st == "unverified") ? 1 : 0
  print series[label], label, scene[key], rt + 0, ok, err, eprof, t + 0
  nrows++
}
END {
  if (bad) exit 2
  if (nrows == 0) { printf "%s: no plottable data rows\n", prog > "/dev/stderr"; exit 2 }
  if (nbadtime) printf "%s: note: %d row(s) without a positive median_seconds skipped\n", prog, nbadtime > "/dev/stderr"
  # scene labels: only the columns that vary between scenes
  for (s = 1; s <= nscenes; s++) {
    n = split(scenekey[s], parts, ";"); lab = ""
    for (j = 1; j < n; j++) {
      eq = index(parts[j], "="); name = substr(parts[j], 1, eq - 1); v = substr(parts[j], eq + 1)
      if (nvals[name] > 1) {
        short = name
        if (name == "eccentricity") short = "eps"
        else if (name == "thickness_ratio") short = "t/L"
        else if (name == "support_displacement_ratio") short = "d/L"
        lab = lab (lab == "" ? "" : ", ") short "=" v
      }
    }
    print s, (lab == "" ? "scene " s : lab) > (tmp "/scenes.tsv")
  }
  print nclamped > (tmp "/nclamped")
}' "$input" "$input" > "$tmp/rows.tsv"

# 2. Sort by series, scene, rtol and split into one data file per (chart, series, scene), plus the
#    failed/flagged runs; write the series list and the data ranges.
LC_ALL=C sort -t $'\t' -k1,1n -k3,3n -k4,4g "$tmp/rows.tsv" |
awk -F'\t' -v tmp="$tmp" -v clamp="$CLAMP" '
function upd(c, x, y) {
  if (!(c in xmin) || x < xmin[c]) xmin[c] = x; if (!(c in xmax) || x > xmax[c]) xmax[c] = x
  if (!(c in ymin) || y < ymin[c]) ymin[c] = y; if (!(c in ymax) || y > ymax[c]) ymax[c] = y
}
{
  if (!($1 in lab)) { lab[$1] = $2; print $1 "\t" $2 > (tmp "/series.tsv") }
  # chart "hv": x = field 6; chart "prof": x = field 7
  for (c = 1; c <= 2; c++) {
    chart = (c == 1) ? "hv" : "prof"; x = (c == 1) ? $6 : $7
    if (x == "nan") { if ($5 == 0) nofail[chart]++; continue }
    x += 0
    if (x <= clamp * 1.000001) nclamp[chart]++
    upd(chart, x, $8)
    if ($5 == 1) {
      f = tmp "/" chart "_" $1 "_" $3 ".dat"
      if (!(f in files)) { files[f] = 1; print chart "\t" $1 "\t" $3 "\t" f > (tmp "/files.tsv") }
      print x "\t" $8 "\t" $4 > f
    } else {
      print x "\t" $8 "\t" $4 > (tmp "/" chart "_failed.dat"); nfail[chart]++
    }
  }
}
END {
  for (c = 1; c <= 2; c++) {
    chart = (c == 1) ? "hv" : "prof"
    if (chart in xmin)
      printf "%s %.6g %.6g %.6g %.6g %d %d %d\n", chart, xmin[chart], xmax[chart], ymin[chart], ymax[chart],
             nfail[chart] + 0, nofail[chart] + 0, nclamp[chart] + 0 > (tmp "/ranges.txt")
  }
}'
touch "$tmp/files.tsv" "$tmp/ranges.txt"

if gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1; then
  png_term="pngcairo enhanced size 1300,780 font 'sans,12' background rgb 'white'"
else
  png_term="png enhanced size 1300,780 font 'sans,11' background rgb 'white'"
fi
svg_term="svg enhanced size 1300,780 dynamic font 'sans,12' background rgb 'white'"

gp_quote() { local s=${1//\'/\'\'}; printf "'%s'" "$s"; }

colors=('#1f77b4' '#2ca02c' '#ff7f0e' '#9467bd' '#17becf' '#8c564b' '#e377c2' '#7f7f7f' '#bcbd22' '#000080')
ptypes=(7 5 9 11 13 15 4 6 8 10)
nscenes=$(wc -l < "$tmp/scenes.tsv")

# 3. One chart: $1 = hv|prof, $2 = output prefix, $3 = x label, $4 = title
chart() {
  local kind=$1 out=$2 xlabel=$3 ctitle=$4
  local line xmin xmax ymin ymax nfail nofail nclamp
  line=$(awk -v k="$kind" '$1 == k' "$tmp/ranges.txt")
  read -r _ xmin xmax ymin ymax nfail nofail nclamp <<< "$line"
  # pad by a quarter decade, then round out to whole decades
  local range
  range=$(awk -v a="$xmin" -v b="$xmax" -v c="$ymin" -v d="$ymax" 'function fl(x){return x==int(x)?x:(x<0?int(x)-1:int(x))}
    function ce(x){return -fl(-x)}
    function l(x){return log(x)/log(10)}
    BEGIN { x0=fl(l(a)-0.25); x1=ce(l(b)+0.25); y0=fl(l(c)-0.25); y1=ce(l(d)+0.25);
            printf "%d %d %d %d", x0, x1, y0, y1 }')
  local x0 x1 y0 y1; read -r x0 x1 y0 y1 <<< "$range"
  local xstep=1; (( x1 - x0 > 10 )) && xstep=2
  local ystep=1; (( y1 - y0 > 10 )) && ystep=2

  local gp="$tmp/$kind.gp" plots=() s
  {
    echo "set title $(gp_quote "$ctitle") noenhanced font ',14'"
    echo "set logscale xy"
    echo "set xrange [1e$x0:1e$x1]"
    echo "set yrange [1e$y0:1e$y1]"
    echo "set xtics 10**$xstep format '10^{%T}'"
    echo "set ytics 10**$ystep format '10^{%T}'"
    echo "set mxtics 10; set mytics 10"
    echo "set grid xtics ytics lc rgb '#d0d0d0' lw 1, lc rgb '#f0f0f0'"
    echo "set xlabel $(gp_quote "$xlabel") noenhanced"
    echo "set ylabel 'median time per solve [s]'"
    echo "set key outside right top vertical Left reverse noenhanced spacing 1.2 samplen 3 box lc rgb '#b0b0b0'"
    echo "set border lw 1.2"
    echo "set lmargin 10; set bmargin 4"
    # series key entries (colour and mark), then scene entries (dash type), then the extras
    local sno slabel
    while IFS=$'\t' read -r sno slabel; do
      local ci=$(( (sno - 1) % ${#colors[@]} ))
      plots+=("keyentry with linespoints lw 2 ps 1.3 lc rgb '${colors[ci]}' pt ${ptypes[ci]} title $(gp_quote "$slabel")")
    done < "$tmp/series.tsv"
    if (( nscenes > 1 )); then
      local scno sclabel
      while IFS=$'\t' read -r scno sclabel; do
        local dt=$(( (scno - 1) % 5 + 1 ))
        plots+=("keyentry with lines lw 2 dt $dt lc rgb '#404040' title $(gp_quote "$sclabel")")
      done < "$tmp/scenes.tsv"
    fi
    local f ser sc
    while IFS=$'\t' read -r ckind ser sc f; do
      [[ $ckind == "$kind" ]] || continue
      local ci=$(( (ser - 1) % ${#colors[@]} )) dt=$(( (sc - 1) % 5 + 1 ))
      plots+=("'$f' using 1:2 with linespoints lw 2 ps 1.3 dt $dt lc rgb '${colors[ci]}' pt ${ptypes[ci]} notitle")
    done < "$tmp/files.tsv"
    if [[ -s $tmp/${kind}_failed.dat ]]; then
      local ft="failed / flagged runs"
      (( nofail > 0 )) && ft="$ft; $nofail without a finite error not drawn"
      plots+=("'$tmp/${kind}_failed.dat' using 1:2 with points pt 2 ps 2.2 lw 3 lc rgb '#d62728' title $(gp_quote "$ft")")
    elif (( nofail > 0 )); then
      plots+=("keyentry with points pt 2 ps 2.2 lw 3 lc rgb '#d62728' title $(gp_quote "failed / flagged runs: $nofail without a finite error, not drawn")")
    fi
    if (( nclamp > 0 )); then
      echo "set arrow from $CLAMP, graph 0 to $CLAMP, graph 1 nohead dt 3 lw 1.5 lc rgb '#808080' back"
      plots+=("keyentry with lines dt 3 lw 1.5 lc rgb '#808080' title 'error 0 drawn at $CLAMP'")
    fi
    local joined="" p
    for p in "${plots[@]}"; do joined+="${joined:+, \\
  }$p"; done
    echo "set terminal $png_term"
    echo "set output $(gp_quote "$out.png")"
    echo "plot $joined"
    echo "set terminal $svg_term"
    echo "set output $(gp_quote "$out.svg")"
    echo "replot"
    echo "unset output"
  } > "$gp"
  gnuplot "$gp"
  echo "$prog: wrote $out.png and $out.svg" >&2
}

if ! grep -q '^hv ' "$tmp/ranges.txt"; then
  echo "$prog: no row has a finite error_H_over_V: nothing to draw" >&2
  exit 1
fi
chart hv "$prefix" "relative error of H/V against the reference" "$title"
if grep -q '^prof ' "$tmp/ranges.txt"; then
  chart prof "$prefix-profile" "profile error: forces, M in kern units, displacements (README)" "$title (profile)"
else
  echo "$prog: note: no finite error_profile values: no profile chart" >&2
fi
