#!/usr/bin/python3
"""The speed table of benchmarks/speed/README.md and docs/methods.md: medians of `ogive bench` rows, measured round-robin in one run.

    /usr/bin/python3 benchmarks/speed/speed_table.py [--ogive build/ogive] [--base OTHER_OGIVE] [--rounds 7]
                                            [--repeats 201] [--no-sweeps] [--sweep-runs 15]

Each row is one `ogive bench` call (its own median over --repeats solves); the rows are run in turn,
--rounds times, so that a machine whose load changes during the run slows every row alike; the table
gives the median over the rounds of each row's median, and its ratio to the closed form's time on the
semicircle (the target: at most 3x for the smooth curves with auto at rtol 1e-8). With
--base (a build of an older ogive), the auto and raw single-shooting rows are also run with it, in the
same rounds, and the table gives its time and the speed-up (its auto chose verified CVODE shooting). Errors are bench's own: against the closed form, or, for
non-circular curves, against verified multiple shooting at rtol 1e-12 (reference_error).

Then, unless --no-sweeps, two whole-process measurements (each command run --sweep-runs times,
alternating, output discarded, wall-clock medians): the raw Adams sweep
`thrust --eccentricity 0:1:4000 --method shooting --no-verify` on one thread, with its time per scene
beyond start-up (a 2-scene run's time subtracted), against --base if given; and the 20000-scene catenary
sweep on one thread and on two, whose outputs must be byte-identical (the target: at least 1.7x).

Prints a Markdown table on stdout; exits 1 if a bench call fails.
"""
import argparse
import csv
import hashlib
import io
import statistics
import subprocess
import sys
import time

CLOSED_FORM = ("closed form (auto), semicircle", ["--curve", "semicircular", "--methods", "auto"])

AUTO_ROWS = [
    ("auto, catenary rise 0.5", ["--curve", "catenary", "--rise-ratio", "0.5"]),
    ("auto, parabola rise 0.5", ["--curve", "parabolic", "--rise-ratio", "0.5"]),
    ("auto, ellipse rise 0.3", ["--curve", "elliptical", "--rise-ratio", "0.3"]),
    ("auto, ellipse rise 0.7", ["--curve", "elliptical", "--rise-ratio", "0.7"]),
    ("auto, survey catenary-survey.csv", ["--curve", "points", "--curve-file", "data/curves/catenary-survey.csv"]),
    ("auto, survey parabola-40.csv", ["--curve", "points", "--curve-file", "data/curves/parabola-40.csv"]),
]

RAW_ROWS = [
    ("raw shooting adams, eps 0.5", ["--eccentricity", "0.5", "--methods", "shooting", "--integrators", "adams",
                                     "--no-verify"]),
    ("raw shooting bdf, eps 0.5", ["--eccentricity", "0.5", "--methods", "shooting", "--integrators", "bdf",
                                   "--no-verify"]),
    ("raw multiple shooting adams 8 segments, eps 0.5", ["--eccentricity", "0.5", "--methods", "multiple-shooting",
                                                         "--segments", "8", "--integrators", "adams", "--no-verify"]),
    ("raw shooting adams, ellipse rise 0.3", ["--curve", "elliptical", "--rise-ratio", "0.3", "--methods", "shooting",
                                              "--integrators", "adams", "--no-verify"]),
]


def bench(binary, args, repeats):
    cmd = [binary, "bench", "--rtols", "1e-8", "--repeats", str(repeats)] + args
    if "--methods" not in args:
        cmd += ["--methods", "auto"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    rows = list(csv.DictReader(io.StringIO(run.stdout)))
    # bench exits 3 on a row that is not a success; a raw (--no-verify) row is unverified by design.
    raw = "--no-verify" in args and rows and all(r["status"] == "unverified" for r in rows)
    if run.returncode != 0 and not (run.returncode == 3 and raw):
        sys.exit(f"speed_table.py: {' '.join(cmd)} failed ({run.returncode}): {run.stderr.strip()}")
    if len(rows) != 1:
        sys.exit(f"speed_table.py: {' '.join(cmd)} printed {len(rows)} rows, expected 1")
    return rows[0]


def wall(cmd):
    """Seconds of wall-clock time for one run of cmd, its output discarded."""
    start = time.perf_counter()
    run = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - start
    if run.returncode not in (0, 3):  # 3: some row not success, which a raw sweep may print
        sys.exit(f"speed_table.py: {' '.join(cmd)} failed ({run.returncode}): {run.stderr.strip()}")
    return seconds


def has_threads(binary):
    """Whether this ogive has --threads (older builds run one thread)."""
    return "--threads" in subprocess.run([binary, "thrust", "--help"], capture_output=True, text=True).stdout


def sweeps(opts):
    """The whole-process measurements of the module docstring, printed as Markdown lines."""
    binaries = [("new", opts.ogive)] + ([("base", opts.base)] if opts.base else [])
    raw = ["thrust", "--method", "shooting", "--no-verify"]
    one = {who: (["--threads", "1"] if has_threads(b) else []) for who, b in binaries}
    catenary = [opts.ogive, "thrust", "--curve", "catenary", "--rise-ratio", "0.3:0.7:20000"]
    times = {}
    for _ in range(opts.sweep_runs):
        for who, b in binaries:
            for label, eccentricity in (("4000", "0:1:4000"), ("2", "0:1:2")):
                times.setdefault((who, label), []).append(wall([b] + raw + ["--eccentricity", eccentricity] + one[who]))
        for threads in ("1", "2"):
            times.setdefault(("threads", threads), []).append(wall(catenary + ["--threads", threads]))
    median = {key: statistics.median(values) for key, values in times.items()}
    print()
    print(f"Whole process, {opts.sweep_runs} alternating runs of each, medians:")
    print()
    per_scene = {}
    for who, _ in binaries:
        per_scene[who] = (median[(who, "4000")] - median[(who, "2")]) / 3998
        print(f"- {who}: `thrust --eccentricity 0:1:4000 --method shooting --no-verify` (one thread) "
              f"{median[(who, '4000')]:.3f} s, 2 scenes {median[(who, '2')] * 1e3:.1f} ms, "
              f"{per_scene[who] * 1e6:.1f} us per scene beyond start-up")
    if opts.base:
        print(f"- speed-up: whole process {median[('base', '4000')] / median[('new', '4000')]:.2f}x, "
              f"per scene beyond start-up {per_scene['base'] / per_scene['new']:.2f}x")
    digests = {t: hashlib.sha256(subprocess.run(catenary + ["--threads", t], capture_output=True).stdout).hexdigest()
               for t in ("1", "2")}
    print(f"- `thrust --curve catenary --rise-ratio 0.3:0.7:20000`: {median[('threads', '1')]:.3f} s on one thread, "
          f"{median[('threads', '2')]:.3f} s on two, {median[('threads', '1')] / median[('threads', '2')]:.2f}x; "
          f"output {'byte-identical' if digests['1'] == digests['2'] else 'DIFFERENT'}")
    if digests["1"] != digests["2"]:
        sys.exit("speed_table.py: --threads 1 and 2 printed different output")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ogive", default="build/ogive")
    parser.add_argument("--base", help="an older ogive binary for the raw-shooting speed-ups")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--repeats", type=int, default=201)
    parser.add_argument("--no-sweeps", action="store_true", help="skip the whole-process measurements")
    parser.add_argument("--sweep-runs", type=int, default=15)
    opts = parser.parse_args()

    jobs = [("new",) + CLOSED_FORM] + [("new",) + r for r in AUTO_ROWS] + [("new",) + r for r in RAW_ROWS]
    if opts.base:
        jobs += [("base",) + r for r in AUTO_ROWS + RAW_ROWS]
    times = {(who, label): [] for who, label, _ in jobs}
    last = {}
    for _ in range(opts.rounds):
        for who, label, args in jobs:
            row = bench(opts.ogive if who == "new" else opts.base, args, opts.repeats)
            times[(who, label)].append(float(row["median_seconds"]))
            last[(who, label)] = row
    median = {key: statistics.median(values) for key, values in times.items()}
    reference = median[("new", CLOSED_FORM[0])]

    def fmt(x):
        return "" if x in ("", None) else f"{float(x):.1e}"

    print(f"{opts.rounds} rounds x {opts.repeats} solves per row, rtol 1e-8; times in us (median of the rounds' medians)")
    print()
    print("| row | method chosen | time | / closed form | error H/V | error profile | error estimate | status |"
          + (" base time | speed-up |" if opts.base else ""))
    print("|---|---|---|---|---|---|---|---|" + ("---|---|" if opts.base else ""))
    for who, label, _ in jobs:
        if who != "new":
            continue
        row = last[(who, label)]
        t = median[(who, label)]
        line = (f"| {label} | {row['chosen_method']} | {t * 1e6:.1f} | {t / reference:.2f} | "
                f"{fmt(row['error_H_over_V'])} | {fmt(row['error_profile'])} | {fmt(row['error_estimate'])} | "
                f"{row['status']} |")
        if opts.base:
            if ("base", label) in median:
                b = median[("base", label)]
                line += f" {b * 1e6:.1f} | {b / t:.2f}x |"
            else:
                line += " | |"
        print(line)
    # The bound on multiple shooting: 8 segments at most 2.5 times single shooting, same scene.
    single = median[("new", "raw shooting adams, eps 0.5")]
    multiple = median[("new", "raw multiple shooting adams 8 segments, eps 0.5")]
    print()
    print(f"Multiple shooting (8 segments) / single shooting, raw Adams, eps 0.5: {multiple / single:.2f}")
    if not opts.no_sweeps:
        sweeps(opts)


if __name__ == "__main__":
    main()
