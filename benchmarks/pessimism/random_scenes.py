#!/usr/bin/env python3
"""The false-alarm table on random scenes: how often a row whose numbers are within rtol says otherwise,
and whether any row says success with numbers outside rtol.

    /usr/bin/python3 benchmarks/pessimism/random_scenes.py [--ogive build/ogive] [--scenes 100] [--seed 1]
        [--csv benchmarks/pessimism/random_scenes.csv] [--extra '--atol 1e300']

Writes the rows to random_scenes.csv and the scenes (number, reference, options) to random_scenes_scenes.csv.

Draws elastic scenes at random: every curve family (semicircular, pointed, segmental, three- and
four-centred, elliptical, parabolic, catenary), t/L 0.01 .. 0.25 (log-uniform), clamped or pinned
springings (each side on its own in one scene of five; a crown hinge in a third of the pinned ones),
point, live and fill loads, springings that spread, settle or rotate. Solves each with every method
(closed form, quadrature, single and multiple shooting, auto; Adams and BDF) at rtol 1e-4 .. 1e-12,
`thrust` (six reactions) and `profile` (41 stations), and measures each row's true error as
pessimism.py does (what docs/methods.md says `success` promises).

References, never the row's own solve:
  closed   the closed form (circular arcs, point loads only): its numbers are exact to round-off, their
           error estimate (its round-off bound) is the reference's noise
  refined  elsewhere multiple shooting with 64 segments and Adams at rtol 1e-12 (or the first of 1e-11,
           1e-10, 1e-9 that says success, where round-off holds a thin arch's profile above 1e-12): the
           reference's noise is its own error estimate
A scene whose reference is not `success` is skipped (counted).

A row is success-worthy when its true error plus the reference's noise is within rtol, and then a
false alarm when its status is not success (tolerance_not_met, unverified, ill_conditioned, ...; the
table counts each); a false success when it says success with a true error minus the noise above rtol
(the script exits 1). --extra adds options to the measured rows (never to the references): no option
may make a false success. Prints the table per method and integrator, for rtol >= 1e-10 and for all
rtols, as Markdown. Standard library only.
"""
import argparse
import csv
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import pessimism  # noqa: E402

RTOLS = ["1e-4", "1e-5", "1e-6", "1e-7", "1e-8", "1e-9", "1e-10", "1e-11", "1e-12"]
CIRCULAR = ["semicircular", "pointed", "segmental", "three-centred", "four-centred"]
CURVES = CIRCULAR + ["elliptical", "parabolic", "catenary"]
ALARM_FROM = 1e-10  # the table's first part: rtol at least this


def log_uniform(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def random_scene(rng):
    """(label, ogive options, whether the closed form treats it)."""
    curve = rng.choice(CURVES)
    opts = ["--curve", curve]
    if curve == "pointed":
        opts += ["--eccentricity", f"{rng.uniform(0.05, 1.5):.3g}"]
    elif curve in ("segmental", "elliptical", "parabolic", "catenary"):
        opts += ["--rise-ratio", f"{rng.uniform(0.1 if curve == 'segmental' else 0.2, 0.5):.3g}"]
    opts += ["--thickness-ratio", f"{log_uniform(rng, 0.01, 0.25):.3g}"]
    distributed = False
    if rng.random() < 0.2:
        left, right = rng.choice(["clamped", "pinned"]), rng.choice(["clamped", "pinned"])
        opts += ["--left-support", left, "--right-support", right]
    else:
        left = right = rng.choice(["clamped", "clamped", "pinned"])
        opts += ["--supports", left]
        if left == "pinned" and rng.random() < 0.33:
            opts += ["--crown-hinge"]
    if rng.random() < 0.4:
        opts += ["--point-load", f"{log_uniform(rng, 1e3, 1e5):.3g}", "--point-load-at", f"{rng.uniform(0.05, 0.95):.3g}"]
    if rng.random() < 0.25:
        a = rng.uniform(0, 0.6)
        opts += ["--live-load", f"{log_uniform(rng, 1e3, 3e4):.3g}", "--live-load-from", f"{a:.3g}",
                 "--live-load-to", f"{rng.uniform(a + 0.1, 1):.3g}"]
        distributed = True
    if rng.random() < 0.25:
        opts += ["--fill-density", f"{rng.uniform(1400, 2000):.4g}", "--fill-height-ratio", f"{rng.uniform(0.3, 1.0):.3g}"]
        distributed = True
    move = rng.random()
    if move < 0.2:
        opts += ["--support-displacement-ratio", f"{log_uniform(rng, 1e-5, 1e-3):.3g}"]
    elif move < 0.3:
        opts += ["--right-settlement-ratio", f"{log_uniform(rng, 1e-5, 1e-3):.3g}"]
    elif move < 0.4 and left == "clamped":
        opts += ["--left-rotation", f"{log_uniform(rng, 1e-5, 1e-3):.3g}"]
    return " ".join(opts), opts, curve in CIRCULAR and not distributed


def reference_of(ogive, opts, closed):
    """(kind, reference as pessimism.as_reference gives it) or None."""
    tries = [("closed", "closed-form", "1e-8", [])] if closed else []
    tries += [("refined", "multiple-shooting", r, ["--segments", "64"]) for r in ("1e-12", "1e-11", "1e-10", "1e-9")]
    for kind, method, rtol, extra in tries:
        _, t = pessimism.run(ogive, "thrust", opts + extra, [method], ["adams"], [rtol])
        _, p = pessimism.run(ogive, "profile", opts + extra, [method], ["adams"], [rtol], pessimism.STATIONS)
        t, p = next(iter(t.values())), next(iter(p.values()))
        if t[0]["status"] == "success" and p[0]["status"] == "success":
            return kind, pessimism.as_reference(t, p)
    return None


def measure(ogive, label, kind, opts, ref, methods, integrators, shown=None):
    rows = []
    reactions, profile, hv, noise = ref
    t = pessimism.thickness_of(opts)
    for command in ["thrust", "profile"]:
        _, solves = pessimism.run(ogive, command, opts, methods, integrators, RTOLS,
                                  pessimism.STATIONS if command == "profile" else None)
        for (method, integ, rtol), rs in solves.items():
            err = (pessimism.reaction_error(rs[0], reactions, t) if command == "thrust"
                   else pessimism.profile_error(rs, profile, hv, t))
            rows.append(dict(scene=label, reference=kind, command=command, method=shown or method,
                             integrator=integ if not shown else integrators[0], chosen=method,
                             rtol=float(rtol), status=rs[0]["status"], error_estimate=pessimism.f(rs[0]["error_estimate"]),
                             true_error=err, reference_noise=noise))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ogive", default=os.path.join(HERE, "..", "..", "build", "ogive"))
    ap.add_argument("--scenes", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--csv", default=os.path.join(HERE, "random_scenes.csv"))
    ap.add_argument("--extra", default="", help="options added to the measured rows (not the references), e.g. "
                                                "'--atol 1e300' or '--no-verify': no option may make a false success")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    rows, skipped = [], 0
    for i in range(a.scenes):
        label, opts, closed = random_scene(rng)
        found = reference_of(a.ogive, opts, closed)
        if found is None:
            skipped += 1
            print(f"{i + 1}/{a.scenes} {label}: no reference, skipped", file=sys.stderr)
            continue
        kind, ref = found
        methods = (["closed-form"] if closed else []) + ["quadrature", "shooting", "multiple-shooting"]
        extra = a.extra.split()
        rows += measure(a.ogive, label, kind, opts + extra, ref, methods, ["adams", "bdf"])
        for integ in ["adams", "bdf"]:
            rows += measure(a.ogive, label, kind, opts + extra, ref, ["auto"], [integ], shown="auto")
        print(f"{i + 1}/{a.scenes} {label}: {len(rows)} rows", file=sys.stderr)
    for r in rows:
        r["success_worthy"] = r["true_error"] + r["reference_noise"] <= r["rtol"]
        r["false_alarm"] = r["success_worthy"] and r["status"] != "success"
        r["false_success"] = r["status"] == "success" and r["true_error"] - r["reference_noise"] > r["rtol"]
    write(rows, a.csv)
    print(f"{a.scenes} scenes (seed {a.seed}{', ' + a.extra if a.extra else ''}), {skipped} without a reference; "
          f"{len(rows)} rows\n")
    summarize(rows)
    return 1 if any(r["false_success"] for r in rows) else 0


ROW_COLUMNS = ["scene", "command", "method", "integrator", "chosen", "rtol", "status", "error_estimate", "true_error",
               "reference_noise", "success_worthy", "false_alarm", "false_success"]


def write(rows, path):
    """Two files: path (one row per solve: the scene by its number, auto's chosen method, the numbers to 3
    digits, success-worthy, false alarm and false success as 1 or 0, judged on the unrounded numbers) and
    path with _scenes before .csv (each scene's number, reference and options)."""
    numbers = {}
    for r in rows:
        numbers.setdefault(r["scene"], (len(numbers) + 1, r["reference"]))
    with open(path.replace(".csv", "_scenes.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["scene", "reference", "options"])
        for label, (n, kind) in numbers.items():
            w.writerow([n, kind, label])
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(ROW_COLUMNS)
        for r in rows:
            out = dict(r, scene=numbers[r["scene"]][0], chosen=r["chosen"] if r["method"] == "auto" else "")
            w.writerow([f"{out[k]:.3g}" if isinstance(out[k], float) else int(out[k]) if isinstance(out[k], bool)
                        else out[k] for k in ROW_COLUMNS])


def summarize(rows):
    # Methods whose integrator does not matter (closed form, quadrature) are one group.
    def group(r):
        return r["method"] + (f" {r['integrator']}" if r["integrator"] and r["method"] != "quadrature" else "")

    for title, keep in [(f"rtol >= {ALARM_FROM:.0e}", lambda r: r["rtol"] >= ALARM_FROM * (1 - 1e-9)),
                        ("every rtol", lambda r: True)]:
        sel = [r for r in rows if keep(r)]
        statuses = sorted({r["status"] for r in sel if r["false_alarm"]})
        print(f"{title}:\n")
        print("| method | rows | success-worthy | false alarms | " + " | ".join(statuses) + " | false successes |")
        print("|---|---|---|---|" + "---|" * len(statuses) + "---|")
        groups = {}
        for r in sel:
            groups.setdefault(group(r), []).append(r)
        for name in sorted(groups) + ["all"]:
            g = sel if name == "all" else groups[name]
            worthy = sum(r["success_worthy"] for r in g)
            fa = sum(r["false_alarm"] for r in g)
            by = [sum(r["false_alarm"] and r["status"] == s for r in g) for s in statuses]
            fs = sum(r["false_success"] for r in g)
            pct = 100 * fa / worthy if worthy else 0
            print(f"| {name} | {len(g)} | {worthy} | {fa} ({pct:.1f} %) | " + " | ".join(map(str, by)) + f" | {fs} |")
        print()
    for r in rows:
        if r["false_success"]:
            print(f"FALSE SUCCESS: {r}")


if __name__ == "__main__":
    sys.exit(main())
