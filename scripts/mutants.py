#!/usr/bin/env python3
"""The mutation benchmark of examples/detectors/nbs_reference.c and nbs3d_reference.c (issue 37, point 7):
every tagged line of the reference (a trailing /* @N */ comment, N its 1-based pseudocode line) is
mutated one change at a time, each mutant is built as a plugin and run headless on the bundled scenes
(a 3D reference: replayed on the LIGGGHTS pour, assets/examples/pour3d), and each is classified by what
nbscope said: equivalent on this data, located at the mutated line, located at the first operation it
changed, located elsewhere, caught but not located, API error, hang, crash, or nbscope itself aborted.
"The first operation it changed": the located operation is the first at which the frame's trace
differs from the unmodified reference's on the same frame (scripts/mutants_trace_shim.c writes both);
a crash, hang or refused trace call located "after operation N" where the first change is operation
N+1 is located there too.

Index: constants | tagged lines (code and comments apart) | the four operators | mutants (ids, subset)
| build | run one mutant over the scenes | the first changed operation | classify one run |
results.json, table.md | main.

Usage: mutants.py --nbscope PATH [--subset] [--only m001,m017] [--scenes pile,gas] [--frames N]
                  [--jobs N] [--out DIR] [--source FILE] [--cc CC] [--detector-timeout S] [--list]
       mutants.py --credit --out DIR [--source FILE]   (a finished run's mutants located elsewhere, again)
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
import threading
import time
from dataclasses import dataclass

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["pile", "dense-box", "gas", "lattice", "mixed-sizes"]
# The 3D inputs: replayed dumps (`nbscope replay --dump GLOB`), by name; a 3D reference runs on these.
DUMPS = {"pour3d": "assets/examples/pour3d/atoms.*.dump"}
INPUTS_3D = ["pour3d"]
OPERATORS = ["relational", "off-by-one", "delete", "swap"]  # the sort order within a line

EQUIVALENT = "equivalent"
LOCATED = "located at the mutated line"
FIRST_CHANGED = "located at the first changed operation"
ELSEWHERE = "located elsewhere"
NOT_LOCATED = "caught, not located"
API_ERROR = "API error"
HANG = "hang"
CRASH = "crash"
ABORTED = "nbscope aborted"
UNCLASSIFIED = "unclassified"  # an outcome none of the above describes: shown, never hidden
VERDICTS = [LOCATED, FIRST_CHANGED, ELSEWHERE, NOT_LOCATED, API_ERROR, HANG, CRASH, ABORTED, UNCLASSIFIED]

# Each relational operator's neighbours: the operators that differ from it in exactly one of the three
# outcomes (less, equal, greater), so each mutant is one step away, never always-true or always-false.
ROR_NEIGHBOURS = {"<": ["<=", "!="], "<=": ["<", "=="], ">": [">=", "!="], ">=": [">", "=="],
                  "==": ["<=", ">="], "!=": ["<", ">"]}
# Arrays and coordinates a slip of the pen exchanges (whole identifiers, on one line).
SWAPS = [("B0", "B1"), ("X", "Y"), ("x", "y"), ("ix", "iy"), ("nx", "ny"), ("x_min", "y_min"),
         ("xk", "yk"), ("yh", "B0"), ("ix", "jx")]
# The 3D reference's (nbs3d_reference.c): the 2D ones that it has, and z against y (its names: z-lists
# C/Z, y-lists B0/B1 on Y, the five rows' row_y/row_z from row_dy/row_dz).
SWAPS_3D = [("B0", "B1"), ("X", "Y"), ("x", "y"), ("ix", "iy"), ("nx", "ny"), ("xk", "yk"), ("ix", "jx"),
            ("y", "z"), ("iy", "iz"), ("ny", "nz"), ("y_min", "z_min"), ("yk", "zk"), ("Y", "Z"), ("C", "B0"),
            ("row_y", "row_z"), ("row_dy", "row_dz")]
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
# A crash or hang in nbscope_release, when nbscope closes the plugin's host after the run: the heap the
# plugin corrupted in a detection gives way there (glibc's words come from the host, passed on). The
# frames were checked before it: the run's report is its verdict; nbscope itself did not abort.
RELEASE_LINE = re.compile(r"nbscope: error: .*(crashed with SIG[A-Z]+|did not return within .*) in nbscope_release\(\)")


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
    first_change: object = None  # where its trace first differs from the reference's (located elsewhere)


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


def swap(code, swaps=SWAPS):
    plain = masked(code)
    for a, b in swaps:
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

def is_3d(text):
    """A 3D reference (nbs3d_reference.c) is built with nbs3d_plugin.c and run on 3D inputs."""
    return '#include "nbs3d_plugin.h"' in text


def generate(text):
    """Every mutant of the tagged lines, in a stable order (line, operator, column, text), ids m001...;
    a change that one operator already made on the same line is made once."""
    found, seen = [], set()
    functions = dict(OPERATOR_FUNCTIONS)
    if is_3d(text):
        functions["swap"] = lambda code: swap(code, SWAPS_3D)
    for number, code, tag in tagged_lines(text):
        for operator in OPERATORS:
            for column, mutated in sorted(set(functions[operator](code))):
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

def build(args, name, source_text, traced=False):
    """Writes OUT/NAME.c and builds OUT/NAME.so as a user would; the compiler's first error, or None.
    traced: builds OUT/NAME.traced.so instead, with scripts/mutants_trace_shim.c between the plugin and
    nbscope's trace table (frame_trace)."""
    c_file = os.path.join(args.out, name + ".c")
    so_file = os.path.join(args.out, name + (".traced.so" if traced else ".so"))
    if not traced:
        with open(c_file, "w") as f:
            f.write(source_text)
    detectors = os.path.join(ROOT, "examples", "detectors")
    plumbing = "nbs3d_plugin.c" if is_3d(source_text) else "nbs_plugin.c"
    command = [args.cc, "-std=c99", "-O1", "-shared", "-fPIC", "-I" + os.path.join(ROOT, "include"),
               "-I" + detectors, c_file, os.path.join(detectors, plumbing), "-o", so_file]
    if traced:
        command[1:1] = ["-Dnbscope_detect=nbscope_mutant_detect_inner"]
        command.insert(-2, os.path.join(ROOT, "scripts", "mutants_trace_shim.c"))
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode == 0:
        return None
    errors = [l for l in done.stderr.splitlines() if "error" in l]
    return (errors or done.stderr.splitlines() or ["exit %d" % done.returncode])[0]


# ---- run one mutant over the scenes -----------------------------------------------------------------

def scene_path(scene):
    return scene if scene.endswith(".json") else os.path.join(ROOT, "assets", "scenes", scene + ".json")


def scene_stem(scene):
    return scene if scene in DUMPS else os.path.basename(scene_path(scene))[:-len(".json")]


def scene_command(args, scene, frames):
    """The command that runs a plugin on one input: headless on a scene (frames 0..frames), or replay of
    a 3D dump (its first `frames` frames, all when None)."""
    if scene in DUMPS:
        command = [args.nbscope, "replay", "--headless", "--dump", os.path.join(ROOT, DUMPS[scene])]
        return command + (["--frames", str(frames)] if frames is not None else [])
    return [args.nbscope, "headless", "--scene", scene_path(scene), "--frames", str(frames)]


def run_scene(args, name, scene, frames=None, library=None, env=None):
    """One headless run; (exit code or "timeout", stderr, stdout, report path)."""
    report = os.path.join(args.out, "%s-%s.report.json" % (name, scene_stem(scene)))
    if os.path.exists(report):
        os.remove(report)  # a report left by an earlier benchmark must not stand for this run's
    command = scene_command(args, scene, args.frames if frames is None else frames) + [
        "--detector-lib", library or os.path.join(args.out, name + ".so"), "--report", report,
        "--detector-timeout", "%g" % args.detector_timeout, "--quiet"]
    # The outer timeout catches what the per-call watchdog cannot: a plugin slow on every frame, or
    # nbscope itself stuck after the plugin wrote over its memory.
    try:
        done = subprocess.run(command, capture_output=True, text=True, errors="replace", cwd=ROOT,
                              timeout=args.detector_timeout + 120, env=env)
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
            if verdict == ELSEWHERE:
                credit_first_change(args, mutant, scene, text)
            return mutant
    mutant.verdict, mutant.scene, mutant.exit_code, mutant.stderr_line = EQUIVALENT, "", 0, ""
    return mutant


# ---- the first operation a mutant changed ----------------------------------------------------------
# nbscope's CLI names a frame's located operation, not the frame's whole trace; the plugin's side has it.
# So a mutant located elsewhere is built again with scripts/mutants_trace_shim.c, which writes every
# trace call of one frame (with the values each push, clear and set wrote) as the plugin makes it, and
# run again up to that frame, as is the unmodified reference; the frames are the same (the plugin's
# pairs do not move Box2D's bodies, and a dump's are read). Operations are numbered as nbscope numbers
# them (phases included, from 1): the shim's count must equal the report's "operations" for the
# comparison to stand.

_reference_traces = {}
_reference_lock = threading.Lock()


SHIM_WORDS = {"call", "declare", "phase", "push", "clear", "visit", "test", "set"}  # mutants_trace_shim.c's lines


def frame_trace(args, name, scene, frame):
    """The operations of frame `frame` of OUT/NAME.traced.so on `scene`, one text line each (the shim's),
    and how many calls nbscope made for that frame; (None, 0) when none was written."""
    path = os.path.join(args.out, "%s-%s-f%d.trace" % (name, scene_stem(scene), frame))
    if os.path.exists(path):
        os.remove(path)
    env = dict(os.environ, NBSCOPE_MUTANT_TRACE=path, NBSCOPE_MUTANT_TRACE_FRAME=str(frame))
    # headless runs frames 0..N (N >= 1); replay the first N
    frames = frame + 1 if scene in DUMPS else max(frame, 1)
    run_scene(args, name + ".traced", scene, frames, os.path.join(args.out, name + ".traced.so"), env)
    try:
        with open(path) as f:
            lines = f.read().split("\n")
    except OSError:
        return None, 0
    lines.pop()  # a crash inside a trace call leaves its line unfinished (no newline): no operation
    # A crashed call's host and the host nbscope starts to record it again up to the crash both write
    # the file: a fragment one left is no operation.
    lines = [l for l in lines if l.split(" ", 1)[0] in SHIM_WORDS]
    calls = sum(1 for l in lines if l.startswith("call "))
    last = max(i for i, l in enumerate(lines) if l.startswith("call ")) if calls else -1
    return [l for l in lines[last + 1:] if not l.startswith("declare ")], calls


def reference_trace(args, scene, frame):
    with _reference_lock:  # each (scene, frame) once, whichever worker asks first
        key = (scene, frame)
        if key not in _reference_traces:
            _reference_traces[key] = frame_trace(args, "reference", scene, frame)[0]
        return _reference_traces[key]


def credit_first_change(args, mutant, scene, text):
    """A mutant located elsewhere is located at the first operation it changed when its located
    operation is the first index at which its frame's trace differs from the reference's on the same
    frame (kind, line, element, other, list, cell, contact, the values written); mutant.first_change
    says where that is, or why it could not be told."""
    located = mutant.located or {}
    frame, operation = located.get("frame"), located.get("operation")
    if frame is None or operation is None:
        mutant.first_change = {"note": "the located violation names no frame or operation"}
        return
    if build(args, mutant.id, mutant_source(text, mutant), traced=True) is not None:
        mutant.first_change = {"note": "the traced build failed"}
        return
    mine, calls = frame_trace(args, mutant.id, scene, frame)
    theirs = reference_trace(args, scene, frame)
    if mine is None or theirs is None:
        mutant.first_change = {"note": "no trace of frame %d was written" % frame}
        return
    first = next((i for i, (a, b) in enumerate(zip(mine, theirs)) if a != b), min(len(mine), len(theirs)))
    change = {"operation": first + 1, "operations": len(mine), "calls": calls,
              "mutant": mine[first] if first < len(mine) else "(its trace ends)",
              "reference": theirs[first] if first < len(theirs) else "(its trace ends)"}
    # A crash, a hang or a trace call nbscope refused ends the call: nbscope names the boundary ("after
    # operation N"), the first change is operation N+1, the one the call never made right (the shim
    # wrote a refused call before nbscope saw it: one operation more than nbscope's).
    after = located.get("text", "").startswith("after operation") and located.get("operations") in (len(mine), len(mine) - 1)
    if mine == theirs:
        change = {"note": "its trace of frame %d equals the reference's" % frame, "operations": len(mine)}
    elif after and calls == 1 and operation == first:
        mutant.verdict = FIRST_CHANGED
    elif calls != 1 or (located.get("operations") is not None and located["operations"] != len(mine)):
        change["note"] = "the shim's trace (%d operations, %d calls) is not the one nbscope located in (%s)" % (
            len(mine), calls, located.get("operations"))
    elif operation == first + 1:
        mutant.verdict = FIRST_CHANGED
    mutant.first_change = change


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
        return {k: located.get(k) for k in ("frame", "operation", "operations", "kind", "contract", "line", "text")}
    except (OSError, ValueError, KeyError, IndexError, TypeError):
        m = re.search(r"; located: (.*?) \(reference", stdout)
        return {"line": None, "text": m.group(1)} if m else None


def classify(code, stderr, stdout, report, tag):
    """The verdict of one scene's run, None when it was clean, and the located violation if any.
    nbscope's own death is asked first: its messages may follow a plugin's crash line."""
    if code == "timeout":
        return HANG, None
    released = code == 2 and RELEASE_LINE.search(stderr) is not None
    # glibc's heap words with nbscope's own exit (1, 2) are the plugin's host's, passed on: nbscope lived.
    if code < 0 or code in (134, 139) or (HEAP_ABORT.search(stderr) and code not in (0, 1, 2)):
        return ABORTED, None
    if released:  # the run's frames were checked (and located) before the host's release gave way
        code, stderr = (1, "") if report is not None else (code, stderr)
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
    rows = ["| id | line | tag | operator | mutated | verdict | scene | located line | located op | first changed op |",
            "|---|---:|---:|---|---|---|---|---:|---:|---|"]
    for m in mutants:
        if m.verdict == EQUIVALENT:
            continue
        located = m.located.get("line") if m.located else ""
        shown = "deleted: " + m.original if m.operator == "delete" else m.mutated
        mutated = shorten(shown).replace("|", "\\|")
        operation = m.located.get("operation") if m.located else None
        change = m.first_change or {}
        changed = ("%s `%s` (reference: `%s`)" % (change["operation"], change["mutant"], change["reference"])
                   if "operation" in change else change.get("note", ""))
        rows.append("| %s | %d | %d | %s | `%s` | %s | %s | %s | %s | %s |" % (
            m.id, m.line, m.tag, m.operator, mutated, m.verdict, m.scene, "" if located is None else located,
            "" if operation is None else operation, changed.replace("|", "\\|")))
    return "\n".join(rows)


def write_results(args, mutants, dropped, seconds):
    everyone = sorted(mutants + dropped, key=lambda m: m.id)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump([{k: v for k, v in vars(m).items() if k != "column"} for m in everyone], f, indent=1)
    frames = "every recorded frame" if args.frames is None else "%d frames" % args.frames
    head = ("# Mutation benchmark of %s\n\n%d mutants of its tagged lines, %d of them built; each run headless "
            "on %s for %s (the first input that is not clean decides); %.0f s.\n\n"
            % (os.path.relpath(args.source, ROOT), len(everyone), len(mutants), ", ".join(args.scenes),
               frames, seconds))
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
    p.add_argument("--scenes", help="comma-separated scene names (assets/scenes) or paths; a 3D reference's "
                   "inputs are named dumps (%s)" % ", ".join(sorted(DUMPS)))
    p.add_argument("--frames", type=int)
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    p.add_argument("--detector-timeout", type=float, default=10.0)
    p.add_argument("--only", help="comma-separated mutant ids (m001,m017)")
    p.add_argument("--subset", action="store_true", help="CI: ~8 mutants on pile.json for 30 frames (3D: on pour3d)")
    p.add_argument("--list", action="store_true", help="print the mutants and run none")
    p.add_argument("--credit", action="store_true",
                   help="run no mutant: take OUT/results.json of a finished run and look again for the first "
                        "changed operation of each mutant located elsewhere; rewrites results.json and table.md")
    args = p.parse_args(argv)
    args.nbscope, args.source, args.out = (os.path.abspath(a) for a in (args.nbscope, args.source, args.out))
    try:
        with open(args.source) as f:
            three_d = is_3d(f.read())
    except OSError:
        p.error("cannot read --source %s" % args.source)
    if three_d:  # replayed 3D dumps: every recorded frame unless --frames
        args.scenes = args.scenes.split(",") if args.scenes else INPUTS_3D
    else:
        args.scenes = args.scenes.split(",") if args.scenes else (["pile"] if args.subset else SCENES)
        args.frames = args.frames if args.frames is not None else (30 if args.subset else 120)
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
    error = build(args, "reference", text) or build(args, "reference", text, traced=True)
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


def credit_again(args, generated, text):
    """--credit: the verdicts of OUT/results.json (a run of this --source), each mutant located elsewhere
    (or at the first changed operation) looked at again; the table rewritten."""
    with open(os.path.join(args.out, "results.json")) as f:
        saved = {r["id"]: r for r in json.load(f)}
    mutants = []
    for m in generated:
        r = saved.get(m.id)
        if r is None:
            continue
        if (r["line"], r["mutated"]) != (m.line, m.mutated):
            print("mutants: %s of results.json is not %s's (another --source?)" % (m.id, m.id), file=sys.stderr)
            return 2
        for key in ("verdict", "scene", "exit_code", "stderr_line", "signal", "located", "first_change"):
            setattr(m, key, r.get(key))
        if m.verdict == FIRST_CHANGED:
            m.verdict = ELSEWHERE
        if m.verdict == ELSEWHERE and m.located and m.located.get("operations") is None:
            m.located = located_violation(  # a results.json written before "operations" was kept
                os.path.join(args.out, "%s-%s.report.json" % (m.id, scene_stem(m.scene))), "") or m.located
        mutants.append(m)
    start = time.monotonic()
    if build(args, "reference", text, traced=True) is not None:
        print("mutants: the reference does not build with the trace shim", file=sys.stderr)
        return 1
    again = [m for m in mutants if m.verdict == ELSEWHERE]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(args.jobs, 1)) as pool:
        list(pool.map(lambda m: credit_first_change(args, m, m.scene, text), again))
    built = [m for m in mutants if m.verdict != "does not compile"]
    dropped = [m for m in mutants if m.verdict == "does not compile"]
    print(write_results(args, built, dropped, time.monotonic() - start))
    print("mutants: %d located elsewhere looked at again, %d of them at the first changed operation; %s" % (
        len(again), sum(1 for m in again if m.verdict == FIRST_CHANGED), os.path.join(args.out, "table.md")))
    return 0


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
    if args.credit:
        return credit_again(args, generated, text)
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
