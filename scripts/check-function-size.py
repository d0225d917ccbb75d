#!/usr/bin/env python3
"""Lists every function body in src/ longer than 80 lines and every function declared in a
public header (src/**/*.hpp) with more than 6 parameters, and fails when one of them is not
on the allow-list (scripts/function-size-allowlist.txt: known offenders, to be split; the
list only shrinks). Run by .ci/run before the builds.

  scripts/check-function-size.py            # check src/ against the allow-list
  scripts/check-function-size.py --all      # list every offender, allowed or not
  scripts/check-function-size.py --self-test

The parser reads C++ as text: comments, string and character literals are blanked, then
each '{' whose header (the text since the previous ';', '{' or '}') ends like a function
signature opens a function; the outermost such body is measured from the line of its '{'
to the line of its '}'. Lambdas and local classes count toward their enclosing function.
"""

import argparse
import os
import re
import sys

MAX_LINES = 80
MAX_PARAMETERS = 6
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ALLOW_LIST = os.path.join(ROOT, "scripts", "function-size-allowlist.txt")
CONTROL = re.compile(r"^(if|for|while|switch|catch|else|do|try)\b|\b(if|for|while|switch|catch)\s*\(")
SIGNATURE_END = re.compile(r"\)\s*(const|noexcept|override|final|mutable|&|&&|->[^{;]*|\s)*$")


def blank_comments_and_literals(text):
    """The text with comments and literals replaced by spaces (newlines kept)."""
    keep_lines = lambda m: re.sub(r"[^\n]", " ", m.group(0))
    pattern = re.compile(
        r'//[^\n]*|/\*.*?\*/|R"(?P<d>[^(]*)\(.*?\)(?P=d)"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
        re.S)
    return pattern.sub(keep_lines, text)


def function_header(text, brace):
    start = max(text.rfind(";", 0, brace), text.rfind("{", 0, brace), text.rfind("}", 0, brace))
    return " ".join(text[start + 1:brace].split())


def is_function_header(header):
    if not header or CONTROL.search(header) or not SIGNATURE_END.search(header):
        return False
    before_parameters = header.split("(")[0]
    # `x = f(...) {` is an initialiser, `[...](...) {` a lambda
    return "=" not in before_parameters and not before_parameters.rstrip().endswith("]")


def function_bodies(text):
    """(lines, first line, header, start, end) of every outermost function body of the
    blanked `text` (start and end: offsets of its braces)."""
    found, stack, line = [], [], 1
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "{":
            header = function_header(text, i)
            stack.append((is_function_header(header), line, header, i))
        elif c == "}" and stack:
            is_function, first, header, start = stack.pop()
            if is_function and not any(entry[0] for entry in stack):
                found.append((line - first + 1, first, header, start, i))
    return found


def long_functions(text):
    """(lines, first line, header) of every outermost function body."""
    return [body[:3] for body in function_bodies(blank_comments_and_literals(text))]


def parameter_count(parameters):
    depth, count, seen = 0, 0, False
    for c in parameters:
        if c in "(<[{":
            depth += 1
        elif c in ")>]}":
            depth -= 1
        elif c == "," and depth == 0:
            count += 1
        if not c.isspace():
            seen = True
    stripped = parameters.strip()
    return 0 if not seen or stripped == "void" else count + 1


def long_parameter_lists(text):
    """(parameters, line, name) of every function declared with more than MAX_PARAMETERS."""
    text = blank_comments_and_literals(text)
    bodies = [(start, end) for *_, start, end in function_bodies(text)]
    found = []
    for m in re.finditer(r"\b([A-Za-z_][A-Za-z_0-9:~]*)\s*\(", text):
        if any(start < m.start() < end for start, end in bodies):
            continue  # a call inside a function body
        name = m.group(1)
        if name in ("if", "for", "while", "switch", "return", "sizeof", "decltype", "alignas",
                    "static_assert", "noexcept", "catch", "defined", "TEST", "TEST_F"):
            continue
        depth, j = 1, m.end()
        while j < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[j], 0)
            j += 1
        after = text[j:j + 40].lstrip()
        if not re.match(r"(const\b|noexcept\b|override\b|final\b|->|;|\{|=\s*(default|delete|0))",
                        after):
            continue
        count = parameter_count(text[m.end():j - 1])
        if count > MAX_PARAMETERS:
            found.append((count, text.count("\n", 0, m.start()) + 1, name))
    return found


def offenders(root):
    rows = []
    for folder, _, files in os.walk(os.path.join(root, "src")):
        for name in sorted(files):
            if not name.endswith((".cpp", ".hpp", ".inc")):
                continue
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            for lines, first, header in long_functions(text):
                if lines > MAX_LINES:
                    rows.append((f"{rel}: {function_name(header)}", f"{lines} lines (line {first})"))
            if name.endswith(".hpp"):
                for count, line, fname in long_parameter_lists(text):
                    rows.append((f"{rel}: {fname} parameters", f"{count} parameters (line {line})"))
    return rows


def function_name(header):
    before = header.split("(")[0].split()
    return before[-1] if before else header


def read_allow_list():
    if not os.path.exists(ALLOW_LIST):
        return set()
    with open(ALLOW_LIST, encoding="utf-8") as f:
        return {line.strip() for line in f if line.strip() and not line.startswith("#")}


def self_test():
    code = """
    // a comment with { braces } and a signature f(int) {
    int short_one(int a) { return a; }
    struct S { void m() const {
    """ + "x();\n" * 85 + """
    } };
    void g() { auto l = [&](int x) {
    """ + "y();\n" * 90 + """
    }; if (true) { z(); } }
    const char* s = "f() {";
    """
    found = {function_name(h): n for n, _, h in long_functions(code)}
    assert found.get("short_one") == 1, found
    assert found.get("m", 0) > 80, found
    assert found.get("g", 0) > 90 and "l" not in found, found
    header = "void seven(int a, int b, std::pair<int, int> c, int d, int e, int f, int g);\n" \
             "void six(int a, int b, int c, int d, int e, int f) const;\nvoid none();\n" \
             "inline void calls() { seven(1, 2, {}, 4, 5, 6, 7); }\n"
    names = [name for _, _, name in long_parameter_lists(header)]
    assert names == ["seven"], names
    print("check-function-size self-test: ok")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all", action="store_true", help="list allowed offenders too")
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        self_test()
        return 0
    allowed = read_allow_list()
    rows = offenders(ROOT)
    new = [(key, what) for key, what in rows if key not in allowed]
    for key, what in (rows if args.all else new):
        print(f"{key}  [{what}]{'' if key not in allowed else '  (allow-listed)'}")
    stale = sorted(allowed - {key for key, _ in rows})
    for key in stale:
        print(f"{key}  [no longer an offender: remove it from {os.path.relpath(ALLOW_LIST, ROOT)}]")
    print(f"{len(rows)} offenders, {len(rows) - len(new)} allow-listed, {len(new)} new, "
          f"{len(stale)} stale allow-list lines (functions <= {MAX_LINES} lines, "
          f"public parameter lists <= {MAX_PARAMETERS})")
    return 1 if new or stale else 0


if __name__ == "__main__":
    sys.exit(main())
