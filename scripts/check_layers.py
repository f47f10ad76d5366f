#!/usr/bin/env python3
"""Checks the README's "Architecture": no file of include/, src/ or cli/ includes a file of a higher layer,
and CVODE and Clp are each included by one file only. Exit 0 when every include keeps the rule, else 1
with one line per broken include.   usage: scripts/check_layers.py [REPO]"""
import pathlib
import re
import sys

LAYERS = [
    ("geometry", ["curve", "curve_families", "points_curve", "gauss_legendre", "chebyshev"]),
    ("model", ["scene", "loads_file", "arch_model", "section"]),
    ("solution types", ["solution"]),
    ("one BVP solve", ["bvp"]),
    ("methods", ["closed_form", "shooting", "quadrature", "cvode_integrator", "no_tension", "no_tension_quadrature", "damped_newton", "limit", "limit_internal",
                 "limit_lp", "voussoirs"]),
    ("dispatcher", ["solve"]),
    ("output", ["csv", "svg", "thrust_line"]),
    ("cli", ["cli", "values", "main"]),
]
RANK = {stem: (i, name) for i, (name, stems) in enumerate(LAYERS) for stem in stems}
ONLY = {prefix: "src/cvode_integrator.cpp"
        for prefix in ("cvode/", "sundials/", "sunnonlinsol/", "sunlinsol/", "sunmatrix/", "nvector/")}
ONLY.update({prefix: "src/limit/limit_lp.cpp" for prefix in ("coin/", "Clp", "Coin")})

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
problems = []
files = [p for d in ("include", "src", "cli") for p in (root / d).rglob("*") if p.suffix in (".hpp", ".cpp")]
for path in sorted(files):
    rel = path.relative_to(root).as_posix()
    if path.stem not in RANK:
        problems.append(f"{rel}: not in any layer of scripts/check_layers.py")
        continue
    rank, layer = RANK[path.stem]
    for n, line in enumerate(path.read_text().splitlines(), 1):
        m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
        if not m:
            continue
        target = m.group(2)
        for prefix, owner in ONLY.items():
            if target.startswith(prefix) and rel != owner:
                problems.append(f"{rel}:{n}: includes {target}; only {owner} may")
        if m.group(1) != '"':
            continue
        stem = pathlib.PurePosixPath(target).stem
        if stem in RANK and RANK[stem][0] > rank:
            problems.append(f"{rel}:{n}: {layer} includes {target}, of the higher layer {RANK[stem][1]}")
for p in problems:
    print(p)
print(f"check_layers.py: {len(files)} files, {len(problems)} problems", file=sys.stderr)
sys.exit(1 if problems else 0)
