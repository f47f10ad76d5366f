#!/usr/bin/env python3
"""Checks that the documentation says what ogive does (docs/development.md, "Documentation").

    python3 .ci/check_docs.py --columns OGIVE          # docs/cli.md's column table against OGIVE
    python3 .ci/check_docs.py --write-columns OGIVE    # rewrite that table from OGIVE
    python3 .ci/check_docs.py --commands BUILD_DIR [FILE.md ...]

--columns: the table between `<!-- columns:begin -->` and `<!-- columns:end -->` in docs/cli.md must be
exactly the one generated from what `OGIVE SUBCOMMAND --columns help` prints (CSV column,unit,meaning)
for every subcommand that `OGIVE --help` lists, and for `limit --thrust-line min`: one row per column in
the order of first appearance, with the subcommands that print it. Exit 0 when equal, 1 with a one-line
summary of the difference.

--write-columns: writes that table into docs/cli.md between the markers.

--commands: runs every ```sh (or ```bash) block of README.md and docs/*.md (or of the FILEs given), each
block as one bash script with `set -eo pipefail`, from the repository's top, stdin from /dev/null.
The README's two commands (install, build, run) are not run here: .ci/run runs them word for word, and
this check fails if README.md does not hold them word for word. A block whose info string is `sh ci`
is not run either: each of its commands must appear word for word in .ci/run, which runs it. Blocks of
output (```text, ```csv) are never run; one marked `output` (```csv output, ```text output) that
follows a run block with nothing but blank lines between them must be exactly what that block prints. Fails (exit 1, naming file and line of the block) when a block
exits non-zero, runs longer than --timeout seconds or prints other than its `output` block, or when a
tracked file changed during the run
(doc commands must not modify tracked files). Afterwards removes every file the blocks created that
git does not track (compared with `git ls-files --others` before the run), and the directories they
created. In a working tree shared with other work, a new untracked file is removed only when a block
names it (its path, its file name, or a new top-level directory holding it); others are listed and
left alone. BUILD_DIR is where ogive was built: the blocks call ./build/ogive, which is redirected to
BUILD_DIR/ogive when BUILD_DIR is not ./build.
"""
import argparse
import csv
import hashlib
import io
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

REPO = pathlib.Path(__file__).resolve().parent.parent
CLI_DOC = REPO / "docs" / "cli.md"
BEGIN, END = "<!-- columns:begin -->", "<!-- columns:end -->"
# Command lines that print columns beyond their subcommand's default (a variant with other rows).
VARIANTS = [(["limit", "--thrust-line", "min"], "limit --thrust-line"), (["spread", "--path"], "spread --path")]
# The README's two commands, as .ci/run runs them.
README_COMMANDS = [
    "bash .ci/install_deps.sh && cmake --preset release && cmake --build --preset release && "
    "./build/ogive thrust --eccentricity 0:1:11",
    "bash .ci/install_deps.sh && cmake --preset release && cmake --build --preset release && "
    "ctest --preset release",
]
RUN_LANGUAGES = {"sh", "bash"}


# ---------------------------------------------------------------------------------------------------
# The column table.

def run_ogive(ogive, args):
    done = subprocess.run([ogive, *args], capture_output=True, text=True, stdin=subprocess.DEVNULL)
    if done.returncode != 0:
        sys.exit(f"check_docs: `{ogive} {' '.join(args)}` exited {done.returncode}: {done.stderr.strip()}")
    return done.stdout


def subcommands(ogive):
    """The subcommands that `OGIVE --help` lists, in its order."""
    names, inside = [], False
    for line in run_ogive(ogive, ["--help"]).splitlines():
        if line.startswith("Subcommands:"):
            inside = True
        elif inside:
            match = re.match(r"  (\S+)\s", line)
            if not match:
                break
            names.append(match.group(1))
    if not names:
        sys.exit(f"check_docs: `{ogive} --help` lists no subcommands")
    return names


def columns(ogive):
    """[(name, unit, meaning, [command lines that print it])] in order of first appearance."""
    order, seen = [], {}
    for args, label in [([name], name) for name in subcommands(ogive)] + VARIANTS:
        rows = list(csv.reader(io.StringIO(run_ogive(ogive, [*args, "--columns", "help"]))))
        if not rows or rows[0] != ["column", "unit", "meaning"]:
            sys.exit(f"check_docs: `{ogive} {' '.join(args)} --columns help` does not start with column,unit,meaning")
        for name, unit, meaning in rows[1:]:
            if name not in seen:
                seen[name] = (name, unit, meaning, [])
                order.append(name)
            elif seen[name][1:3] != (unit, meaning):
                sys.exit(f"check_docs: column {name} has another unit or meaning in `{label}`")
            if not any(label.startswith(have + " ") for have in seen[name][3]):
                seen[name][3].append(label)
    return [seen[name] for name in order]


def cell(text):
    return text.replace("|", "\\|")


def column_table(ogive):
    every = set(subcommands(ogive))
    lines = ["| column | unit | meaning | printed by |", "|---|---|---|---|"]
    for name, unit, meaning, printed_by in columns(ogive):
        by = "every command" if set(printed_by) == every else ", ".join(printed_by)
        lines.append(f"| `{name}` | {cell(unit)} | {cell(meaning)} | {by} |")
    return "\n".join(lines)


def split_cli_doc():
    text = CLI_DOC.read_text()
    if text.count(BEGIN) != 1 or text.count(END) != 1 or text.index(BEGIN) > text.index(END):
        sys.exit(f"check_docs: docs/cli.md needs one {BEGIN} and one {END} after it")
    head, rest = text.split(BEGIN)
    table, tail = rest.split(END)
    return head, table.strip("\n"), tail


def table_names(table):
    """Column name -> its row, from a markdown table of the generated form."""
    rows = {}
    for line in table.splitlines():
        match = re.match(r"\| `([^`]+)` \|", line)
        if match:
            rows[match.group(1)] = line
    return rows


def summarize(names, limit=4):
    shown = ", ".join(names[:limit])
    return shown + (f" and {len(names) - limit} more" if len(names) > limit else "")


def check_columns(ogive):
    _, have, _ = split_cli_doc()
    want = column_table(ogive)
    if have == want:
        print(f"check_docs: docs/cli.md's column table is {ogive}'s ({len(table_names(want))} columns)")
        return 0
    have_rows, want_rows = table_names(have), table_names(want)
    missing = [n for n in want_rows if n not in have_rows]
    extra = [n for n in have_rows if n not in want_rows]
    changed = [n for n in want_rows if n in have_rows and have_rows[n] != want_rows[n]]
    parts = []
    if missing:
        parts.append(f"{len(missing)} missing ({summarize(missing)})")
    if extra:
        parts.append(f"{len(extra)} not printed by ogive ({summarize(extra)})")
    if changed:
        parts.append(f"{len(changed)} changed ({summarize(changed)})")
    if not parts:
        parts.append("same rows, other order or layout")
    print(f"check_docs: docs/cli.md's column table differs from {ogive}'s --columns help: {'; '.join(parts)}; "
          f"python3 .ci/check_docs.py --write-columns {ogive} rewrites it")
    return 1


def write_columns(ogive):
    head, _, tail = split_cli_doc()
    table = column_table(ogive)
    CLI_DOC.write_text(f"{head}{BEGIN}\n{table}\n{END}{tail}")
    print(f"check_docs: wrote {len(table_names(table))} columns into docs/cli.md")
    return 0


# ---------------------------------------------------------------------------------------------------
# The commands.

def blocks(path):
    """(line of the opening fence, line of the closing one, info string, text) for every fenced block."""
    found, lines, i = [], path.read_text().splitlines(), 0
    while i < len(lines):
        match = re.match(r"^(\s*)(`{3,}|~{3,})\s*(.*)$", lines[i])
        if not match:
            i += 1
            continue
        indent, fence, info = len(match.group(1)), match.group(2), match.group(3).strip()
        body, j = [], i + 1
        while j < len(lines) and not re.match(rf"^\s*{re.escape(fence[0])}{{{len(fence)},}}\s*$", lines[j]):
            body.append(lines[j][indent:] if lines[j][:indent].strip() == "" else lines[j].lstrip())
            j += 1
        found.append((i + 1, j + 1, info, "\n".join(body) + "\n"))
        i = j + 1
    return found


def command_lines(text):
    """The block's lines that are not blank or comments, continuation lines joined."""
    out, current = [], ""
    for line in text.splitlines():
        if not current and (not line.strip() or line.lstrip().startswith("#")):
            continue
        current += line.strip()
        if current.endswith("\\"):
            current = current[:-1] + " "
            continue
        out.append(current)
        current = ""
    if current:
        out.append(current)
    return out


def git(*args):
    return subprocess.run(["git", *args], cwd=REPO, capture_output=True, text=True, check=True).stdout


def untracked():
    """Files git does not track: untracked ones one by one, ignored ones by their top directory."""
    listed = git("ls-files", "--others", "--exclude-standard", "-z").split("\0")
    listed += git("ls-files", "--others", "--ignored", "--exclude-standard", "--directory", "-z").split("\0")
    return {p for p in listed if p}


def tracked_digests():
    digests = {}
    for rel in git("ls-files", "-z").split("\0"):
        path = REPO / rel
        if rel and path.is_file() and not path.is_symlink():
            digests[rel] = hashlib.sha1(path.read_bytes()).hexdigest()
    return digests


def named_by(rel, texts, existed_before):
    """Whether a block names this new untracked path (so that it made it)."""
    rel = rel.rstrip("/")
    top = rel.split("/")[0]
    base = rel.split("/")[-1]
    for text in texts:
        if rel in text or re.search(rf"(?<![\w.-]){re.escape(base)}(?![\w-])", text):
            return True
        if top not in existed_before and re.search(rf"(?<![\w.-]){re.escape(top)}(?![\w-])", text):
            return True
    return False


def remove(rel):
    path = REPO / rel.rstrip("/")
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    elif path.exists() or path.is_symlink():
        path.unlink()
    parent = path.parent
    while parent != REPO and parent.is_dir() and not any(parent.iterdir()) and not git("ls-files", "--", str(parent.relative_to(REPO))):
        parent.rmdir()
        parent = parent.parent


def redirect_build(text, build_dir):
    """./build/ogive (and build/ogive) -> BUILD_DIR/ogive when BUILD_DIR is not ./build."""
    if build_dir.resolve() == (REPO / "build").resolve():
        return text
    return re.sub(r"(?<![\w./-])(\./)?build/ogive(?![\w.-])", str(build_dir.resolve() / "ogive"), text)


def check_commands(build_dir, files, timeout):
    if not (build_dir / "ogive").is_file():
        print(f"check_docs: {build_dir / 'ogive'} does not exist (build first)")
        return 1
    if not files:
        files = [REPO / "README.md"] + sorted((REPO / "docs").glob("*.md"))
    failures = []
    readme = (REPO / "README.md").read_text().splitlines()
    for command in README_COMMANDS:
        if command not in (line.strip() for line in readme):
            failures.append(f"README.md: lacks the command .ci/run runs word for word: {command}")
    ci_run = (REPO / ".ci" / "run").read_text()
    ci_lines = {" ".join(line.split()) for line in command_lines(ci_run)}

    to_run, skipped = [], 0
    for path in files:
        rel = path.relative_to(REPO)
        lines = path.read_text().splitlines()
        found = blocks(path)
        for k, (line, end, info, text) in enumerate(found):
            words = info.split()
            if words[1:] == ["output"]:
                previous = found[k - 1] if k else None
                if (not previous or previous[2].split()[:1] not in ([w] for w in RUN_LANGUAGES)
                        or any(l.strip() for l in lines[previous[1]:line - 1])):
                    failures.append(f"{rel}:{line}: an output block must follow its ```sh block directly")
            if not words or words[0] not in RUN_LANGUAGES:
                continue
            expected = None
            if k + 1 < len(found) and found[k + 1][2].split()[1:] == ["output"] and not any(
                    l.strip() for l in lines[end:found[k + 1][0] - 1]):
                expected = found[k + 1][3]
            if words[1:] == ["ci"]:
                for command in command_lines(text):
                    if " ".join(command.split()) not in ci_lines:
                        failures.append(f"{rel}:{line}: not in .ci/run word for word: {command}")
                skipped += 1
                continue
            kept = "\n".join(l for l in text.splitlines() if l.strip() not in README_COMMANDS)
            if not command_lines(kept):
                skipped += 1
                continue
            to_run.append((rel, line, kept + "\n", expected))

    before_untracked = untracked()
    before_tracked = tracked_digests()
    existed_before = {p.name for p in REPO.iterdir()}
    start = time.monotonic()
    slowest = []
    for rel, line, text, expected in to_run:
        script = "set -eo pipefail\n" + redirect_build(text, build_dir)
        t0 = time.monotonic()
        try:
            done = subprocess.run(["bash", "-c", script], cwd=REPO, stdin=subprocess.DEVNULL,
                                  capture_output=True, text=True, timeout=timeout)
            code = done.returncode
            err = (done.stderr.strip() or done.stdout.strip()).splitlines()
        except subprocess.TimeoutExpired:
            code, err, done = None, [f"longer than {timeout} s"], None
        seconds = time.monotonic() - t0
        slowest.append((seconds, f"{rel}:{line}"))
        if code != 0:
            why = f"exited {code}" if code is not None else "timed out"
            failures.append(f"{rel}:{line}: the block {why}" + (f": {err[-1]}" if err else ""))
        elif expected is not None and done.stdout != expected:
            got, want = done.stdout.splitlines(), expected.splitlines()
            n = next((i for i, (a, b) in enumerate(zip(got, want)) if a != b), min(len(got), len(want)))
            failures.append(f"{rel}:{line}: prints other than its output block, from its line {n + 1}: "
                            f"{(got[n] if n < len(got) else '(nothing)')!r}")
    elapsed = time.monotonic() - start

    texts = [text for _, _, text, _ in to_run]
    after_tracked = tracked_digests()
    for rel in sorted(before_tracked):
        if after_tracked.get(rel) != before_tracked[rel]:
            failures.append(f"{rel}: a tracked file changed during the run (doc commands must not modify "
                            f"tracked files; or another process changed it)")
    left = []
    for rel in sorted(untracked() - before_untracked):
        if named_by(rel, texts, existed_before):
            remove(rel)
        else:
            left.append(rel)
    for rel in left:
        print(f"check_docs: left alone (new, untracked, named by no block): {rel}")

    slowest.sort(reverse=True)
    print(f"check_docs: {len(to_run)} blocks run, {skipped} not run (README's two commands, `sh ci`), "
          f"in {elapsed:.1f} s; slowest: " + ", ".join(f"{where} {s:.1f} s" for s, where in slowest[:3]))
    for failure in failures:
        print(f"check_docs: {failure}")
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--columns", metavar="OGIVE", help="check docs/cli.md's column table")
    mode.add_argument("--write-columns", metavar="OGIVE", help="rewrite docs/cli.md's column table")
    mode.add_argument("--commands", metavar="BUILD_DIR", help="run the ```sh blocks of README.md and docs/*.md")
    parser.add_argument("files", nargs="*", help="with --commands: only these markdown files")
    parser.add_argument("--timeout", type=float, default=300, help="seconds a block may take (default 300)")
    args = parser.parse_args()
    if args.columns:
        return check_columns(args.columns)
    if args.write_columns:
        return write_columns(args.write_columns)
    files = [pathlib.Path(f).resolve() for f in args.files]
    return check_commands(pathlib.Path(args.commands), files, args.timeout)


if __name__ == "__main__":
    sys.exit(main())
