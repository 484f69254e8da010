#!/usr/bin/env python3
"""nbscope tests/dem: a second oracle for LIGGGHTS's contact lists, independent of nbscope (docs/dem.md).

Reads `dump custom` frames (id type x y z radius, any column order, atoms in any order) and the
`dump local` contacts of `compute pair/gran/local pos id` (ids in columns 7 and 8), and compares each
frame's list with the exact strict contacts: |c_i - c_j|^2 < (r_i + r_j)^2 computed in rational
arithmetic on the doubles as read, minimum image on the axes BOX BOUNDS flags `pp`.

A pair on which the two disagree is "within the data's precision" when its gap |c_i - c_j| - (r_i + r_j)
is no larger than the error the printed digits allow (half a unit of each number's last printed digit,
summed along the pair): a dump printed with %g (6 digits) cannot say which side such a pair is on.

Usage: check_contacts.py [--band] 'ATOMS_GLOB' 'CONTACTS_GLOB'
  One line per frame (timestep, atoms, contacts, and the pairs that differ), then a summary line.
  Exit 0: every frame's list equals the exact one (with --band: every difference is within the data's
  precision); 1: a difference, each named "timestep T: contact (i, j) ..."; 2: unreadable input.
"""
import glob
import math
import sys
from fractions import Fraction


class InputError(Exception):
    """Bad input: reported as `check_contacts: error: <where>: <what>` and exit 2."""


def last_digit_half_unit(text):
    """Half a unit of the last digit `text` prints (0.0015 -> 5e-5, 1.2e-03 -> 5e-5), as a float."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (-decimals + (int(exponent) if exponent else 0))


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
                atoms[atom] = ([Fraction(f) for f in floats], [last_digit_half_unit(t) for t in texts], floats)
            frames[timestep] = (box, atoms)
    if not frames:
        raise InputError(f"'{pattern}': no file matches")
    return frames


def read_contacts(pattern):
    """{timestep: [(i, j), ...]} from the `dump local` files of compute pair/gran/local pos id."""
    frames = {}
    for path in sorted(glob.glob(pattern)):
        for timestep, _, _, rows, where in frames_of(path):
            pairs = []
            for row in rows:
                ids = [float(value) for value in row[6:8]]
                if any(value != math.floor(value) for value in ids):
                    raise InputError(f"{where}: a contact's id is not an integer: {row[6:8]}")
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
    for pair, what in [(p, "missing from LIGGGHTS's list") for p in sorted(exact - given)] + \
                      [(p, "listed by LIGGGHTS, not touching") for p in sorted(given - exact)
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


def main(argv):
    """Check every frame; print a line per frame and difference; exit 0, 1 or 2 (see the module doc)."""
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
        print(f"LIGGGHTS's list equals the exact strict list in every frame but for {inside} pair(s) at the "
              f"boundary, within the data's precision ({frames} frames)")
    else:
        print(f"LIGGGHTS's list equals the exact strict list in every frame ({frames} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
