#!/usr/bin/env bash
# Installs what ogive needs from Debian's packages, only if something is missing (idempotent, fast when
# all is there). With --charts it also installs what the benchmark charts and the scipy peer need.
# clang and libclang-rt-14-dev (libFuzzer, the sanitizers' runtimes for clang) serve .ci/fuzz.sh;
# libxml2-utils (xmllint) lets the tests check that `ogive draw` writes well-formed SVG. --charts adds
# librsvg2-bin (rsvg-convert, SVG to PNG) for docs/figures/make_figures.sh, chromium-headless-shell
# (about a minute to install) for .ci/check_report.sh, which renders `ogive report` to PNG and PDF, and
# calculix-ccx (CalculiX) for the continuum reference's check (benchmarks/continuum/continuum.py check).
set -euo pipefail
packages=(cmake g++ make libsundials-dev libeigen3-dev libfmt-dev libcli11-dev doctest-dev coinor-libclp-dev libboost-dev pkg-config clang libclang-rt-14-dev libxml2-utils)
if [[ "${1:-}" == "--charts" ]]; then packages+=(gnuplot-nox python3-scipy python3-numpy python3-pandas librsvg2-bin chromium-headless-shell bc calculix-ccx); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [[ $(id -u) -eq 0 ]] || sudo="sudo"
  echo "installing: ${missing[*]}" >&2
  $sudo apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
