#!/usr/bin/env python3
"""nbscope tests/dem: --export-vtk and --color-by on a real LAMMPS run (docs/export.md).

    check_vtk_export.py NBSCOPE_BIN SRC_DIR OUT_DIR

1. lmp runs tests/dem/lammps_vtk.in in OUT_DIR (emptied first): 294 spheres, 4 frames of
   atoms.*.dump (id type x y z radius vx vy vz proc, %.17g) and contacts.*.dump.
2. nbscope replay --headless --dump --contacts --touching strict --algorithm recorded --export-vtk vtk:
   every frame_TIMESTEP.vtp is read back with VTK's own vtkXMLPolyDataReader (Debian's python3-vtk9)
   and held to the dump as this script reads it: the point count, each point's id, position, radius,
   type, vx and proc (exactly: the files carry shortest round-trip numbers), the contact lines (the
   atom ids of each, kind 1) against the contacts file; series.pvd lists every frame by its timestep.
3. The same with one contact deleted from the last frame: exit 1, and that frame's file holds one line
   of kind 2 (missing) between exactly the deleted contact's atoms.
4. --color-by: vx colours the atoms (no pixel of the default fill is left; the plain picture has
   them), an unknown column and `rank` without a proc column are refused in one line, exit 2.
Exit 77 (CTest's skip) when lmp or VTK's Python module is missing, unless CI=true.
"""
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

# Debian's VTK is for Debian's python3; another interpreter first on PATH has no vtkmodules.
try:
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkCommonCore import vtkFileOutputWindow, vtkIdList, vtkOutputWindow
except ImportError:
    if os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3") and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    vtkXMLPolyDataReader = None

DEFAULT_FILL = (86, 120, 160)  # render/palette.hpp's kDynamicFill: an atom not coloured


def fail(what):
    print("FAIL (vtk_export): " + what, file=sys.stderr)
    sys.exit(1)


def skip(why):
    if os.environ.get("CI") == "true":
        fail(why + " (CI=true: this test must run)")
    print("SKIP (vtk_export): " + why)
    sys.exit(77)


def read_dump(path):
    """The frame of a `dump custom` file: timestep, column names, rows as dicts of strings."""
    with open(path) as f:
        lines = f.read().split("\n")
    timestep = int(lines[lines.index("ITEM: TIMESTEP") + 1])
    at = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[at].split()[2:]
    count = int(lines[lines.index("ITEM: NUMBER OF ATOMS") + 1])
    rows = [dict(zip(names, l.split())) for l in lines[at + 1:at + 1 + count]]
    return timestep, names, rows


def read_contacts(path):
    with open(path) as f:
        lines = f.read().split("\n")
    at = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ENTRIES"))
    return {tuple(sorted((int(float(w[0])), int(float(w[1]))))) for w in (l.split() for l in lines[at + 1:]) if len(w) >= 2}


def run(want, *args):
    r = subprocess.run(list(args), capture_output=True, text=True)
    print("--- %s: exit %d\n%s%s" % (" ".join(args[1:]), r.returncode, r.stdout, r.stderr))
    if r.returncode != want:
        fail("%s exited %d, expected %d" % (" ".join(args), r.returncode, want))
    return r


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    errors = vtkFileOutputWindow()  # VTK's own complaints, into a file: any is a failure
    errors.SetFileName(path + ".errors")
    vtkOutputWindow.SetInstance(errors)
    reader.Update()
    if reader.GetErrorCode() != 0 or (os.path.exists(path + ".errors") and os.path.getsize(path + ".errors") > 0):
        fail(path + ": VTK could not read it")
    return reader.GetOutput()


def values(array):
    return [array.GetValue(k) for k in range(array.GetNumberOfValues())]


def point_array(poly, name):
    a = poly.GetPointData().GetArray(name)
    if a is None:
        fail("no point data array '%s'" % name)
    return values(a)


def lines_of(poly):
    """Each line cell as (sorted atom ids, kind)."""
    ids = point_array(poly, "id")
    kind = values(poly.GetCellData().GetArray("kind"))
    verts = poly.GetNumberOfVerts()
    out = []
    cells = poly.GetLines()
    cells.InitTraversal()
    points = vtkIdList()
    k = 0
    while cells.GetNextCell(points):
        out.append((tuple(sorted((int(ids[points.GetId(0)]), int(ids[points.GetId(1)])))), int(kind[verts + k])))
        k += 1
    return out


def check_series(vtk_dir, dumps, contacts):
    pvd = ET.parse(os.path.join(vtk_dir, "series.pvd")).getroot()
    entries = [(int(d.get("timestep")), d.get("file")) for d in pvd.iter("DataSet")]
    if [t for t, _ in entries] != sorted(dumps):
        fail("series.pvd lists timesteps %s, the dump has %s" % ([t for t, _ in entries], sorted(dumps)))
    for timestep, name in entries:
        names, rows = dumps[timestep]
        poly = read_vtp(os.path.join(vtk_dir, name))
        if poly.GetNumberOfPoints() != len(rows):
            fail("%s: %d points, the dump's frame has %d atoms" % (name, poly.GetNumberOfPoints(), len(rows)))
        by_id = {int(r["id"]): r for r in rows}
        ids = point_array(poly, "id")
        if sorted(by_id) != [int(i) for i in ids]:
            fail(name + ": the ids are not the dump's, ascending")
        xyz = [poly.GetPoint(k) for k in range(poly.GetNumberOfPoints())]
        for column, values in (("radius", point_array(poly, "radius")), ("vx", point_array(poly, "vx")),
                               ("type", point_array(poly, "type")), ("proc", point_array(poly, "proc"))):
            for k, i in enumerate(ids):
                if float(values[k]) != float(by_id[int(i)][column]):
                    fail("%s: atom %d: %s %r, the dump says %s" % (name, i, column, values[k], by_id[int(i)][column]))
        for k, i in enumerate(ids):
            for a, c in enumerate("xyz"):
                if float(xyz[k][a]) != float(by_id[int(i)][c]):
                    fail("%s: atom %d: %s %r, the dump says %s" % (name, i, c, xyz[k][a], by_id[int(i)][c]))
        lines = lines_of(poly)
        if poly.GetNumberOfVerts() != len(rows):
            fail("%s: %d vertex cells for %d atoms" % (name, poly.GetNumberOfVerts(), len(rows)))
        yield timestep, name, lines, contacts[timestep]


def main():
    if len(sys.argv) != 4:
        print("usage: check_vtk_export.py NBSCOPE_BIN SRC_DIR OUT_DIR", file=sys.stderr)
        return 2
    nbscope, src, out = os.path.realpath(sys.argv[1]), os.path.realpath(sys.argv[2]), sys.argv[3]
    lmp = os.environ.get("LMP") or shutil.which("lmp")
    if not lmp or not os.access(lmp, os.X_OK):
        skip("lmp is not installed (apt-get install lammps; scripts/dev deps)")
    if vtkXMLPolyDataReader is None:
        skip("VTK's Python module is not installed (apt-get install python3-vtk9; scripts/dev deps)")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    os.chdir(out)
    run(0, lmp, "-in", os.path.join(src, "tests/dem/lammps_vtk.in"), "-log", "log.lmp", "-echo", "none", "-screen", "/dev/null")
    dumps, contacts = {}, {}
    for name in sorted(os.listdir(".")):
        if name.startswith("atoms."):
            t, names, rows = read_dump(name)
            dumps[t] = (names, rows)
        elif name.startswith("contacts."):
            contacts[int(name.split(".")[1])] = read_contacts(name)
    if len(dumps) < 2 or sum(len(c) for c in contacts.values()) == 0:
        fail("expected several frames with contacts, found %d frames" % len(dumps))

    # 2. The export of the run as LAMMPS wrote it: every contact a line of kind 1, nothing else.
    replay = [nbscope, "replay", "--headless", "--quiet", "--dump", "atoms.*.dump", "--touching", "strict",
              "--algorithm", "recorded"]
    run(0, *replay, "--contacts", "contacts.*.dump", "--export-vtk", "vtk")
    for timestep, name, lines, pairs in check_series("vtk", dumps, contacts):
        if sorted(p for p, k in lines if k == 1) != sorted(pairs) or any(k != 1 for _, k in lines):
            fail("%s: the contact lines are not the contacts file's %d pairs (%d lines, kinds %s)" %
                 (name, len(pairs), len(lines), sorted({k for _, k in lines})))
        print("%s: %d atoms, %d contacts as lines: as the dump" % (name, len(dumps[timestep][1]), len(lines)))

    # 3. One contact deleted from the last frame: the check fails, the export names it as missing.
    last = max(dumps)
    os.makedirs("removed")
    for t in contacts:
        shutil.copy("contacts.%d.dump" % t, "removed/")
    path = "removed/contacts.%d.dump" % last
    with open(path) as f:
        text = f.read().split("\n")
    at = next(i for i, l in enumerate(text) if l.startswith("ITEM: ENTRIES")) + 5
    deleted = tuple(sorted(int(float(w)) for w in text[at].split()[:2]))
    del text[at]
    count = next(i for i, l in enumerate(text) if l == "ITEM: NUMBER OF ENTRIES") + 1
    text[count] = str(int(text[count]) - 1)
    with open(path, "w") as f:
        f.write("\n".join(text))
    run(1, *replay, "--contacts", "removed/contacts.*.dump", "--export-vtk", "vtk_removed")
    for timestep, name, lines, pairs in check_series("vtk_removed", dumps, contacts):
        missing = [p for p, k in lines if k == 2]
        want = [deleted] if timestep == last else []
        if missing != want or any(k not in (1, 2) for _, k in lines):
            fail("%s: missing lines %s, expected %s" % (name, missing, want))
    print("the deleted contact %s of timestep %d: one line of kind 2 (missing)" % (deleted, last))

    # 4. --color-by in a headless screenshot, and its refusals: where this nbscope renders (a build
    # with NBSCOPE_GUI=OFF, as the sanitizer build, makes no pictures: --version says so).
    version = subprocess.run([nbscope, "--version"], capture_output=True, text=True).stdout
    if "window: no" in version:
        print("--color-by: not run (%s)" % next(l for l in version.split("\n") if l.startswith("window:")))
        print("ok")
        return 0
    shot = replay + ["--contacts", "contacts.*.dump", "--frames", "1", "--size", "640x480", "--overlays", "-grid"]
    def pixels(png):
        reader = vtkPNGReader()
        reader.SetFileName(png)
        reader.Update()
        data = reader.GetOutput().GetPointData().GetScalars()
        return sum(1 for k in range(data.GetNumberOfTuples()) if tuple(int(v) for v in data.GetTuple(k)[:3]) == DEFAULT_FILL)
    run(0, *shot, "--screenshot", "plain.png")
    run(0, *shot, "--screenshot", "vx.png", "--color-by", "vx")
    plain, coloured = pixels("plain.png"), pixels("vx.png")
    if plain == 0 or coloured != 0:
        fail("--color-by vx: %d pixels of the default fill (plain: %d); expected none (plain: some)" % (coloured, plain))
    print("--color-by vx: no atom left in the default fill (%d pixels of it without the flag)" % plain)
    r = run(2, *shot, "--screenshot", "foo.png", "--color-by", "foo")
    want = "nbscope: error: --color-by: the dump has no column 'foo' (it has: id type x y z radius vx vy vz proc)\n"
    if r.stderr != want or os.path.exists("foo.png"):
        fail("--color-by foo: stderr %r, expected %r (and no picture)" % (r.stderr, want))
    with open("atoms.%d.dump" % last) as f:
        text = f.read()
    with open("no_proc.dump", "w") as f:  # the same frame without its proc column
        for line in text.split("\n"):
            words = line.split()
            f.write((" ".join(words[:-1]) if line.startswith("ITEM: ATOMS") or (words and not line.startswith("ITEM") and len(words) == 10) else line) + "\n")
    r = run(2, nbscope, "replay", "--headless", "--quiet", "--dump", "no_proc.dump", "--screenshot", "rank.png", "--color-by", "rank")
    want = "nbscope: error: --color-by rank: the dump has no column 'proc' (it has: id type x y z radius vx vy vz)\n"
    if r.stderr != want:
        fail("--color-by rank: stderr %r, expected %r" % (r.stderr, want))
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
