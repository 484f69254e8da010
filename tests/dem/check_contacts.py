#!/usr/bin/env python3
"""nbscope tests/dem: a second oracle for LIGGGHTS's and LAMMPS's contact lists, independent of nbscope (docs/dem.md).

Reads `dump custom` frames (id type x y z radius, any column order, atoms in any order) and the
`dump local` contacts of LIGGGHTS's `compute pair/gran/local pos id` (ids in columns 7 and 8) or of
LAMMPS's `compute property/local patom1 patom2` (two columns: the ids), and compares each
frame's list with the exact strict contacts: |c_i - c_j|^2 < (r_i + r_j)^2 computed in rational
arithmetic on the doubles as read, minimum image on the axes BOX BOUNDS flags `pp`.

A pair on which the two disagree is "within the data's precision" when its gap |c_i - c_j| - (r_i + r_j)
is no larger than the error the printed digits allow (half a unit of each number's last printed digit,
summed along the pair; see print_errors): a dump printed with %g (6 digits) cannot say which side
such a pair is on.

Usage: check_contacts.py [--band] 'ATOMS_GLOB' 'CONTACTS_GLOB'    (or --self-test: hand-made frames)
  One line per frame (timestep, atoms, contacts, and the pairs that differ), then a summary line.
  Exit 0: every frame's list equals the exact one (with --band: every difference is within the data's
  precision); 1: a difference, each named "timestep T: contact (i, j) ..."; 2: unreadable input.
"""
import glob
import math
import sys
from decimal import Decimal
from fractions import Fraction


class InputError(Exception):
    """Bad input: reported as `check_contacts: error: <where>: <what>` and exit 2."""


def print_errors(texts):
    """The most each printed number can differ from the value it stands for (half a unit of a digit).

    A %g-style format (LAMMPS's default %g, or %.17g) drops trailing zeros: %.17g prints 0.0015 as
    `0.0015`, which is exact to 17 digits, not to 4. So when no number of the frame ends its fraction
    in a zero, each is taken as exact to the most significant digits any of them shows (17 for %.17g, 6
    for %g; `0` then exact); otherwise (a fixed format, "%.6f") to its own last printed digit.
    """
    numbers = [Decimal(text) for text in texts]
    fixed = any(n.as_tuple().exponent < 0 and n.as_tuple().digits[-1] == 0 and n != 0 for n in numbers)
    digits = max((len(n.normalize().as_tuple().digits) for n in numbers if n != 0), default=1)
    errors = []
    for n in numbers:
        last = 0.5 * 10.0 ** n.as_tuple().exponent
        if fixed:
            errors.append(last)
        elif n == 0:
            errors.append(0.0)
        else:
            errors.append(min(last, 0.5 * 10.0 ** (n.adjusted() - digits + 1)))
    return errors


def frames_of(path):
    """Yield (timestep, box, header, rows, line) for each frame of a LAMMPS/LIGGGHTS dump file."""
    with open(path, encoding="ascii") as handle:
        lines = handle.read().splitlines()
    at = 0
    while at < len(lines):
        if not lines[at].strip():
            at += 1
            continue
        if lines[at] != "ITEM: TIMESTEP":
            raise InputError(f"{path}:{at + 1}: expected 'ITEM: TIMESTEP', found '{lines[at]}'")
        start = at + 1
        timestep = int(lines[at + 1])
        count = int(lines[at + 3])
        flags = lines[at + 4].split()[3:]
        if len(flags) != 3:
            raise InputError(f"{path}:{at + 5}: BOX BOUNDS without three flags (a triclinic box?)")
        box = []
        for axis in range(3):
            lo, hi = lines[at + 5 + axis].split()[:2]
            box.append((Fraction(float(lo)), Fraction(float(hi)), flags[axis].startswith("p"), float(hi) - float(lo)))
        header = lines[at + 8].split()[2:]
        rows = [line.split() for line in lines[at + 9:at + 9 + count]]
        if len(rows) != count or any(len(row) != len(header) for row in rows):
            raise InputError(f"{path}:{at + 9}: fewer rows than the {count} announced, or a short row")
        yield timestep, box, header, rows, f"{path}:{start}"
        at += 9 + count


def read_atoms(pattern):
    """{timestep: (box, {id: ([x y z r] exact, their errors, as floats)})} from every file the glob matches."""
    frames = {}
    for path in sorted(glob.glob(pattern)):
        for timestep, box, header, rows, where in frames_of(path):
            try:
                columns = [header.index(name) for name in ("id", "x", "y", "z", "radius")]
            except ValueError:
                raise InputError(f"{where}: the ATOMS line needs id x y z radius") from None
            atoms = {}
            for row in rows:
                atom = int(row[columns[0]])
                if atom in atoms:
                    raise InputError(f"{where}: atom {atom} twice")
                texts = [row[c] for c in columns[1:]]
                floats = [float(t) for t in texts]
                atoms[atom] = [[Fraction(f) for f in floats], texts, floats]
            errors = print_errors([t for data in atoms.values() for t in data[1]])
            for index, data in enumerate(atoms.values()):
                data[1] = errors[4 * index:4 * index + 4]
            frames[timestep] = (box, atoms)
    if not frames:
        raise InputError(f"'{pattern}': no file matches")
    return frames


def read_contacts(pattern):
    """{timestep: [(i, j), ...]} from `dump local` files: pair/gran/local pos id, or property/local patom1 patom2."""
    frames = {}
    for path in sorted(glob.glob(pattern)):
        for timestep, _, _, rows, where in frames_of(path):
            pairs = []
            for row in rows:
                texts = row[0:2] if len(row) == 2 else row[6:8]  # patom1 patom2 alone, else `pos id`
                ids = [float(value) for value in texts]
                if len(ids) != 2 or any(value != math.floor(value) for value in ids):
                    raise InputError(f"{where}: a contact's ids are not two integers: {texts}")
                pairs.append((int(ids[0]), int(ids[1])))
            frames[timestep] = pairs
    if not frames:
        raise InputError(f"'{pattern}': no file matches")
    return frames


def separation(a, b, box):
    """c_a - c_b per axis, the minimum image on periodic axes (exact)."""
    out = []
    for axis, (lo, hi, periodic, _) in enumerate(box):
        d = a[axis] - b[axis]
        if periodic:
            length = hi - lo
            d -= length * round(d / length)
        out.append(d)
    return out


def exact_contacts(box, atoms):
    """Every unordered pair with |c_i - c_j|^2 < (r_i + r_j)^2, found through cells of the largest diameter."""
    cell = 2 * max(data[2][3] for data in atoms.values())
    counts = [max(1, int(float(hi - lo) // cell)) for lo, hi, _, _ in box]
    sizes = [float(hi - lo) / n for (lo, hi, _, _), n in zip(box, counts)]
    bins = {}
    for atom, (_, _, floats) in atoms.items():
        key = tuple(min(n - 1, max(0, int((v - float(lo)) // size)))
                    for v, (lo, _, _, _), size, n in zip(floats, box, sizes, counts))
        bins.setdefault(key, []).append(atom)
    found = set()
    offsets = [(i, j, k) for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)]
    for key, members in bins.items():
        neighbours = set()
        for offset in offsets:
            other = [key[axis] + offset[axis] for axis in range(3)]
            other = tuple(index % counts[axis] if box[axis][2] else index for axis, index in enumerate(other))
            neighbours.update(bins.get(other, ()))
        candidates = sorted(neighbours)
        for a in members:
            for b in candidates:
                if b > a and touching(atoms[a], atoms[b], box):
                    found.add((a, b))
    return found


def touching(a, b, box):
    """|c_a - c_b|^2 < (r_a + r_b)^2, exactly: floats decide unless the pair is within 1e-9 of the boundary."""
    fa, fb = a[2], b[2]
    reach = fa[3] + fb[3]
    distance2 = 0.0
    for axis in range(3):
        d = fa[axis] - fb[axis]
        if box[axis][2]:
            length = box[axis][3]
            d -= length * round(d / length)
        if d > reach or -d > reach:
            return False
        distance2 += d * d
    reach2 = reach * reach
    if abs(distance2 - reach2) > 1e-9 * reach2:
        return distance2 < reach2
    va, vb = a[0], b[0]
    return sum(x * x for x in separation(va, vb, box)) < (va[3] + vb[3]) ** 2


def gap_and_error(a, b, box, atoms):
    """The pair's gap |c_a - c_b| - (r_a + r_b) and the most the printed digits can move it."""
    (va, ea, _), (vb, eb, _) = atoms[a], atoms[b]
    d = separation(va, vb, box)
    gap = math.sqrt(sum(float(x) ** 2 for x in d)) - float(va[3] + vb[3])
    error = math.sqrt(sum((ea[i] + eb[i]) ** 2 for i in range(3))) + ea[3] + eb[3]
    return gap, error


def check_frame(timestep, box, atoms, listed, band):
    """Compare one frame; return (message lines, pairs out of band, pairs in band)."""
    messages, outside, inside = [], 0, 0
    given = set()
    for i, j in listed:
        pair = (min(i, j), max(i, j))
        if i not in atoms or j not in atoms:
            messages.append(f"timestep {timestep}: contact ({i}, {j}) names an atom the frame does not have")
            outside += 1
        elif pair in given:
            messages.append(f"timestep {timestep}: contact ({i}, {j}) listed twice")
            outside += 1
        given.add(pair)
    exact = exact_contacts(box, atoms)
    for pair, what in [(p, "missing from the dump's list") for p in sorted(exact - given)] + \
                      [(p, "listed in the dump, not touching") for p in sorted(given - exact)
                       if p[0] in atoms and p[1] in atoms]:
        gap, error = gap_and_error(pair[0], pair[1], box, atoms)
        if band and abs(gap) <= error:
            inside += 1
            messages.append(f"timestep {timestep}: contact {pair} {what}: gap {gap:.3g} at the boundary, "
                            f"within the data's precision ({error:.3g})")
        else:
            outside += 1
            messages.append(f"timestep {timestep}: contact {pair} {what}: gap {gap:.3g}")
    return messages, outside, inside, len(exact)


def frame_text(bounds, rows):
    """A one-frame `dump custom` (bounds "pp pp ff" and the rows "id x y z r") for the self-test."""
    lines = ["ITEM: TIMESTEP", "500", "ITEM: NUMBER OF ATOMS", str(len(rows)), f"ITEM: BOX BOUNDS {bounds}",
             "0 10", "0 10", "0 10", "ITEM: ATOMS id type x y z radius"]
    return "\n".join(lines + [f"{r.split()[0]} 1 {' '.join(r.split()[1:])}" for r in rows]) + "\n"


def contacts_text(pairs, two_columns=False):
    """A one-frame `dump local` for the self-test: pair/gran/local pos id, or property/local patom1 patom2."""
    lines = ["ITEM: TIMESTEP", "500", "ITEM: NUMBER OF ENTRIES", str(len(pairs)), "ITEM: BOX BOUNDS ff ff ff",
             "0 10", "0 10", "0 10"]
    if two_columns:
        return "\n".join(lines + ["ITEM: ENTRIES c_pl[1] c_pl[2]"] + [f"{i} {j}" for i, j in pairs]) + "\n"
    lines.append("ITEM: ENTRIES c_pgl[1] c_pgl[2] c_pgl[3] c_pgl[4] c_pgl[5] c_pgl[6] c_pgl[7] c_pgl[8] c_pgl[9]")
    return "\n".join(lines + [f"0 0 0 0 0 0 {i} {j} 0" for i, j in pairs]) + "\n"


def self_test():
    """Hand-made frames with known answers: strictness, the minimum image, the precision band."""
    import contextlib
    import io
    import os
    import tempfile
    touching_at_zero_gap = ["1 0 5 5 0.5", "2 1 5 5 0.5"]             # |c1 - c2| = r1 + r2 exactly
    across_x = ["1 0.125 5 5 0.25", "2 9.875 5 5 0.25"]                # 0.25 apart through x = 0
    printed_g = ["1 0 5 5 0.5", "2 1.00001 5 5 0.500008"]              # gap 2e-6, %g's error 6e-6
    overlapping = ["1 0 5 5 0.5", "2 0.875 5 5 0.5"]
    cases = [  # (name, bounds, rows, listed pairs, --band, expected exit)
        ("zero gap is no strict contact", "ff ff ff", touching_at_zero_gap, [], False, 0),
        ("zero gap listed is an extra pair", "ff ff ff", touching_at_zero_gap, [(1, 2)], False, 1),
        ("periodic pair found by minimum image", "pp pp ff", across_x, [(2, 1)], False, 0),
        ("periodic pair missing is named", "pp pp ff", across_x, [], False, 1),
        ("no image without pp", "ff ff ff", across_x, [], False, 0),
        ("%g pair within the data's precision", "ff ff ff", printed_g, [(1, 2)], True, 0),
        ("%g pair without --band", "ff ff ff", printed_g, [(1, 2)], False, 1),
        ("exact digits leave no band", "ff ff ff", ["1 0 5 5 0.5", "2 1.0000020000000001 5 5 0.5"],
         [(1, 2)], True, 1),
        ("LAMMPS patom1 patom2: ids in columns 1 and 2", "ff ff ff", overlapping, [(2, 1)], False, 0),
        ("LAMMPS patom1 patom2: a missing pair is named", "ff ff ff", overlapping, [], False, 1),
    ]
    failed = 0
    with tempfile.TemporaryDirectory() as folder:
        for name, bounds, rows, pairs, band, want in cases:
            atoms, contacts = os.path.join(folder, "atoms.dump"), os.path.join(folder, "contacts.dump")
            with open(atoms, "w", encoding="ascii") as handle:
                handle.write(frame_text(bounds, rows))
            with open(contacts, "w", encoding="ascii") as handle:
                handle.write(contacts_text(pairs, two_columns=name.startswith("LAMMPS")))
            with contextlib.redirect_stdout(io.StringIO()) as out:
                got = main((["--band"] if band else []) + [atoms, contacts])
            if got != want:
                failed += 1
                print(f"self-test FAILED: {name}: exit {got}, expected {want}\n{out.getvalue()}")
    print(f"self-test: {len(cases) - failed} of {len(cases)} cases hold")
    return 1 if failed else 0


def main(argv):
    """Check every frame; print a line per frame and difference; exit 0, 1 or 2 (see the module doc)."""
    if argv == ["--self-test"]:
        return self_test()
    band = "--band" in argv
    args = [a for a in argv if a != "--band"]
    if len(args) != 2:
        print("usage: check_contacts.py [--band] 'ATOMS_GLOB' 'CONTACTS_GLOB'", file=sys.stderr)
        return 2
    try:
        atom_frames, contact_frames = read_atoms(args[0]), read_contacts(args[1])
    except (InputError, OSError, ValueError, IndexError) as error:
        print(f"check_contacts: error: {error}", file=sys.stderr)
        return 2
    outside = inside = 0
    for timestep in sorted(set(atom_frames) | set(contact_frames)):
        if timestep not in atom_frames or timestep not in contact_frames:
            print(f"timestep {timestep}: only in the {'contacts' if timestep in contact_frames else 'atoms'}")
            outside += 1
            continue
        box, atoms = atom_frames[timestep]
        lines, out, inn, exact = check_frame(timestep, box, atoms, contact_frames[timestep], band)
        print(f"timestep {timestep}: {len(atoms)} atoms, {len(contact_frames[timestep])} contacts listed, "
              f"{exact} exact")
        for line in lines:
            print("  " + line)
        outside += out
        inside += inn
    frames = len(atom_frames)
    if outside:
        print(f"{outside} contact(s) differ from the exact list ({frames} frames)")
        return 1
    if inside:
        print(f"The dump's list equals the exact strict list in every frame but for {inside} pair(s) at the "
              f"boundary, within the data's precision ({frames} frames)")
    else:
        print(f"The dump's list equals the exact strict list in every frame ({frames} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
