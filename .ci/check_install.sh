#!/usr/bin/env bash
# Installs ogive from a build directory (default: build) into a temporary prefix, then configures,
# builds and runs examples/ against that prefix with find_package(ogive), as a user's project would.
# Also checks the installed files: the executable answers --version with the project's version, and the
# public headers name no SUNDIALS or CLI11 type. Exits non-zero on any failure; removes the prefix.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in include/ogive/ogive.hpp include/ogive/version.hpp bin/ogive; do
  [[ -e "$prefix/$f" ]] || { echo "check-install: $f was not installed" >&2; exit 1; }
done
for f in libogive.a ogiveConfig.cmake ogiveConfigVersion.cmake ogiveTargets.cmake; do
  [[ -n $(find "$prefix" -name "$f") ]] || { echo "check-install: $f was not installed" >&2; exit 1; }
done
# SUNDIALS' and CLI11's headers and types (not the words: a comment may name CVODE's tolerances).
if grep -rnE '#include *[<"](sundials|cvode|nvector|sunlinsol|sunmatrix|sunnonlinsol|CLI)/|\b(N_Vector|SUNContext|SUNMatrix|SUNLinearSolver|sunrealtype|sunindextype)\b|CLI::' -r "$prefix/include/ogive/"; then
  echo "check-install: a public header exposes SUNDIALS or CLI11 (above)" >&2
  exit 1
fi
version=$("$prefix/bin/ogive" --version)
expected="ogive $(sed -n 's/^project(ogive VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)"
[[ "$version" == "$expected" ]] || { echo "check-install: --version printed '$version', not '$expected'" >&2; exit 1; }
echo "installed: $version"

cmake -S examples -B "$prefix/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$prefix/build" -j2 >/dev/null
"$prefix/build/thrust_of_one_arch"
