#!/usr/bin/env python3
"""nbscope tests/dem: the docs' LAMMPS and LIGGGHTS recipes run as written (docs/dem.md "Recipes").

Usage: run_recipes.py NBSCOPE SRC_DIR OUT_DIR CASE
  CASE lammps | liggghts: every block the docs mark `<!-- run: CODE FILE -->` (the input, written to
      FILE and run by lmp / liggghts in OUT_DIR) or `<!-- run: CODE -->` (nbscope commands, one a
      line, each followed by `# → TEXT` or `# → exit N: TEXT`: its exit status, 0 unless given, and
      words its output must hold) in docs/dem.md, docs/formats.md and README.md; a block marked
      `<!-- part-of: CODE -->` must be lines of CODE's input. Every command must state its outcome.
  CASE neighbours: the LAMMPS recipe without `cutoff radius` (LAMMPS then lists its neighbour list):
      verify and replay fail and say, in one hint line, how many listed pairs do not touch, a count
      held to an exact oracle (check_contacts.py).
  CASE gaps: tests/dem/lammps_gaps.in (atoms deleted with `compress no`: ids with gaps): `pairs` of
      a frame writes its atom ids under `id1,id2`, equal to the exact contacts, and `verify --pairs`
      of that file says right.
Exit 77 (CTest's skip) when the simulator is missing, unless CI=true.
"""
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, HERE)
import check_contacts  # noqa: E402  (the independent exact oracle)

DOCS = ("docs/dem.md", "docs/formats.md", "README.md")
SIMULATORS = {"lammps": ("lmp", "LMP", "lammps"), "liggghts": ("liggghts", "LIGGGHTS", "liggghts")}


def fail(case, text):
    print(f"FAIL ({case}): {text}", file=sys.stderr)
    sys.exit(1)


def marked_blocks(src):
    """[(doc, line, marker words, block text)] for every fenced block right after a run/part-of mark."""
    out = []
    for doc in DOCS:
        with open(os.path.join(src, doc), encoding="utf-8") as handle:
            lines = handle.read().splitlines()
        k = 0
        while k < len(lines):
            mark = re.fullmatch(r"<!-- (run|part-of): ([^>]*?) -->", lines[k].strip())
            k += 1
            if not mark:
                continue
            while k < len(lines) and not lines[k].strip():
                k += 1
            if k >= len(lines) or not lines[k].startswith("```"):
                raise SystemExit(f"{doc}:{k}: a mark without a fenced block after it")
            start = k + 1
            end = start
            while end < len(lines) and not lines[end].startswith("```"):
                end += 1
            out.append((doc, start, [mark.group(1)] + mark.group(2).split(), "\n".join(lines[start:end]) + "\n"))
            k = end + 1
    return out


def commands_of(doc, line, text):
    """[(command, want_exit, want_text, where)] of a commands block; each must state its outcome."""
    out = []
    pending = None
    rows = text.splitlines()
    k = 0
    while k < len(rows):
        row, where = rows[k], f"{doc}:{line + k + 1}"
        k += 1
        outcome = re.match(r"#\s*→\s*(?:exit (\d+):\s*)?(.*)$", row.strip())
        if outcome:
            if pending is None:
                raise SystemExit(f"{where}: an outcome with no command before it")
            out.append((pending[0], int(outcome.group(1) or 0), outcome.group(2).strip(), pending[1]))
            pending = None
            continue
        if not row.strip() or row.lstrip().startswith("#"):
            continue
        command = row
        while command.endswith("\\") and k < len(rows):
            command = command[:-1] + rows[k]
            k += 1
        if pending is not None:
            raise SystemExit(f"{pending[1]}: a command without its outcome (`# → ...` after it)")
        pending = (command.strip(), where)
    if pending is not None:
        raise SystemExit(f"{pending[1]}: a command without its outcome (`# → ...` after it)")
    return out


def simulate(case, code, input_name, input_text, out):
    program, variable, package = SIMULATORS[code]
    simulator = os.environ.get(variable) or shutil.which(program)
    if not simulator or not os.access(simulator, os.X_OK):
        if os.environ.get("CI") == "true":
            fail(case, f"{program} is not installed (CI=true: this test must run)")
        print(f"SKIP ({case}): {program} is not installed (apt-get install {package}; scripts/dev deps)")
        sys.exit(77)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with open(os.path.join(out, input_name), "w", encoding="utf-8") as handle:
        handle.write(input_text)
    # -screen none would crash LIGGGHTS (fix insert/pack prints to the NULL screen).
    run = subprocess.run([simulator, "-in", input_name, "-log", f"log.{program}", "-echo", "none", "-screen", "/dev/null"],
                         cwd=out, capture_output=True, text=True, check=False)
    if run.returncode != 0:
        fail(case, f"{program} -in {input_name} exited {run.returncode}: {run.stdout[-2000:]}{run.stderr[-2000:]}")


def nbscope_env(nbscope, out):
    """The environment in which `nbscope` is the binary under test."""
    bin_dir = os.path.join(out, ".bin")
    os.makedirs(bin_dir, exist_ok=True)
    link = os.path.join(bin_dir, "nbscope")
    if not os.path.lexists(link):
        os.symlink(os.path.realpath(nbscope), link)
    return dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))


def expect(case, command, want_exit, want_text, where, out, env):
    """Runs `command` (bash, in OUT) and holds it to its exit status and words; returns its output."""
    run = subprocess.run(["bash", "-c", command], cwd=out, env=env, capture_output=True, text=True, check=False)
    said = run.stdout + run.stderr
    print(f"--- {where}: {command}: exit {run.returncode}\n{said}", end="" if said.endswith("\n") else "\n")
    if run.returncode != want_exit:
        fail(case, f"{where}: `{command}` exited {run.returncode}, the page says {want_exit}")
    if want_text not in said:
        fail(case, f"{where}: `{command}` does not say '{want_text}'")
    return run.stdout


def recipe(case, src, nbscope, out):
    blocks = [b for b in marked_blocks(src) if b[2][1] == case]
    inputs = [b for b in blocks if b[2][0] == "run" and len(b[2]) == 3]
    if len(inputs) != 1:
        fail(case, f"expected one `<!-- run: {case} FILE -->` input block in the docs, found {len(inputs)}")
    doc, line, words, input_text = inputs[0]
    for part_doc, part_line, _, part in (b for b in blocks if b[2][0] == "part-of"):
        for k, row in enumerate(part.splitlines()):
            if row.strip() and row.rstrip() not in input_text.splitlines():
                fail(case, f"{part_doc}:{part_line + k + 1}: '{row.strip()}' is not a line of the recipe ({doc}:{line})")
    commands = [c for b in blocks if b[2][0] == "run" and len(b[2]) == 2 for c in commands_of(b[0], b[1], b[3])]
    if not commands:
        fail(case, f"no `<!-- run: {case} -->` commands in the docs")
    simulate(case, case, words[2], input_text, out)
    env = nbscope_env(nbscope, out)
    for command, want_exit, want_text, where in commands:
        expect(case, command, want_exit, want_text, where, out, env)
    print(f"--- {case}: {len(commands)} commands of the docs ran and said what the docs say")


def last_timestep(out):
    return max(int(name.split(".")[1]) for name in os.listdir(out) if name.startswith("atoms.") and name.endswith(".dump"))


def neighbours(src, nbscope, out):
    case = "neighbours"
    inputs = [b for b in marked_blocks(src) if b[2][:2] == ["run", "lammps"] and len(b[2]) == 3]
    text = inputs[0][3]
    forgotten = text.replace("patom1 patom2 cutoff radius", "patom1 patom2")
    if forgotten == text:
        fail(case, "the LAMMPS recipe has no `property/local patom1 patom2 cutoff radius` to leave out")
    simulate(case, "lammps", "in.neighbours", forgotten, out)
    env = nbscope_env(nbscope, out)
    t = last_timestep(out)
    atoms = check_contacts.read_atoms(os.path.join(out, f"atoms.{t}.dump"))
    listed = check_contacts.read_contacts(os.path.join(out, f"contacts.{t}.dump"))[t]
    box, frame = atoms[t]
    # The oracle: listed pairs that do not touch (|c_i - c_j|^2 >= (r_i + r_j)^2, exactly).
    apart = len({(min(i, j), max(i, j)) for i, j in listed if not check_contacts.touching(frame[i], frame[j], box)})
    if apart < 10:
        fail(case, f"LAMMPS listed only {apart} pairs apart: no neighbour list to test the hint on")
    hint = f"hint: {apart} of the "
    said = expect(case, f"nbscope verify --input atoms.{t}.dump --2d --pairs contacts.{t}.dump --touching strict", 1,
                  f"{hint}{len(listed)} listed pairs do not touch (gaps up to ", "verify", out, env)
    if sum("neighbour list rather than contacts?" in row and "cutoff radius" in row for row in said.splitlines()) != 1:
        fail(case, "verify's hint is not one line naming the neighbour list and `cutoff radius`")
    said = expect(case, f"nbscope replay --headless --2d --dump atoms.{t}.dump --contacts contacts.{t}.dump --touching strict "
                  "--algorithm recorded", 1, hint, "replay", out, env)
    if sum("neighbour list rather than contacts?" in row for row in said.splitlines()) != 1:
        fail(case, "replay's hint is not one line")
    print(f"--- {case}: {apart} of {len(listed)} listed pairs apart, said by verify and replay")


def gaps(src, nbscope, out):
    case = "gaps"
    with open(os.path.join(HERE, "lammps_gaps.in"), encoding="utf-8") as handle:
        simulate(case, "lammps", "in.gaps", handle.read(), out)
    env = nbscope_env(nbscope, out)
    t = last_timestep(out)
    box, frame = check_contacts.read_atoms(os.path.join(out, f"atoms.{t}.dump"))[t]
    if sorted(frame) == list(range(1, len(frame) + 1)):
        fail(case, "the ids have no gaps: nothing to test")
    expect(case, f"nbscope pairs --input atoms.{t}.dump --touching strict --output pairs.csv", 0, "elements (3D)", "pairs", out, env)
    with open(os.path.join(out, "pairs.csv"), encoding="ascii") as handle:
        rows = handle.read().splitlines()
    if rows[0] != "id1,id2":
        fail(case, f"pairs.csv's header is '{rows[0]}': it must say it holds atom ids (id1,id2)")
    written = {tuple(int(v) for v in row.split(",")) for row in rows[1:]}
    exact = check_contacts.exact_contacts(box, frame)
    if written != exact or len(exact) < 10:
        fail(case, f"pairs.csv holds {len(written)} pairs, the exact contacts are {len(exact)} ({len(written ^ exact)} differ)")
    if max(max(p) for p in exact) <= len(frame):
        fail(case, "no contact names an id past the atom count: the ids' gaps are not exercised")
    expect(case, f"nbscope verify --input atoms.{t}.dump --pairs pairs.csv --touching strict", 0,
           f"{len(exact)} right, 0 missing, 0 extra", "verify", out, env)
    print(f"--- {case}: {len(frame)} atoms, ids up to {max(frame)}, {len(exact)} contacts round-tripped")


def main(argv):
    if len(argv) != 5 or argv[4] not in ("lammps", "liggghts", "neighbours", "gaps"):
        print("usage: run_recipes.py NBSCOPE SRC_DIR OUT_DIR lammps|liggghts|neighbours|gaps", file=sys.stderr)
        return 2
    nbscope, src, out, case = argv[1], os.path.realpath(argv[2]), os.path.realpath(argv[3]), argv[4]
    {"lammps": lambda: recipe("lammps", src, nbscope, out), "liggghts": lambda: recipe("liggghts", src, nbscope, out),
     "neighbours": lambda: neighbours(src, nbscope, out), "gaps": lambda: gaps(src, nbscope, out)}[case]()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
