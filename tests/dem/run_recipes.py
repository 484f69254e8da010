#!/usr/bin/env python3
"""nbscope tests/dem: LAMMPS cases around docs/dem.md's recipes (the recipes' own commands run in
tests/docs/test_docs_commands.cpp).

Usage: run_recipes.py NBSCOPE SRC_DIR OUT_DIR CASE
  CASE neighbours: the LAMMPS recipe of docs/dem.md (its `<!-- run: lammps FILE -->` block) without
      `cutoff radius`, so that LAMMPS lists its neighbour list: verify and replay fail and say, in one
      hint line, how many listed pairs do not touch, a count held to an exact oracle (check_contacts.py).
  CASE gaps: tests/dem/lammps_gaps.in (atoms deleted with `compress no`: ids with gaps): `pairs` of
      a frame writes its atom ids under `id1,id2`, equal to the exact contacts, and `verify --pairs`
      of that file says right.
Exit 77 (CTest's skip) when lmp is missing, unless CI=true.
"""
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, HERE)
import check_contacts  # noqa: E402  (the independent exact oracle)

SIMULATORS = {"lammps": ("lmp", "LMP", "lammps")}


def fail(case, text):
    print(f"FAIL ({case}): {text}", file=sys.stderr)
    sys.exit(1)


def lammps_recipe(src):
    """The text of docs/dem.md's block marked `<!-- run: lammps FILE -->`."""
    with open(os.path.join(src, "docs/dem.md"), encoding="utf-8") as handle:
        text = handle.read()
    found = re.search(r"<!-- run: lammps \S+ -->\s*```[^\n]*\n(.*?)```", text, re.S)
    if not found:
        raise SystemExit("docs/dem.md: no `<!-- run: lammps FILE -->` recipe")
    return found.group(1)


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


def last_timestep(out, atoms):
    """The last timestep of the dumps ATOMS.*.dump in OUT."""
    return max(int(name.split(".")[1]) for name in os.listdir(out) if name.startswith(atoms + ".") and name.endswith(".dump"))


def neighbours(src, nbscope, out):
    case = "neighbours"
    text = lammps_recipe(src)
    forgotten = text.replace("patom1 patom2 cutoff radius", "patom1 patom2")
    if forgotten == text:
        fail(case, "the LAMMPS recipe has no `property/local patom1 patom2 cutoff radius` to leave out")
    simulate(case, "lammps", "in.neighbours", forgotten, out)
    env = nbscope_env(nbscope, out)
    t = last_timestep(out, "atoms2d")
    atoms = check_contacts.read_atoms(os.path.join(out, f"atoms2d.{t}.dump"))
    listed = check_contacts.read_contacts(os.path.join(out, f"contacts2d.{t}.dump"))[t]
    box, frame = atoms[t]
    # The oracle: listed pairs that do not touch (|c_i - c_j|^2 >= (r_i + r_j)^2, exactly).
    apart = len({(min(i, j), max(i, j)) for i, j in listed if not check_contacts.touching(frame[i], frame[j], box)})
    if apart < 10:
        fail(case, f"LAMMPS listed only {apart} pairs apart: no neighbour list to test the hint on")
    hint = f"hint: {apart} of the "
    said = expect(case, f"nbscope verify --input atoms2d.{t}.dump --2d --pairs contacts2d.{t}.dump --touching strict", 1,
                  f"{hint}{len(listed)} listed pairs do not touch (gaps up to ", "verify", out, env)
    if sum("neighbour list rather than contacts?" in row and "cutoff radius" in row for row in said.splitlines()) != 1:
        fail(case, "verify's hint is not one line naming the neighbour list and `cutoff radius`")
    said = expect(case, f"nbscope replay --headless --2d --dump atoms2d.{t}.dump --contacts contacts2d.{t}.dump --touching strict "
                  "--algorithm recorded", 1, hint, "replay", out, env)
    if sum("neighbour list rather than contacts?" in row for row in said.splitlines()) != 1:
        fail(case, "replay's hint is not one line")
    print(f"--- {case}: {apart} of {len(listed)} listed pairs apart, said by verify and replay")


def gaps(src, nbscope, out):
    case = "gaps"
    with open(os.path.join(HERE, "lammps_gaps.in"), encoding="utf-8") as handle:
        simulate(case, "lammps", "in.gaps", handle.read(), out)
    env = nbscope_env(nbscope, out)
    t = last_timestep(out, "atoms")
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
    if len(argv) != 5 or argv[4] not in ("neighbours", "gaps"):
        print("usage: run_recipes.py NBSCOPE SRC_DIR OUT_DIR neighbours|gaps", file=sys.stderr)
        return 2
    nbscope, src, out, case = argv[1], os.path.realpath(argv[2]), os.path.realpath(argv[3]), argv[4]
    (neighbours if case == "neighbours" else gaps)(src, nbscope, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
