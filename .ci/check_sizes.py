#!/usr/bin/env python3
"""Checks the size limits of docs/development.md: no source file under src/, cli/ or include/ longer
than 700 lines, no function body longer than 120 lines. Functions are found as text: a brace that opens
after a parameter list ')' (with qualifiers such as const, noexcept, override or a trailing return type,
or a constructor's initialiser list) at namespace or class scope, not after if/for/while/switch/catch;
its body runs to the matching brace (comments and string literals are skipped). Exit 0 within the
limits, else 1 with one line per file or function over its limit.   usage: .ci/check_sizes.py [REPO]"""
import pathlib
import re
import sys

MAX_FILE_LINES = 700
MAX_FUNCTION_LINES = 120
CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else|return)\s*$")
SCOPE = re.compile(r"\b(namespace|class|struct|union|enum)\b[^;()]*$")


def strip(text):
    """The text with comments, string and character literals blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (j + 1 - i)); i = j + 1
        else:
            out.append(c); i += 1
    return "".join(out)


def functions(code):
    """(name, first line, line count) of every function body at namespace or class scope."""
    stack = []  # for each open brace: True when it opens a function body
    found = []
    for i, c in enumerate(code):
        if c == "{":
            in_function = any(stack)
            head = code[max(0, i - 400):i]
            head = head[max(head.rfind(";"), head.rfind("}"), head.rfind("{")) + 1:].strip()
            is_function = (not in_function and ")" in head and not SCOPE.search(head)
                           and not CONTROL.search(head.split(")")[0].split("(")[0].strip())
                           and not head.endswith("=") and "=" not in head.split("(")[0])
            stack.append(is_function)
            if is_function:
                name = re.findall(r"([~\w:<>]+)\s*\(", head)
                found.append([name[0] if name else "?", code.count("\n", 0, i) + 1, i])
        elif c == "}" and stack:
            if stack.pop():
                for f in reversed(found):
                    if len(f) == 3:
                        f.append(code.count("\n", 0, i) + 1 - f[1] + 1)
                        break
    return [(f[0], f[1], f[3]) for f in found if len(f) == 4]


root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
problems = []
files = sorted(p for d in ("src", "cli", "include") for p in (root / d).rglob("*") if p.suffix in (".hpp", ".cpp"))
for path in files:
    rel = path.relative_to(root).as_posix()
    text = path.read_text()
    lines = text.count("\n")
    if lines > MAX_FILE_LINES:
        problems.append(f"{rel}: {lines} lines, over {MAX_FILE_LINES}")
    for name, line, count in functions(strip(text)):
        if count > MAX_FUNCTION_LINES:
            problems.append(f"{rel}:{line}: {name} is {count} lines, over {MAX_FUNCTION_LINES}")
for p in problems:
    print(p)
print(f"check_sizes.py: {len(files)} files, {len(problems)} over a limit", file=sys.stderr)
sys.exit(1 if problems else 0)
