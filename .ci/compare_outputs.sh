#!/usr/bin/env bash
# Runs every command of .ci/output_commands.txt with two ogive binaries and compares, by cmp, what each
# prints on stdout and its exit status. Exits 0 when all are identical, 1 otherwise (naming each command
# that differs). For a change meant to keep behaviour: build the base (a git worktree of the commit
# compared with) and the change, then
#   bash .ci/compare_outputs.sh BASE/build/ogive build/ogive
set -uo pipefail
cd "$(dirname "$0")/.."
[[ $# -eq 2 ]] || { echo "usage: .ci/compare_outputs.sh BASE_OGIVE NEW_OGIVE" >&2; exit 2; }
base=$(realpath "$1") new=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0 differ=0
while IFS= read -r line; do
  [[ -z "$line" || "$line" == \#* ]] && continue
  n=$((n + 1))
  for side in base new; do
    bin=${!side}
    (OGIVE=$bin; eval "${line//OGIVE/\"\$OGIVE\"}") >"$work/$side.out" 2>/dev/null
    echo "exit $?" >>"$work/$side.out"
  done
  if ! cmp -s "$work/base.out" "$work/new.out"; then
    echo "differs: $line"
    differ=$((differ + 1))
  fi
done <.ci/output_commands.txt
echo "compare_outputs: $n commands, $differ differ"
[[ $differ -eq 0 ]]
