#!/usr/bin/env bash
# Installs ogive from a build directory (default: build) into a temporary prefix, checks what was
# installed, then configures, builds and tests examples/ against that prefix with find_package(ogive), as
# a user's project would (each example is a ctest test there). The installed tree must hold the umbrella
# and version headers and the public headers by layer, no private header (methods, numerics, the CVODE
# wrapper, the limit analysis' internals), no SUNDIALS or CLI11 type in a public header, the library, its
# package files and the executable, which answers --version with the project's version.
# Exits non-zero on any failure; removes the prefix.
#   usage: .ci/check_install.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
fail() { echo "check-install: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in include/ogive/ogive.hpp include/ogive/version.hpp bin/ogive; do
  [[ -e "$prefix/$f" ]] || fail "$f was not installed"
done
for layer in geometry model core solve limit output; do
  [[ -n $(find "$prefix/include/ogive/$layer" -name '*.hpp' 2>/dev/null) ]] || fail "include/ogive/$layer/ has no header"
done
# Public headers only: the installed folders are the layers above, and no header of src/ was copied.
for dir in "$prefix"/include/ogive/*/; do
  case "$(basename "$dir")" in
    geometry | model | core | solve | limit | output) ;;
    *) fail "include/ogive/$(basename "$dir")/ was installed: not a public layer" ;;
  esac
done
while IFS= read -r private; do
  [[ -z $(find "$prefix/include" -name "$(basename "$private")") ]] || fail "the private header $private was installed"
done < <(find src -name '*.hpp')
for f in libogive.a ogiveConfig.cmake ogiveConfigVersion.cmake ogiveTargets.cmake; do
  [[ -n $(find "$prefix" -name "$f") ]] || fail "$f was not installed"
done
# SUNDIALS' and CLI11's headers and types (not the words: a comment may name CVODE's tolerances).
if grep -rnE '#include *[<"](sundials|cvode|nvector|sunlinsol|sunmatrix|sunnonlinsol|CLI)/|\b(N_Vector|SUNContext|SUNMatrix|SUNLinearSolver|sunrealtype|sunindextype)\b|CLI::' -r "$prefix/include/ogive/"; then
  fail "a public header exposes SUNDIALS or CLI11 (above)"
fi
version=$("$prefix/bin/ogive" --version)
expected="ogive $(sed -n 's/^project(ogive VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)"
[[ "$version" == "$expected" ]] || fail "--version printed '$version', not '$expected'"
echo "check-install: installed $version, $(find "$prefix/include" -name '*.hpp' | wc -l) public headers"

# The examples against the installed package, built and run as its tests.
cmake -S examples -B "$prefix/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$prefix/build" -j2 >/dev/null
ctest --test-dir "$prefix/build" --output-on-failure
