#!/usr/bin/python3
"""Functions longer than a limit (issue 40: no function over 120 lines).

    scripts/function_lengths.py [--limit N] [--all] [PATH ...]

scans the project's own C++ code (default: include/CGAL/Hyperbolic_orbifold_Tutte/,
application/, tools/, python/src/) and prints every function longer than N lines (default
120) as `path:line name length`, the length counted from the first line of its signature (its
template header included) to the line of its closing brace (comments before the signature are
not counted; lambdas and local classes count as part of the enclosing function). Exit 1 when any is found, 0 otherwise. --all prints
every function found, whatever its length (the exit code still follows the limit).

A brace-matching scan, not a parser: comments, string and character literals (raw strings
too) are blanked first; a `{` opens a function body when the text before it, back to the
previous `;`, `{` or `}`, ends with a parameter list `(...)` followed only by qualifiers
(const, noexcept, override, a trailing return type, a constructor's initializer list, ...)
and is not a control statement (if, for, while, switch, catch) or a lambda; braces inside a
declaration (a default argument `= {}`, a member initializer `a_{x}`) are skipped. Inside a
function body, braces are only counted. Preprocessor lines are left out.
"""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATHS = ["include/CGAL/Hyperbolic_orbifold_Tutte", "application", "tools", "python/src"]
EXTENSIONS = (".h", ".hpp", ".cpp", ".cc", ".cxx", ".ipp")
CONTROL = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "alignof",
           "noexcept", "static_assert", "requires", "constexpr"}


def blank(text):
    """Comments, string and character literals replaced by spaces (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "/" and text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif c == "/" and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")
                                                          or text[i - 2:i] in ("u8",) or text[i - 1] in "uUL"):
            m = re.match(r'R"([^()\\\s]{0,16})\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            # a digit separator (1'000'000) is not a character literal
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum() \
                    and re.search(r"\b\d[\w']*$", text[max(0, i - 40):i]):
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    # preprocessor directives (with their continuation lines)
    lines = "".join(out).split("\n")
    cont = False
    for k, line in enumerate(lines):
        if cont or line.lstrip().startswith("#"):
            cont = line.rstrip().endswith("\\")
            lines[k] = ""
    return "\n".join(lines)


def strip_balanced_tail(head):
    """(rest, params): the last balanced `(...)` of head and the text before it, or None."""
    depth = 0
    for k in range(len(head) - 1, -1, -1):
        ch = head[k]
        if ch == ")":
            depth += 1
        elif ch == "(":
            depth -= 1
            if depth == 0:
                return head[:k], head[k:]
    return None


QUALIFIERS = re.compile(r"^\s*(?:(?:const|volatile|noexcept|override|final|mutable|constexpr|&&|&|"
                        r"noexcept\s*\([^()]*\)|throw\s*\(\s*\))\s*)*(?:->[^{};]*)?$")


def function_name(head):
    """The function's name when the text before `{` ends as a function definition, else None."""
    head = head.strip()
    if not head:
        return None
    # a constructor's initializer list: `Name(args) : a_(x), b_{y}` -- cut at the ` : `
    m = re.search(r"\)\s*(?:noexcept\s*)?:(?!:)", head)
    if m:
        head = head[:m.start() + 1]
    # trailing qualifiers and return type after the parameter list
    k = head.rfind(")")
    if k < 0:
        return None
    if not QUALIFIERS.match(head[k + 1:]):
        return None
    split = strip_balanced_tail(head[:k + 1])
    if split is None:
        return None
    before, _ = split
    before = before.rstrip()
    if before.endswith("]") or before.endswith(">") and not re.search(r"operator\s*[<>=]*>$", before):
        # a lambda `[...](...) {` or a template-id call; lambdas belong to their function
        if before.endswith("]"):
            return None
    m = re.search(r"((?:~?[A-Za-z_]\w*(?:\s*<[^<>;{}()]*>)?\s*::\s*)*(?:operator\s*(?:\(\)|[^\s(]+)|~?[A-Za-z_]\w*))$",
                  before)
    if not m:
        return None
    name = re.sub(r"\s+", "", m.group(1))
    last = name.split("::")[-1]
    if last in CONTROL:
        return None
    prefix = before[:m.start()].rstrip()
    # `x = f(...) {` or `return g(...) {` are not definitions
    if prefix.endswith("=") or prefix.endswith(",") or prefix.endswith("(") or prefix.endswith("return"):
        return None
    return name


def functions(text):
    """(line, name, length) of each function defined in text (already blanked)."""
    found = []
    depth = 0
    body_depth = None  # depth at which the current function body opened
    start = 0          # offset after the previous `;`, `{` or `}` outside functions
    name, name_line = None, 0
    line_starts = [0]
    for k, ch in enumerate(text):
        if ch == "\n":
            line_starts.append(k + 1)

    def line_of(off):
        lo, hi = 0, len(line_starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if line_starts[mid] <= off:
                lo = mid
            else:
                hi = mid - 1
        return lo + 1

    paren = 0
    skip = 0  # depth inside braces that are part of a declaration (`f(int a = {})`, `A() : a_{1}`)
    for k, ch in enumerate(text):
        if skip:
            skip += 1 if ch == "{" else -1 if ch == "}" else 0
            continue
        if body_depth is not None:
            if ch == "{":
                depth += 1
            elif ch == "}":
                depth -= 1
                if depth == body_depth:
                    end_line = line_of(k)
                    found.append((name_line, name, end_line - name_line + 1))
                    body_depth = None
                    start = k + 1
            continue
        if ch == "(":
            paren += 1
        elif ch == ")":
            paren = max(0, paren - 1)
        elif ch == ";" and paren == 0:
            start = k + 1
        elif ch == "{":
            head = text[start:k]
            if paren > 0 or (re.search(r"\)\s*(?:noexcept\s*)?:(?!:)", head) and re.search(r"[\w>]\s*$", head)):
                skip = 1  # a default argument's or a member initializer's braces
                continue
            fname = function_name(head)
            if fname:
                # the signature's first line: skip leading blanks and a template header
                lead = re.match(r"\s*(?:(?:public|private|protected)\s*:(?!:)\s*)*", head)
                sig = start + lead.end()
                name, name_line = fname, line_of(sig)
                body_depth = depth
            depth += 1
            start = k + 1
        elif ch == "}":
            depth = max(0, depth - 1)
            start = k + 1
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--limit", type=int, default=120)
    ap.add_argument("--all", action="store_true", help="print every function found")
    ap.add_argument("paths", nargs="*")
    args = ap.parse_args()
    paths = args.paths or [os.path.join(ROOT, p) for p in DEFAULT_PATHS]
    files = []
    for p in paths:
        if os.path.isfile(p):
            files.append(p)
        for dirpath, dirnames, filenames in os.walk(p):
            dirnames.sort()
            files += [os.path.join(dirpath, f) for f in sorted(filenames) if f.endswith(EXTENSIONS)]
    over = 0
    for path in files:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = blank(f.read())
        shown = os.path.relpath(path, ROOT) if os.path.abspath(path).startswith(ROOT + os.sep) else path
        for line, name, length in functions(text):
            if length > args.limit:
                over += 1
            if length > args.limit or args.all:
                print(f"{shown}:{line} {name} {length}")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
