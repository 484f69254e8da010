#!/usr/bin/env python3
"""nbscope's house rules for source files (docs/architecture.md, "House rules"), run as a CTest.

Fails, one line per offence, when a file under src/ is longer than MAX_LINES lines, or when a header
holds more than MAX_HEADER_BODY lines of function bodies (a header declares; the code lives in the
.cpp). A one-line body counts as one line. Usage: house_rules.py SOURCE_DIR, or house_rules.py --self-test (plants one offence of each kind
in a scratch tree and fails unless both are named).
"""
import pathlib
import re
import sys

MAX_LINES = 500        # a file over this asks to be split along its concerns
MAX_HEADER_BODY = 60   # lines of function bodies a header may hold (inline accessors, small templates)

# A line that opens a function body: a parameter list's ")" (then qualifiers) and "{", and not a
# type, a namespace, an initialiser ("= {") or a control statement.
FUNCTION_OPEN = re.compile(r"\)\s*(const|noexcept|override|final|->\s*[\w:<>&*, ]+|\s)*\{")
NOT_A_FUNCTION = re.compile(r"^\s*(struct|class|union|namespace|enum|if|for|while|switch|else|do|return)\b|=\s*\{")


def strip(line: str) -> str:
    """The line without its // comment and string literals (braces inside them do not count)."""
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])*'", "''", line)
    return line.split("//", 1)[0]


def header_body_lines(lines: list[str]) -> int:
    total = 0
    depth_in_body = 0  # brace depth inside the current function body; 0 when outside
    for raw in lines:
        line = strip(raw)
        if depth_in_body == 0:
            if FUNCTION_OPEN.search(line) and not NOT_A_FUNCTION.search(line):
                opened = line[line.index("{"):]
                depth = opened.count("{") - opened.count("}")
                total += 1
                depth_in_body = max(depth, 0)
            continue
        total += 1
        depth_in_body += line.count("{") - line.count("}")
        depth_in_body = max(depth_in_body, 0)
    return total


def offences_in(root: pathlib.Path) -> list[str]:
    offences = []
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h", ".c"):
            continue
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
        shown = path.relative_to(root.parent)
        if len(lines) > MAX_LINES:
            offences.append(f"{shown}: {len(lines)} lines, over {MAX_LINES}: split it along its concerns")
        if path.suffix in (".hpp", ".h"):
            body = header_body_lines(lines)
            if body > MAX_HEADER_BODY:
                offences.append(f"{shown}: {body} lines of function bodies in a header, over {MAX_HEADER_BODY}: "
                                "move them to a .cpp")
    return offences


def self_test() -> int:
    import tempfile
    with tempfile.TemporaryDirectory() as scratch:
        root = pathlib.Path(scratch) / "src"
        (root / "core").mkdir(parents=True)
        (root / "core" / "long.cpp").write_text("int x;\n" * (MAX_LINES + 1))
        (root / "core" / "short.cpp").write_text("int y;\n" * MAX_LINES)
        body = "".join(f"  int v{i} = {i};\n" for i in range(MAX_LINES // 8))
        (root / "core" / "bodies.hpp").write_text(f"#pragma once\ninline int f(int a) {{\n{body}  return a;\n}}\n")
        (root / "core" / "decls.hpp").write_text("#pragma once\nstruct S {\n  int get() const { return 1; }\n};\nint g(int);\n")
        found = offences_in(root)
    expected = ["src/core/long.cpp:", "src/core/bodies.hpp:"]
    missing = [e for e in expected if not any(o.startswith(e) for o in found)]
    extra = [o for o in found if not any(o.startswith(e) for e in expected)]
    for line in missing:
        print(f"house_rules --self-test: the planted offence {line} was not named")
    for line in extra:
        print(f"house_rules --self-test: a clean file was named: {line}")
    return 1 if missing or extra else 0


def main() -> int:
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    offences = offences_in(pathlib.Path(sys.argv[1]))
    for line in offences:
        print(line)
    return 1 if offences else 0


if __name__ == "__main__":
    sys.exit(main())
