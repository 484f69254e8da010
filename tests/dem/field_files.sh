#!/usr/bin/env bash
# nbscope tests/dem: the field's own files from a real LAMMPS run (docs/dem.md, docs/formats.md):
#
#   field_files.sh NBSCOPE_BIN SRC_DIR OUT_DIR
#
# lmp runs tests/dem/lammps_pour2d.in (`dimension 2`, `units lj`, periodic x) in OUT_DIR (emptied first),
# its log echoing the commands as LAMMPS's does by default; then:
# 1. `replay --headless --dump` of its frames WITHOUT --2d: exit 0, A==R in every frame, and the one-line
#    note that the run was read as 2D (the landed tree refused it: z periodic over 1 with 0 cells);
# 2. its data file (write_data) as --input and --dump: the contacts of its timestep verified right,
#    the same pairs as `pairs` gives, one frame of 240 atoms;
# 3. its units: with --log log.lammps the report and the JSON say lj (sigma, tau), --units wins, a wrong
#    --units is one error line, the dump's own ITEM: UNITS (dump_modify units yes) is read; verify of a contact list with one contact deleted names the gap in sigma;
#    the log's `boundary` makes a data file's axes periodic.
# Exit 77 (CTest's skip) when lmp is missing, unless CI=true: CI must run it, so there it fails.
set -euo pipefail

[ $# -eq 3 ] || { echo "usage: $0 NBSCOPE_BIN SRC_DIR OUT_DIR" >&2; exit 2; }
nbscope=$(realpath "$1") src=$2 out=$3
input=$(realpath "$src/tests/dem/lammps_pour2d.in")
python=${PYTHON:-python3}

fail() { echo "FAIL (field files): $*" >&2; exit 1; }
simulator=${LMP:-$(command -v lmp || true)}
if [ ! -x "$simulator" ]; then
  if [ "${CI:-}" = "true" ]; then fail "lmp is not installed (CI=true: this test must run)"; fi
  echo "SKIP (field files): lmp is not installed (apt-get install lammps; scripts/dev deps)"
  exit 77
fi

rm -rf "$out" && mkdir -p "$out"
cd "$out"
"$simulator" -in "$input" -log log.lammps -screen /dev/null >lmp.out 2>&1 || { tail -n 20 log.lammps >&2 || true; fail "lmp exited non-zero"; }
[ -f pour2d.data ] && [ -f atoms.5000.dump ] || fail "lmp wrote no pour2d.data or atoms.5000.dump"

expect() {  # expect WANT FILE COMMAND...: COMMAND's stdout and stderr into FILE (and shown); its exit code must be WANT
  local want=$1 file=$2 rc=0
  shift 2
  "$@" >"$file" 2>&1 || rc=$?
  echo "--- $(basename "$1") ${*:2}: exit $rc"
  cat "$file"
  [ "$rc" -eq "$want" ] || fail "$(basename "$1") exited $rc, expected $want"
}
holds() { grep -qF -- "$2" "$1" || fail "$1 does not say '$2'"; }

# 1. `dimension 2` without --2d.
expect 0 replay2d.txt "$nbscope" replay --headless --dump 'atoms.*.dump' --contacts 'contacts.*.dump' --touching strict \
  --algorithm recorded,nbs
holds replay2d.txt "6 frames, 240 elements: A==R held in every frame"
holds replay2d.txt "nbscope: note: atoms.0.dump: every z is 0 in a thin z box (a \`dimension 2\` run): read as 2D, as --2d does"
[ "$(grep -c 'note:' replay2d.txt)" -eq 1 ] || fail "the 2D note is not one line"

# 2. The data file: one frame, its timestep's contacts, the pairs nbscope finds.
entries=$(sed -n 4p contacts.5000.dump)
expect 0 verify_data.txt "$nbscope" verify --input pour2d.data --pairs contacts.5000.dump --touching strict
holds verify_data.txt "$entries pairs given for 240 elements, the reference (brute) finds $entries: $entries right, 0 missing, 0 extra"
expect 0 replay_data.txt "$nbscope" replay --headless --dump pour2d.data --contacts contacts.5000.dump --touching strict
holds replay_data.txt "1 frame, 240 elements: A==R held in every frame"
expect 0 pairs_data.txt "$nbscope" pairs --input pour2d.data --output pairs.csv --touching strict
[ "$(($(wc -l <pairs.csv) - 1))" -eq "$entries" ] || fail "pairs --input pour2d.data gave $(($(wc -l <pairs.csv) - 1)) pairs, LAMMPS $entries"

# 3. Units: the log's, the flag's, a refusal; a wrong contact's gap in sigma.
expect 0 units.txt "$nbscope" replay --headless --dump 'atoms.*.dump' --log log.lammps --report report.json
holds units.txt "units lj (lengths in sigma, times in tau)"
"$python" - <<'PY' || fail "report.json does not give the units lj (sigma, tau)"
import json
u = json.load(open("report.json"))["units"]
assert u == {"name": "lj", "length": "sigma", "time": "tau"}, u
PY
expect 0 units_flag.txt "$nbscope" replay --headless --dump 'atoms.*.dump' --log log.lammps --units real
holds units_flag.txt "units real (lengths in Angstrom, times in fs)"
expect 0 units_steps.txt "$nbscope" replay --headless --dump 'atoms.*.dump'   # the dump's own ITEM: UNITS
holds units_steps.txt "units lj (lengths in sigma; times in steps: --dt or --log gives them in tau)"
expect 2 units_bad.txt "$nbscope" replay --headless --dump 'atoms.*.dump' --units furlong
[ "$(wc -l <units_bad.txt)" -eq 1 ] || fail "a bad --units is not one line"
holds units_bad.txt "nbscope: error: --units"
awk 'NR == 4 { $0 = $0 - 1 } NR != 10' contacts.5000.dump >removed.dump
expect 1 verify_units.txt "$nbscope" verify --input pour2d.data --pairs removed.dump --touching strict --log log.lammps
holds verify_units.txt "(units lj (lengths in sigma, times in tau))"
grep -q '^missing .* distance - radii = -[0-9.e-]* sigma (in contact)$' verify_units.txt || fail "verify names no gap in sigma"
# A data file has no boundary flags: the log's `boundary p f p` makes x periodic, so two atoms either
# side of x = 0..20 (no image flags) touch across it; without the log they do not.
printf 'LAMMPS data file via write_data, version 29 Sep 2021, timestep = 0\n\n2 atoms\n1 atom types\n\n0 20 xlo xhi\n0 30 ylo yhi\n-0.5 0.5 zlo zhi\n\nAtoms # sphere\n\n1 1 1 1 0.2 5 0 0 0 0\n2 1 1 1 19.7 5 0 0 0 0\n' >edge.data
expect 0 edge_log.txt "$nbscope" pairs --input edge.data --log log.lammps --output edge_log.csv
[ "$(sed -n 2p edge_log.csv)" = "1,2" ] || fail "with the log's boundary, atoms 1 and 2 do not touch across x"
expect 0 edge_alone.txt "$nbscope" pairs --input edge.data --output edge_alone.csv
[ "$(wc -l <edge_alone.csv)" -eq 1 ] || fail "without a log, a data file's x is periodic"
echo "--- field files: passed"
