#!/usr/bin/env python3
"""Holds arrays a user's writer printed (ACTUAL) to a reference in `nbscope dump`'s schema.

    compare_arrays.py REFERENCE.json ACTUAL.json [--set 'KEY[i][j]=V' ...]

Both files are read with their own "base" (default 0) and shifted to 0-based, so a 1-based
Fortran dump compares to nbscope's own. Every key ACTUAL has must equal REFERENCE's (REFERENCE
may have more: pairs, bytes, rows, ...), and ACTUAL must have every key `nbscope verify` reads for
its algorithm. --set changes one 0-based REFERENCE entry first: the one a planted bug changes.
Exit 0: equal; 1: a difference (printed); 2: bad input.
"""
import json
import re
import sys

# Keys whose numbers are element or cell indices (shifted by "base"; -1 stays -1).
INDEX_KEYS = {"heads", "next", "y_heads", "y_next", "z_heads", "z_next", "order", "keys",
              "ix", "iy", "iz", "rows", "x_heads", "x_next", "leaves", "cell", "head"}
# What verify needs besides the grid, per algorithm (dim 2).
REQUIRED = {"screen": ["heads", "next"], "nbs": ["y_heads", "y_next"],
            "tree": ["leaves", "next"], "sort": ["keys", "order", "ix", "iy"]}
GRID = ["algorithm", "dim", "cell_size", "origin", "nx", "ny"]


def shift(value, by, indices=False):
    if isinstance(value, dict):
        return {k: shift(v, by, indices or k in INDEX_KEYS) for k, v in value.items()}
    if isinstance(value, list):
        return [shift(v, by, indices) for v in value]
    if indices and isinstance(value, int) and not isinstance(value, bool) and value != -1:
        return value - by
    return value


def bad(message):
    print(f"compare_arrays: {message}", file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        bad(f"{path}: {e}")
    if not isinstance(data, dict):
        bad(f"{path}: not a JSON object")
    base = data.pop("base", 0)
    if base not in (0, 1):
        bad(f"{path}: base {base!r} is neither 0 nor 1")
    return shift(data, base)


def apply_set(data, spec):
    m = re.fullmatch(r"(\w+)((?:\[\d+\])+)=(-?\d+)", spec)
    if not m:
        bad(f"--set {spec!r}: expected KEY[i]...=VALUE")
    *path, last = [m.group(1)] + [int(i) for i in re.findall(r"\d+", m.group(2))]
    node = data
    for p in path:
        node = node[p]
    node[last] = int(m.group(3))


def first_difference(ref, act, where):
    if type(ref) is not type(act) and not (isinstance(ref, (int, float)) and isinstance(act, (int, float))):
        return where, ref, act
    if isinstance(ref, list):
        if len(ref) != len(act):
            return f"{where} (length)", len(ref), len(act)
        for i, (r, a) in enumerate(zip(ref, act)):
            d = first_difference(r, a, f"{where}[{i}]")
            if d:
                return d
        return None
    return None if ref == act else (where, ref, act)


def main(argv):
    args, sets = [], []
    it = iter(argv)
    for a in it:
        if a == "--set":
            sets.append(next(it, ""))
        else:
            args.append(a)
    if len(args) != 2:
        bad("usage: compare_arrays.py REFERENCE.json ACTUAL.json [--set 'KEY[i]=V' ...]")
    ref, act = load(args[0]), load(args[1])
    for s in sets:
        try:
            apply_set(ref, s)
        except (KeyError, IndexError, TypeError):
            bad(f"--set {s!r}: no such entry in {args[0]}")

    algorithm = act.get("algorithm")
    missing = [k for k in GRID + REQUIRED.get(algorithm, []) if k not in act]
    if algorithm not in REQUIRED or missing:
        print(f"{args[1]}: algorithm {algorithm!r}, missing keys {missing}")
        return 1
    for key, value in act.items():
        if key not in ref:
            print(f"{args[1]}: key {key!r} is not in {args[0]}")
            return 1
        d = first_difference(ref[key], value, key)
        if d:
            print(f"{args[1]}: {d[0]} is {d[2]!r} (0-based), {args[0]} has {d[1]!r}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
