#!/usr/bin/env python3
"""The mutation benchmark of examples/detectors/nbs_reference.c (issue 37, point 7): every tagged line
of the reference (a trailing /* @N */ comment, N its 1-based pseudocode line) is mutated one change at
a time, each mutant is built as a plugin and run headless on the bundled scenes, and each is classified
by what nbscope said: equivalent on this data, located at the mutated line, located elsewhere, caught
but not located, API error, hang, crash, or nbscope itself aborted.

Index: constants | tagged lines (code and comments apart) | the four operators | mutants (ids, subset)
| build | run one mutant over the scenes | classify one run | results.json, table.md | main.

Usage: mutants.py --nbscope PATH [--subset] [--only m001,m017] [--scenes pile,gas] [--frames N]
                  [--jobs N] [--out DIR] [--source FILE] [--cc CC] [--detector-timeout S] [--list]
Exit 0 when the benchmark ran; 1 when the unmodified reference is not clean, or (--subset) when a
mutant took nbscope itself down; 2 on a usage error.
"""
import argparse
import concurrent.futures
import json
import os
import re
import signal
import subprocess
import sys
import time
from dataclasses import dataclass

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["pile", "dense-box", "gas", "lattice", "mixed-sizes"]
OPERATORS = ["relational", "off-by-one", "delete", "swap"]  # the sort order within a line

EQUIVALENT = "equivalent"
LOCATED = "located at the mutated line"
ELSEWHERE = "located elsewhere"
NOT_LOCATED = "caught, not located"
API_ERROR = "API error"
HANG = "hang"
CRASH = "crash"
ABORTED = "nbscope aborted"
UNCLASSIFIED = "unclassified"  # an outcome none of the above describes: shown, never hidden
VERDICTS = [LOCATED, ELSEWHERE, NOT_LOCATED, API_ERROR, HANG, CRASH, ABORTED, UNCLASSIFIED]

# Each relational operator's neighbours: the operators that differ from it in exactly one of the three
# outcomes (less, equal, greater), so each mutant is one step away, never always-true or always-false.
ROR_NEIGHBOURS = {"<": ["<=", "!="], "<=": ["<", "=="], ">": [">=", "!="], ">=": [">", "=="],
                  "==": ["<=", ">="], "!=": ["<", ">"]}
# Arrays and coordinates a slip of the pen exchanges (whole identifiers, on one line).
SWAPS = [("B0", "B1"), ("X", "Y"), ("x", "y"), ("ix", "iy"), ("nx", "ny"), ("x_min", "y_min"),
         ("xk", "yk"), ("yh", "B0"), ("ix", "jx")]
# Names that hold a value only inside one loop (jx, the mask's column): a swap with one of them is made
# only on lines where it appears; elsewhere it would read an unset variable and test the compiler.
LOOP_LOCAL = {"jx"}

TAG = re.compile(r"/\* @(\d+) \*/\s*$")
RELATIONAL = re.compile(r"(?<![-<>=!])(<=|>=|==|!=|<|>)(?![<>=])")  # not ->, <<, >>
PLUS_MINUS_ONE = re.compile(r"(?<=[\w\])]) ([+-]) 1\b(?!\.)")  # `a + 1`, `a - 1`; not the sentinel -1
BOUND = re.compile(r"(<=?) ([A-Za-z_]\w*)\b(?!\s*[\[(.]|\s*[-+] )")  # `< n`, `<= last`
LITERAL_BOUND = re.compile(r"(?:(?:[<>]=?|==|!=|[+-]|:) |\bfor \(\w+ = )([01])\b(?!\.)")
DECLARATION = re.compile(r"^(const\s+)?(int|int32_t|int64_t|double|size_t|nbs_\w+)\s+\**\w+\s*[=;,\[]")
# glibc's words when the heap it guards was written over (AddressSanitizer's, in the asan build):
# nbscope's own memory, whoever wrote it.
HEAP_ABORT = re.compile(r"free\(\): invalid|double free|malloc\(\): |corrupted (size|double-linked)|"
                        r"munmap_chunk\(\)|malloc_consolidate|ERROR: AddressSanitizer")
# plugin_library.cpp's guard (signals_crash.cpp names the signal) and its watchdog.
CRASH_LINE = re.compile(r"crashed with SIG[A-Z]+")
HANG_LINE = "did not return within"


@dataclass
class Mutant:
    id: str
    line: int          # 1-based line of the source file
    tag: int           # the pseudocode line a bug here should be located at
    operator: str
    original: str      # the line's code, comments left out
    mutated: str
    column: int = 0    # where the change is (ordering only)
    verdict: str = ""
    scene: str = ""
    exit_code: object = None
    stderr_line: str = ""
    signal: str = ""   # the signal that killed nbscope, when one did
    located: object = None


# ---- tagged lines ---------------------------------------------------------------------------------

def tagged_lines(text):
    """(line number, code, tag) of each tagged line; the code is the part before its comments."""
    out = []
    for number, raw in enumerate(text.split("\n"), 1):
        m = TAG.search(raw)
        if m:
            out.append((number, raw[:raw.find("/*")].rstrip(), int(m.group(1))))
    return out


def masked(code):
    """The code with string literals blanked, so no operator looks inside "x-list"; same length."""
    return re.sub(r'"(\\.|[^"\\])*"', lambda m: '"' + " " * (len(m.group(0)) - 2) + '"', code)


# ---- the four operators: each yields (column, mutated code) ---------------------------------------

def relational(code):
    for m in RELATIONAL.finditer(masked(code)):
        for other in ROR_NEIGHBOURS[m.group(1)]:
            yield m.start(), code[:m.start()] + other + code[m.end():]


def off_by_one(code):
    """`a +/- 1` -> `a`; a bound `< n` -> `< n - 1`; a literal 0 or 1 that is a bound or index, plus one."""
    plain = masked(code)
    for m in PLUS_MINUS_ONE.finditer(plain):
        yield m.start(), code[:m.start()] + code[m.end():]
    for m in BOUND.finditer(plain):
        yield m.start(), code[:m.end(2)] + " - 1" + code[m.end(2):]
    for m in LITERAL_BOUND.finditer(plain):
        yield m.start(1), code[:m.start(1)] + str(int(m.group(1)) + 1) + code[m.end(1):]


def delete(code):
    """The line's one statement, gone (an empty statement left); never a declaration, a `for` header, a return."""
    body = code.strip()
    if not body.endswith(";") or re.match(r"(for|return)\b", body) or DECLARATION.match(body):
        return
    yield len(code) - len(code.lstrip()), code[:len(code) - len(code.lstrip())] + ";"


def swap(code):
    plain = masked(code)
    for a, b in SWAPS:
        pattern = re.compile(r"\b(%s|%s)\b" % (re.escape(a), re.escape(b)))
        hits = list(pattern.finditer(plain))
        names = {m.group(1) for m in hits}
        if not hits or (LOOP_LOCAL & {a, b}) - names:
            continue
        parts, last = [], 0
        for m in hits:
            parts += [code[last:m.start()], b if m.group(1) == a else a]
            last = m.end()
        yield hits[0].start(), "".join(parts) + code[last:]


OPERATOR_FUNCTIONS = {"relational": relational, "off-by-one": off_by_one, "delete": delete, "swap": swap}


# ---- mutants ----------------------------------------------------------------------------------------

def generate(text):
    """Every mutant of the tagged lines, in a stable order (line, operator, column, text), ids m001...;
    a change that one operator already made on the same line is made once."""
    found, seen = [], set()
    for number, code, tag in tagged_lines(text):
        for operator in OPERATORS:
            for column, mutated in sorted(set(OPERATOR_FUNCTIONS[operator](code))):
                if mutated != code and (number, mutated) not in seen:
                    seen.add((number, mutated))
                    found.append(Mutant("", number, tag, operator, code.strip(), mutated.strip(), column))
    for k, m in enumerate(found, 1):
        m.id = "m%03d" % k
    return found


def subset(mutants):
    """About eight mutants for CI: per operator, the ones a quarter and three quarters along its ids."""
    chosen = []
    for operator in OPERATORS:
        of_op = [m for m in mutants if m.operator == operator]
        for k in sorted({len(of_op) // 4, (3 * len(of_op)) // 4}):
            if k < len(of_op):
                chosen.append(of_op[k])
    return sorted(chosen, key=lambda m: m.id)


def mutant_source(text, mutant):
    """The whole file with the mutant's line changed (its comments, the tag among them, kept)."""
    lines = text.split("\n")
    raw = lines[mutant.line - 1]
    cut = raw.find("/*")
    indent = raw[:len(raw) - len(raw.lstrip())]
    lines[mutant.line - 1] = indent + mutant.mutated + " " + raw[cut:]
    return "\n".join(lines)


# ---- build ------------------------------------------------------------------------------------------

def build(args, name, source_text):
    """Writes OUT/NAME.c and builds OUT/NAME.so as a user would; the compiler's first error, or None."""
    c_file = os.path.join(args.out, name + ".c")
    so_file = os.path.join(args.out, name + ".so")
    with open(c_file, "w") as f:
        f.write(source_text)
    detectors = os.path.join(ROOT, "examples", "detectors")
    command = [args.cc, "-std=c99", "-O1", "-shared", "-fPIC", "-I" + os.path.join(ROOT, "include"),
               "-I" + detectors, c_file, os.path.join(detectors, "nbs_plugin.c"), "-o", so_file]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode == 0:
        return None
    errors = [l for l in done.stderr.splitlines() if "error" in l]
    return (errors or done.stderr.splitlines() or ["exit %d" % done.returncode])[0]


# ---- run one mutant over the scenes -----------------------------------------------------------------

def scene_path(scene):
    return scene if scene.endswith(".json") else os.path.join(ROOT, "assets", "scenes", scene + ".json")


def run_scene(args, name, scene):
    """One headless run; (exit code or "timeout", stderr, stdout, report path)."""
    stem = os.path.basename(scene_path(scene))[:-len(".json")]
    report = os.path.join(args.out, "%s-%s.report.json" % (name, stem))
    if os.path.exists(report):
        os.remove(report)  # a report left by an earlier benchmark must not stand for this run's
    command = [args.nbscope, "headless", "--scene", scene_path(scene), "--detector-lib",
               os.path.join(args.out, name + ".so"), "--frames", str(args.frames), "--report", report,
               "--detector-timeout", "%g" % args.detector_timeout, "--quiet"]
    # The outer timeout catches what the per-call watchdog cannot: a plugin slow on every frame, or
    # nbscope itself stuck after the plugin wrote over its memory.
    try:
        done = subprocess.run(command, capture_output=True, text=True, errors="replace", cwd=ROOT,
                              timeout=args.detector_timeout + 120)
        return done.returncode, done.stderr, done.stdout, report
    except subprocess.TimeoutExpired as e:
        stderr = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
        return "timeout", stderr, "", report


def evaluate(args, mutant, text):
    """Builds the mutant and runs it scene by scene up to the first that is not clean, which decides."""
    error = build(args, mutant.id, mutant_source(text, mutant))
    if error is not None:
        mutant.verdict, mutant.stderr_line = "does not compile", error
        return mutant
    for scene in args.scenes:
        code, stderr, stdout, report = run_scene(args, mutant.id, scene)
        verdict, located = classify(code, stderr, stdout, report, mutant.tag)
        mutant.scene, mutant.exit_code, mutant.stderr_line = scene, code, error_line(stderr)
        if isinstance(code, int) and code < 0:
            mutant.signal = signal.Signals(-code).name  # nbscope killed by it: often with nothing on stderr
        if verdict is not None:
            mutant.verdict, mutant.located = verdict, located
            return mutant
    mutant.verdict, mutant.scene, mutant.exit_code, mutant.stderr_line = EQUIVALENT, "", 0, ""
    return mutant


# ---- classify one run -------------------------------------------------------------------------------

def error_line(stderr):
    """nbscope's error line (the one that says why the run ended), else stderr's first line; with
    glibc's heap message after it when there is one (an error, then the process dies on its way out)."""
    lines = [l.strip() for l in stderr.splitlines() if l.strip()]
    errors = [l for l in lines if "error:" in l][:1] + [l for l in lines if HEAP_ABORT.search(l)][:1]
    return " / ".join(errors or lines[:1])[:400]


def located_violation(report, stdout):
    """runs[0].violations.located of the report (written whole at the end of the run), else the
    summary line's "located: ..." text; None when the run located nothing."""
    try:
        with open(report) as f:
            located = json.load(f)["runs"][0]["violations"]["located"]
        if located is None:
            return None
        return {k: located.get(k) for k in ("frame", "operation", "kind", "line", "text")}
    except (OSError, ValueError, KeyError, IndexError, TypeError):
        m = re.search(r"; located: (.*?) \(reference", stdout)
        return {"line": None, "text": m.group(1)} if m else None


def classify(code, stderr, stdout, report, tag):
    """The verdict of one scene's run, None when it was clean, and the located violation if any.
    nbscope's own death is asked first: its messages may follow a plugin's crash line."""
    if code == "timeout":
        return HANG, None
    if code < 0 or code in (134, 139) or HEAP_ABORT.search(stderr):
        return ABORTED, None
    if HANG_LINE in stderr:
        return HANG, None
    if CRASH_LINE.search(stderr):
        return CRASH, None
    if code == 0:
        return None, None
    if code == 1:
        located = located_violation(report, stdout)
        if located is None or located.get("line") is None:  # a sentence with no operation is no place
            return NOT_LOCATED, located
        return (LOCATED if located["line"] == tag else ELSEWHERE), located
    line = error_line(stderr)
    if code == 2 and (".so" in line or re.search(r"add_pair|trace|cells", line)):
        return API_ERROR, None
    return UNCLASSIFIED, None


# ---- results.json, table.md -------------------------------------------------------------------------

def shorten(text, width=60):
    return text if len(text) <= width else text[:width - 3] + "..."


def summary_table(mutants, dropped):
    caught = [m for m in mutants if m.verdict != EQUIVALENT]
    equivalent = len(mutants) - len(caught)
    rows = ["| verdict | mutants | % of the non-equivalent |", "|---|---:|---:|"]
    for verdict in VERDICTS:
        count = sum(1 for m in caught if m.verdict == verdict)
        if count or verdict != UNCLASSIFIED:
            rows.append("| %s | %d | %.0f%% |" % (verdict, count, 100.0 * count / max(len(caught), 1)))
    rows.append("| **non-equivalent** | **%d** | 100%% |" % len(caught))
    rows.append("| equivalent (on this data) | %d | |" % equivalent)
    rows.append("| does not compile (dropped) | %d | |" % dropped)
    return "\n".join(rows)


def detail_table(mutants):
    rows = ["| id | line | tag | operator | mutated | verdict | scene | located line |",
            "|---|---:|---:|---|---|---|---|---:|"]
    for m in mutants:
        if m.verdict == EQUIVALENT:
            continue
        located = m.located.get("line") if m.located else ""
        shown = "deleted: " + m.original if m.operator == "delete" else m.mutated
        mutated = shorten(shown).replace("|", "\\|")
        rows.append("| %s | %d | %d | %s | `%s` | %s | %s | %s |" % (
            m.id, m.line, m.tag, m.operator, mutated, m.verdict, m.scene, "" if located is None else located))
    return "\n".join(rows)


def write_results(args, mutants, dropped, seconds):
    everyone = sorted(mutants + dropped, key=lambda m: m.id)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump([{k: v for k, v in vars(m).items() if k != "column"} for m in everyone], f, indent=1)
    head = ("# Mutation benchmark of %s\n\n%d mutants of its tagged lines, %d of them built; each run headless "
            "on %s for %d frames (the first scene that is not clean decides); %.0f s.\n\n"
            % (os.path.relpath(args.source, ROOT), len(everyone), len(mutants), ", ".join(args.scenes),
               args.frames, seconds))
    summary = summary_table(mutants, len(dropped))
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(head + summary + "\n\n## The non-equivalent mutants\n\n" + detail_table(mutants) + "\n")
    return summary


# ---- main -------------------------------------------------------------------------------------------

def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--nbscope", default=os.path.join(ROOT, "build", "release", "src", "app", "nbscope"))
    p.add_argument("--source", default=os.path.join(ROOT, "examples", "detectors", "nbs_reference.c"))
    p.add_argument("--out", default=os.path.join(ROOT, "build", "mutants"))
    p.add_argument("--cc", default=os.environ.get("CC") or "cc")
    p.add_argument("--scenes", help="comma-separated scene names (assets/scenes) or paths")
    p.add_argument("--frames", type=int)
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    p.add_argument("--detector-timeout", type=float, default=10.0)
    p.add_argument("--only", help="comma-separated mutant ids (m001,m017)")
    p.add_argument("--subset", action="store_true", help="CI: ~8 mutants on pile.json for 30 frames")
    p.add_argument("--list", action="store_true", help="print the mutants and run none")
    args = p.parse_args(argv)
    args.scenes = args.scenes.split(",") if args.scenes else (["pile"] if args.subset else SCENES)
    args.frames = args.frames if args.frames is not None else (30 if args.subset else 120)
    args.nbscope, args.source, args.out = (os.path.abspath(a) for a in (args.nbscope, args.source, args.out))
    return args


def select(args, mutants):
    if args.only:
        wanted = args.only.split(",")
        unknown = sorted(set(wanted) - {m.id for m in mutants})
        if unknown:
            print("mutants: no mutant %s (there are m001..%s)" % (", ".join(unknown), mutants[-1].id), file=sys.stderr)
            sys.exit(2)
        return [m for m in mutants if m.id in wanted]
    return subset(mutants) if args.subset else mutants


def reference_is_clean(args, text):
    """The unmodified reference on every scene: a benchmark whose reference fails measures nothing."""
    error = build(args, "reference", text)
    if error is not None:
        print("mutants: the reference does not compile: " + error, file=sys.stderr)
        return False
    for scene in args.scenes:
        code, stderr, stdout, _report = run_scene(args, "reference", scene)
        if code != 0:
            said = error_line(stderr) or shorten(stdout.strip().split("\n")[0], 300)
            print("mutants: the unmodified reference is not clean on %s (exit %s): %s" % (scene, code, said),
                  file=sys.stderr)
            return False
    return True


def run_all(args, mutants, text):
    """Every mutant on a pool of --jobs workers (each a compiler, then nbscope: processes, not threads)."""
    done = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(args.jobs, 1)) as pool:
        futures = [pool.submit(evaluate, args, m, text) for m in mutants]
        for future in concurrent.futures.as_completed(futures):
            done.append(future.result())
            if sys.stderr.isatty():
                print("\rmutants: %d/%d" % (len(done), len(mutants)), end="", file=sys.stderr, flush=True)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    return sorted(done, key=lambda m: m.id)


def main(argv):
    args = parse_args(argv)
    with open(args.source) as f:
        text = f.read()
    generated = generate(text)
    mutants = select(args, generated)
    if args.list:
        for m in mutants:
            print("%s  line %d  @%d  %-10s  %s  ->  %s" % (m.id, m.line, m.tag, m.operator, m.original, m.mutated))
        return 0
    if not os.access(args.nbscope, os.X_OK):
        print("mutants: no nbscope at %s (build it, or pass --nbscope)" % args.nbscope, file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    start = time.monotonic()
    if not reference_is_clean(args, text):
        return 1
    results = run_all(args, mutants, text)
    built = [m for m in results if m.verdict != "does not compile"]
    dropped = [m for m in results if m.verdict == "does not compile"]
    seconds = time.monotonic() - start
    print(write_results(args, built, dropped, seconds))
    print("mutants: %d generated, %d of them run, %d dropped (do not compile); %.0f s; %s" % (
        len(generated), len(results), len(dropped), seconds, os.path.join(args.out, "table.md")))
    aborted = [m.id for m in built if m.verdict == ABORTED]
    if args.subset and aborted:
        print("mutants: nbscope itself aborted on %s" % ", ".join(aborted), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
