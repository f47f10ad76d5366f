#!/usr/bin/env bash
# The work-precision data and charts (docs/methods.md, benchmarks/work_precision/README.md), in one run:
#
#   bash benchmarks/work_precision/charts.sh [OGIVE]        # OGIVE defaults to build/ogive
#
# Writes benchmarks/work_precision/{paper,catenary,survey}.csv (ogive bench; the paper's CSV has the scipy
# solve_bvp peer's rows appended) and docs/charts/{paper,catenary,survey}{,-profile}.{png,svg}.
# The raw methods run with --no-verify, so that the charts show what each method does alone; the row
# "auto" is ogive's default, verified, solve. Needs gnuplot-nox, python3-scipy (install-deps.sh --charts).
set -euo pipefail
cd "$(dirname "$0")/../.."
ogive=${1:-build/ogive}
[[ -x $ogive ]] || { echo "charts.sh: no ogive executable at '$ogive' (build first)" >&2; exit 2; }
mkdir -p docs/charts
rtols=1e-2,1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10,1e-11,1e-12
bench=(bench --rtols "$rtols" --integrators adams,bdf --no-verify --repeats 11)

# The quadrature method has no integrator: one call with one (bench would repeat its rows per integrator).
quadrature=(bench --rtols "$rtols" --integrators adams --methods quadrature --repeats 11)
"$ogive" "${bench[@]}" --eccentricity 0,0.5,1 --methods closed-form,shooting,multiple-shooting,auto \
  > benchmarks/work_precision/paper.csv
"$ogive" "${quadrature[@]}" --eccentricity 0,0.5,1 >> benchmarks/work_precision/paper.csv
python3 benchmarks/peer/scipy_peer.py --eccentricity 0,0.5,1 --tols "$rtols" --ogive "$ogive" --repeats 5 \
  >> benchmarks/work_precision/paper.csv
"$ogive" "${bench[@]}" --curve catenary --rise-ratio 0.5 --methods shooting,multiple-shooting,auto \
  > benchmarks/work_precision/catenary.csv
"$ogive" "${quadrature[@]}" --curve catenary --rise-ratio 0.5 >> benchmarks/work_precision/catenary.csv
"$ogive" "${bench[@]}" --curve points --curve-file data/curves/catenary-survey.csv \
  --methods shooting,multiple-shooting,auto > benchmarks/work_precision/survey.csv
"$ogive" "${quadrature[@]}" --curve points --curve-file data/curves/catenary-survey.csv >> benchmarks/work_precision/survey.csv

benchmarks/work_precision/work_precision.sh benchmarks/work_precision/paper.csv docs/charts/paper "pointed arches eps 0 / 0.5 / 1, t = 0.08 L"
benchmarks/work_precision/work_precision.sh benchmarks/work_precision/catenary.csv docs/charts/catenary "catenary, rise L/2, t = 0.08 L"
benchmarks/work_precision/work_precision.sh benchmarks/work_precision/survey.csv docs/charts/survey "25-point survey (data/curves/catenary-survey.csv)"
