#!/usr/bin/env python3
"""Runs every command of .ci/output_commands.txt with two ogive binaries, as compare_outputs.sh does, and
for each command whose output differs says how: every line must keep its text and its count of numbers;
the numbers may differ, each measured against the largest magnitude of its CSV column (outside CSV
fields, against the largest number of its line: a drawing's path). A command whose output differs beyond --rtol, in its text, or in its exit
status fails. The columns that measure a row's error (ERROR_MEASURES) are reported apart and held to
--rtol only with --estimates.

    /usr/bin/python3 .ci/compare_numbers.py BASE_OGIVE NEW_OGIVE [--rtol 1e-12]

For a change meant to move printed numbers only within their round-off: it prints one line per differing
command with its largest difference and the column where it is, and exits 0 when all are within --rtol,
1 otherwise (2 on bad arguments).
"""
import argparse
import os
import re
import subprocess
import sys

# Columns that measure a row's error rather than its result (estimates, residuals, differences from a
# reference, their message): reported apart, and within any bound only with --estimates.
ERROR_MEASURES = {"error_estimate", "boundary_residual", "equilibrium_residual", "relative_difference",
                  "error_H_over_V", "error_profile", "reference_error", "message"}
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def run(binary, line):
    command = line.replace("OGIVE", '"$OGIVE"')
    done = subprocess.run(["bash", "-c", command], capture_output=True, text=True,
                          env=dict(os.environ, OGIVE=binary), cwd=ROOT)
    return done.stdout.splitlines(), done.returncode


def skeleton(line):
    return NUMBER.sub("#", line)


def compare(base, new):
    """(largest difference, where, largest error measure's difference, text differences) of two outputs."""
    if len(base) != len(new):
        return 0.0, "", 0.0, [f"{len(base)} lines against {len(new)}"]
    texts = []
    # Column scales: the largest magnitude of each field position over the CSV rows of both outputs.
    scale = {}
    for line in base + new:
        for i, field in enumerate(line.split(",")):
            if NUMBER.fullmatch(field):
                scale[i] = max(scale.get(i, 0.0), abs(float(field)))
    header = base[0].split(",") if base and "," in base[0] else []
    worst, where, measures = 0.0, "", 0.0
    for n, (a, b) in enumerate(zip(base, new)):
        if a == b:
            continue
        if skeleton(a) != skeleton(b):
            texts.append(f"line {n + 1}: {a[:80]!r} against {b[:80]!r}")
            continue
        fa, fb = a.split(","), b.split(",")
        line_size = max(abs(float(u)) for u in NUMBER.findall(a) + NUMBER.findall(b))
        csv = "," in a and len(fa) == len(fb)
        for i, (x, y) in enumerate(zip(fa, fb) if csv else [(a, b)]):
            for u, v in zip(NUMBER.findall(x), NUMBER.findall(y)):
                if u == v:
                    continue
                u, v = float(u), float(v)
                size = scale.get(i, 0.0) if csv and NUMBER.fullmatch(x) else line_size
                d = abs(u - v) / size if size > 0 else float("inf")
                if csv and i < len(header) and header[i] in ERROR_MEASURES:
                    measures = max(measures, d)
                elif d > worst:
                    worst = d
                    where = header[i] if csv and i < len(header) else f"line {n + 1}"
    return worst, where, measures, texts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--rtol", type=float, default=1e-12)
    parser.add_argument("--estimates", action="store_true", help="hold the error measures to --rtol too")
    args = parser.parse_args()
    base, new = os.path.realpath(args.base), os.path.realpath(args.new)
    commands = [l for l in open(os.path.join(ROOT, ".ci/output_commands.txt")).read().splitlines()
                if l and not l.startswith("#")]
    failed = differ = 0
    for line in commands:
        (a, ca), (b, cb) = run(base, line), run(new, line)
        if a == b and ca == cb:
            continue
        differ += 1
        worst, where, measures, texts = compare(a, b)
        bad = texts or ca != cb or worst > args.rtol or (args.estimates and measures > args.rtol)
        failed += bool(bad)
        status = f"exit {ca} -> {cb}; " if ca != cb else ""
        detail = (f"{len(texts)} lines of other text, first {texts[0]}" if texts else
                  f"largest {worst:.2g}" + (f" ({where})" if where else "") +
                  (f"; error measures {measures:.2g}" if measures else ""))
        print(f"{'FAILS' if bad else 'within'}: {status}{detail}: {line}")
    print(f"compare_numbers: {len(commands)} commands, {differ} differ, {failed} beyond rtol {args.rtol:g} or in text")
    return 1 if failed else 0


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

if __name__ == "__main__":
    sys.exit(main())
