#!/usr/bin/python3
"""What a user waits for beyond the solve: start-up, each method's marginal time per scene, and a large
closed-form sweep's throughput against threads, measured in one run.

    /usr/bin/python3 benchmarks/speed/startup_sweep.py [--ogive build/ogive] [--startup-runs 20]
        [--marginal-scale 1] [--sweep-scenes 1000000] [--sweep-runs 3] [--threads 1,2]
        [--chart docs/figures/sweep-threads.png] [--peer-tol 1e-8] [--startup-only]

Start-up: `ogive thrust` (one scene, its row discarded) and `/bin/true`, run in turn --startup-runs
times each, so that a change in the machine's load slows both alike; the table gives each one's median
wall-clock and CPU time (user + system, from the kernel's accounting of the finished child) and the
median of the pairwise differences. `ogive --version` is measured the same way: what is left of it is
loading the program and building the command line, not solving. --startup-only stops there.

Marginal time per scene: for each method, the best of 5 runs of a sweep of N pointed arches
(`--eccentricity 0:1:N`, one thread, N from 2000 for multiple shooting to 40 000 for the closed form,
times --marginal-scale) minus the best of 5 one-scene runs, divided by N - 1: the cost of one more
scene in a process already started, row formatting and writing included. (`auto` on these arches is
the closed form.)

Sweep throughput: `thrust --eccentricity 0:1:A --thickness-ratio 0.05:0.15:B --method closed-form`
(A x B = --sweep-scenes) written to a file, --sweep-runs times on each thread count, in turn; the table
gives the best and the median wall-clock time, the scenes per second of the best, and the speed-up
over one thread (of the best times). The files of every thread count must be byte-identical; a
difference exits 1. With --chart, gnuplot draws the throughput against threads as a PNG.

The summary columns: the same marginal time per scene with `--columns H,V` and with the thrust line's
summary added (`max_thrust_eccentricity,thrust_in_kern,thrust_in_section`), a quarter of the scenes,
and their ratio: what the largest eccentricity and the kern and section checks cost beside the
reactions.

The solve_bvp ratio: scipy's `solve_bvp` on the equilateral arch (benchmarks/peer/scipy_peer.py,
--peer-tol, median of 5 solves, its H/V error against the closed form) against each method's marginal
time above: how many times longer the general-purpose collocation solver takes per scene.

A busy machine makes every figure worse, never better: quote the best of several runs and the spread.
"""
import argparse
import csv
import filecmp
import io
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

# Each method's sweep length at --marginal-scale 1: about 0.1 to 0.3 s of solving on the project's machine,
# well above the spread of a process's start-up.
METHODS = [("closed-form", 40000), ("quadrature", 10000), ("shooting", 4000), ("multiple-shooting", 2000)]


def run(cmd, out=subprocess.DEVNULL, accepted=(0,)):
    """Wall-clock and CPU seconds of one run of cmd; exits 1 if its exit status is not `accepted`."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    if proc.returncode not in accepted:
        sys.exit(f"startup_sweep.py: {' '.join(cmd)} exited {proc.returncode}: {err.strip()}")
    return wall, usage.ru_utime + usage.ru_stime


def startup(ogive, args, runs):
    """Medians of (wall, cpu) for ogive args and /bin/true, alternating, and of their differences."""
    a, b = [], []
    run([ogive] + args)  # warm-up: the libraries into the page cache
    for _ in range(runs):
        a.append(run([ogive] + args))
        b.append(run(["/bin/true"]))
    med = lambda xs, i: statistics.median(x[i] for x in xs)
    diff = lambda i: statistics.median(x[i] - y[i] for x, y in zip(a, b))
    return med(a, 0), med(a, 1), med(b, 0), med(b, 1), diff(0), diff(1)


SUMMARY_COLUMNS = "H,V,max_thrust_eccentricity,thrust_in_kern,thrust_in_section"


def marginal(ogive, method, scenes, extra=()):
    """Seconds per scene beyond start-up, one thread."""
    base = [ogive, "thrust", "--method", method, "--threads", "1", *extra]
    # Exit 3 (a row whose solve missed rtol: single shooting on a few eccentricities) is a solve all the same.
    one = min(run(base + ["--eccentricity", "0.5"], accepted=(0, 3))[0] for _ in range(5))
    many = min(run(base + ["--eccentricity", f"0:1:{scenes}"], accepted=(0, 3))[0] for _ in range(5))
    return (many - one) / (scenes - 1)


def solve_bvp_seconds(ogive, tol):
    """scipy's solve_bvp on the equilateral arch: median seconds of one solve and its H/V error."""
    peer = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "peer", "scipy_peer.py")
    proc = subprocess.run(["/usr/bin/python3", peer, "--eccentricity", "0.5", "--tols", tol, "--ogive", ogive,
                           "--repeats", "5"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"startup_sweep.py: scipy_peer.py exited {proc.returncode}: {proc.stderr.strip()}")
    row = next(csv.DictReader(io.StringIO(proc.stdout)))
    return float(row["median_seconds"]), row["error_H_over_V"]


def sweep_axes(scenes):
    """Two axis counts whose product is scenes (the first the nearest divisor to its square root)."""
    a = int(math.isqrt(scenes))
    while scenes % a:
        a -= 1
    return a, scenes // a


def sweeps(ogive, scenes, thread_counts, runs, tmp):
    a, b = sweep_axes(scenes)
    times = {t: [] for t in thread_counts}
    for _ in range(runs):
        for t in thread_counts:
            path = os.path.join(tmp, f"sweep-{t}.csv")
            with open(path, "wb") as out:
                times[t].append(run([ogive, "thrust", "--eccentricity", f"0:1:{a}", "--thickness-ratio",
                                     f"0.05:0.15:{b}", "--method", "closed-form", "--threads", str(t)], out)[0])
    first = os.path.join(tmp, f"sweep-{thread_counts[0]}.csv")
    for t in thread_counts[1:]:
        if not filecmp.cmp(first, os.path.join(tmp, f"sweep-{t}.csv"), shallow=False):
            sys.exit(f"startup_sweep.py: the sweep's output on {t} threads differs from {thread_counts[0]}'s")
    return times


def chart(path, scenes, rows):
    """Throughput against threads, with the first count's throughput scaled by threads beside it."""
    data = "\n".join(f"{t} {scenes / best:.6g} {scenes / rows[0][1] * t / rows[0][0]:.6g}" for t, best in rows)
    script = f"""set terminal pngcairo size 640,400
set output '{path}'
set xlabel 'threads'
set ylabel 'closed-form scenes per second (best run)'
set xtics 1
set yrange [0:*]
set key top left
set grid
plot '-' using 1:2 with linespoints pt 7 title 'measured', '-' using 1:3 with lines dt 2 title 'proportional to threads'
{data}
e
{data}
e
"""
    subprocess.run(["gnuplot"], input=script.encode(), check=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ogive", default="build/ogive")
    p.add_argument("--startup-runs", type=int, default=20)
    p.add_argument("--marginal-scale", type=float, default=1.0)
    p.add_argument("--sweep-scenes", type=int, default=1000000)
    p.add_argument("--sweep-runs", type=int, default=3)
    p.add_argument("--threads", default="1,2", help="thread counts of the sweep, a list a,b")
    p.add_argument("--chart", help="PNG of throughput against threads (gnuplot)")
    p.add_argument("--peer-tol", default="1e-8", help="solve_bvp's tolerance for the ratio (default 1e-8)")
    p.add_argument("--startup-only", action="store_true", help="measure the start-up alone (a few seconds)")
    o = p.parse_args()
    if o.startup_runs < 1 or o.sweep_runs < 1 or not o.marginal_scale > 0 or o.sweep_scenes < 1:
        sys.exit("startup_sweep.py: --startup-runs and --sweep-runs must be >= 1, --marginal-scale > 0, "
                 "--sweep-scenes >= 1")
    thread_counts = [int(t) for t in o.threads.split(",")]
    ogive = os.path.abspath(o.ogive)

    print("| start-up (median of %d, alternating with /bin/true) | wall ms | CPU ms | /bin/true wall ms "
          "| /bin/true CPU ms | wall more | CPU more |" % o.startup_runs)
    print("|---|---:|---:|---:|---:|---:|---:|")
    for label, args in [("`ogive thrust` (one scene)", ["thrust"]), ("`ogive --version`", ["--version"])]:
        f = startup(ogive, args, o.startup_runs)
        print(f"| {label} | " + " | ".join(f"{1e3 * x:.2f}" for x in f) + " |")
    print()
    if o.startup_only:
        return

    print("| method (one thread) | scenes | marginal µs per scene |")
    print("|---|---:|---:|")
    per_scene = {}
    for m, n in METHODS:
        n = max(2, round(n * o.marginal_scale))
        per_scene[m] = marginal(ogive, m, n)
        print(f"| {m} | {n} | {1e6 * per_scene[m]:.2f} |")
    print()

    print("| method (one thread) | scenes | `--columns H,V` µs per scene | with the summary columns µs per scene "
          "| ratio |")
    print("|---|---:|---:|---:|---:|")
    for m, n in METHODS:
        n = max(2, round(n * o.marginal_scale / 4))
        plain = marginal(ogive, m, n, ["--columns", "H,V"])
        summary = marginal(ogive, m, n, ["--columns", SUMMARY_COLUMNS])
        print(f"| {m} | {n} | {1e6 * plain:.2f} | {1e6 * summary:.2f} | {summary / plain:.2f} |")
    print()

    bvp, bvp_error = solve_bvp_seconds(ogive, o.peer_tol)
    print(f"| scipy solve_bvp, tol {o.peer_tol}, equilateral arch | µs per solve | its H/V error | "
          + " | ".join(f"ratio to {m}" for m, _ in METHODS) + " |")
    print("|---|---:|---:|" + "---:|" * len(METHODS))
    print(f"| median of 5 | {1e6 * bvp:.0f} | {float(bvp_error):.1e} | "
          + " | ".join(f"{bvp / per_scene[m]:.0f}" for m, _ in METHODS) + " |")
    print()

    with tempfile.TemporaryDirectory() as tmp:
        times = sweeps(ogive, o.sweep_scenes, thread_counts, o.sweep_runs, tmp)
    best1 = min(times[thread_counts[0]])
    print(f"| {o.sweep_scenes} closed-form scenes to a file, threads | best s | median s | max s "
          f"| scenes per s (best) | speed-up over {thread_counts[0]} (best) |")
    print("|---:|---:|---:|---:|---:|---:|")
    for t in thread_counts:
        ts = times[t]
        print(f"| {t} | {min(ts):.3f} | {statistics.median(ts):.3f} | {max(ts):.3f} | "
              f"{o.sweep_scenes / min(ts):.4g} | {best1 / min(ts):.2f} |")
    if o.chart:
        chart(o.chart, o.sweep_scenes, [(t, min(times[t])) for t in thread_counts])


if __name__ == "__main__":
    main()
