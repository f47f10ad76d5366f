#!/usr/bin/env python3
"""Checks the layering of docs/development.md by folders: a file's layer is its folder (src/<layer>/,
include/ogive/<layer>/, cli/), and no file includes one of a higher layer. Also: the public headers
(include/) include only public headers; methods/ and limit/ stand side by side and include neither the
other; only src/methods/cvode/ includes CVODE and only src/limit/limit_lp.cpp the LP library (Clp).
Exit 0 when every include keeps the rules, else 1 with one line per broken include.
usage: .ci/check_layers.py [REPO]"""
import pathlib
import re
import sys

# Lowest first. version.hpp sits below everything; the umbrella ogive.hpp above every library layer.
LAYERS = ["version", "numerics", "geometry", "model", "core", "methods|limit", "solve", "output", "umbrella", "cli"]
RANK = {name: i for i, group in enumerate(LAYERS) for name in group.split("|")}
SIDE_BY_SIDE = {"methods": "limit", "limit": "methods"}
ONLY = {prefix: "src/methods/cvode/"
        for prefix in ("cvode/", "sundials/", "sunnonlinsol/", "sunlinsol/", "sunmatrix/", "nvector/")}
ONLY.update({prefix: "src/limit/limit_lp.cpp" for prefix in ("coin/", "Clp", "Coin")})


def layer_of_file(rel):
    parts = rel.split("/")
    if parts[0] == "cli":
        return "cli"
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    if parts[:2] == ["include", "ogive"]:
        if len(parts) == 3:
            return {"version.hpp": "version", "version.hpp.in": "version", "ogive.hpp": "umbrella"}.get(parts[2])
        return parts[2]
    return None


def layer_of_include(target, includer_rel):
    parts = target.split("/")
    if parts[0] == "ogive":
        return layer_of_file("include/" + target)
    if includer_rel.startswith("cli/"):  # cli's own headers, relative to cli/ or its folders
        return "cli"
    if len(parts) > 1:  # a private header, relative to src/
        return parts[0]
    return layer_of_file(includer_rel)  # beside the includer


root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
problems = []
files = [p for d in ("include", "src", "cli") for p in (root / d).rglob("*") if p.suffix in (".hpp", ".cpp", ".in")]
for path in sorted(files):
    rel = path.relative_to(root).as_posix()
    layer = layer_of_file(rel)
    if layer not in RANK:
        problems.append(f"{rel}: in no layer folder (.ci/check_layers.py: {', '.join(LAYERS)})")
        continue
    for n, line in enumerate(path.read_text().splitlines(), 1):
        m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
        if not m:
            continue
        target = m.group(2)
        for prefix, owner in ONLY.items():
            if target.startswith(prefix) and not rel.startswith(owner):
                problems.append(f"{rel}:{n}: includes {target}; only {owner} may")
        if m.group(1) != '"':
            continue
        if rel.startswith("include/") and not target.startswith("ogive/"):
            problems.append(f"{rel}:{n}: a public header includes the private {target}")
            continue
        target_layer = layer_of_include(target, rel)
        if target_layer not in RANK:
            problems.append(f"{rel}:{n}: includes {target}, in no layer folder")
        elif RANK[target_layer] > RANK[layer]:
            problems.append(f"{rel}:{n}: {layer} includes {target}, of the higher layer {target_layer}")
        elif SIDE_BY_SIDE.get(layer) == target_layer:
            problems.append(f"{rel}:{n}: {layer} includes {target}: {layer} and {target_layer} stand side by side")
for p in problems:
    print(p)
print(f"check_layers.py: {len(files)} files, {len(problems)} problems", file=sys.stderr)
sys.exit(1 if problems else 0)
