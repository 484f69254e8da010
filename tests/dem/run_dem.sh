#!/usr/bin/env bash
# nbscope tests/dem: one LIGGGHTS or LAMMPS simulation, then its frames and contact lists checked (docs/dem.md).
#
#   run_dem.sh NBSCOPE_BIN SRC_DIR OUT_DIR CASE      CASE: pour3d | pour2d | periodic (tests/dem/CASE.in,
#                                                    run by liggghts) | lammps (tests/dem/lammps_pour.in, by lmp)
#
# 1. liggghts (or lmp) runs the case in OUT_DIR (emptied first): atoms.*.dump / contacts.*.dump at %.17g
#    and g_atoms.*.dump / g_contacts.*.dump in the code's default %g, at the same timesteps. LIGGGHTS's
#    contacts are pair/gran/local `pos id` (ids in columns 7, 8), LAMMPS's property/local patom1 patom2.
# 2. check_contacts.py (exact arithmetic, independent of nbscope) holds the simulator's lists to the exact
#    strict contacts: equal at %.17g; at %g equal but for pairs within the data's precision; and a
#    copy of the contacts with one line deleted fails, naming both ids and the timestep.
# 3. nbscope replay --headless --dump/--contacts --touching strict --algorithm recorded,nbs,brute
#    does the same:
#    exit 0 and "A==R held in every frame" (at %g: the pairs "within the data's precision" said so,
#    when step 2 found any), and exit 1 naming the deleted contact's ids and timestep.
# Exit 77 (CTest's skip) when liggghts (lmp) is missing, unless CI=true: CI must run it, so there it fails.
set -euo pipefail

[ $# -eq 4 ] || { echo "usage: $0 NBSCOPE_BIN SRC_DIR OUT_DIR pour3d|pour2d|periodic|lammps" >&2; exit 2; }
nbscope=$1 src=$2 out=$3 case=$4
here=$(realpath "$src/tests/dem")  # absolute: the runs and checks are made from OUT_DIR
python=${PYTHON:-python3}
input="$here/$case.in"
if [ "$case" = lammps ]; then input="$here/lammps_pour.in"; fi
[ -f "$input" ] || { echo "run_dem.sh: error: no case '$case' ($input)" >&2; exit 2; }
[ -x "$nbscope" ] || { echo "run_dem.sh: error: '$nbscope' is not an executable" >&2; exit 2; }
nbscope=$(realpath "$nbscope")  # the checks run from OUT_DIR

fail() { echo "FAIL ($case): $*" >&2; exit 1; }
skip() {  # skip WHY: exit 77 for CTest, or fail under CI=true
  if [ "${CI:-}" = "true" ]; then fail "$* (CI=true: this test must run)"; fi
  echo "SKIP ($case): $*"
  exit 77
}

if [ "$case" = lammps ]; then
  code=lmp package=lammps id_columns="1 2"  # property/local patom1 patom2: the two columns are the ids
  simulator=${LMP:-$(command -v lmp || true)}  # LMP=/no/such/file: the test of this skip
else
  code=liggghts package=liggghts id_columns="7 8"  # pair/gran/local pos id: the ids in columns 7, 8
  simulator=${LIGGGHTS:-$(command -v liggghts || true)}  # LIGGGHTS=/no/such/file: the test of this skip
fi
[ -x "$simulator" ] || skip "$code is not installed (apt-get install $package; scripts/dev deps)"

rm -rf "$out" && mkdir -p "$out"
cd "$out"

# -screen none would crash LIGGGHTS: fix insert/pack prints to the (then NULL) screen in Region::reset_random.
start=$(date +%s%N)
"$simulator" -in "$input" -log "log.$code" -echo none -screen /dev/null >"$code.out" 2>&1 ||
  { tail -n 20 "log.$code" "$code.out" >&2 || true; fail "$code exited non-zero (see $out/log.$code)"; }
ms=$(( ($(date +%s%N) - start) / 1000000 ))
dumps=(atoms.*.dump)
frames=${#dumps[@]}
echo "--- $case: $code ran in $ms ms, $frames frames"
[ "$frames" -ge 2 ] || fail "expected several frames, found $frames"

# expect WANT FILE COMMAND...: run COMMAND, its output into FILE (and shown); its exit code must be WANT.
expect() {
  local want=$1 file=$2 rc=0
  shift 2
  "$@" >"$file" 2>&1 || rc=$?
  echo "--- $(basename "$1") ${*:2}: exit $rc"
  cat "$file"
  [ "$rc" -eq "$want" ] || fail "$(basename "$1") exited $rc, expected $want"
}
holds() { grep -qF -- "$2" "$1" || fail "$1 does not say '$2'"; }
names() {  # names FILE I J T: one line of FILE names both ids I and J, and FILE names the timestep T
  grep -w -- "$2" "$1" | grep -qw -- "$3" || fail "no line of $1 names both $2 and $3"
  grep -qw -- "$4" "$1" || fail "$1 does not name the timestep $4"
}

# A copy of the contacts with one contact deleted: a periodic one when the case has them (LIGGGHTS's
# 9th column 1), so the check must find it across the boundary; from the middle frame.
middle=$(printf '%s\n' contacts.*.dump | sort -t. -k2,2n | sed -n "$(( (frames + 1) / 2 ))p")
mkdir -p removed && cp contacts.*.dump removed/
line=$(awk 'NR > 9 && $9 == 1 { print NR; exit }' "$middle")
line=${line:-14}
read -r first second <<<"$id_columns"
read -r id1 id2 < <(awk -v n="$line" -v a="$first" -v b="$second" 'NR == n { printf "%d %d\n", $a, $b }' "$middle")
timestep=$(sed -n 2p "$middle")
awk -v n="$line" 'NR == 4 { $0 = $0 - 1 } NR != n' "$middle" >"removed/$middle"
echo "--- deleted contact ($id1, $id2) of timestep $timestep ($middle line $line)"

# 2. the independent oracle
check="$here/check_contacts.py"
expect 0 oracle_full.txt "$python" "$check" 'atoms.*.dump' 'contacts.*.dump'
holds oracle_full.txt "The dump's list equals the exact strict list in every frame ($frames frames)"
expect 0 oracle_g.txt "$python" "$check" --band 'g_atoms.*.dump' 'g_contacts.*.dump'
holds oracle_g.txt "The dump's list equals the exact strict list in every frame"
in_band=$(grep -c "within the data's precision (" oracle_g.txt || true)
expect 1 oracle_removed.txt "$python" "$check" 'atoms.*.dump' 'removed/contacts.*.dump'
names oracle_removed.txt "$id1" "$id2" "$timestep"

# 3. nbscope
# --headless: no window even when a display is there.
replay=("$nbscope" replay --headless --touching strict --algorithm "recorded,nbs,brute")
if [ "$case" = pour2d ]; then replay+=(--2d); fi  # LIGGGHTS's `dimension 2` writes z = 0: discs
expect 0 nbscope_full.txt "${replay[@]}" --dump "$out/atoms*.dump" --contacts "$out/contacts*.dump"
holds nbscope_full.txt "A==R held in every frame"
expect 0 nbscope_g.txt "${replay[@]}" --dump "$out/g_atoms*.dump" --contacts "$out/g_contacts*.dump"
holds nbscope_g.txt "A==R held in every frame"
if [ "$in_band" -gt 0 ]; then holds nbscope_g.txt "at the boundary, within the data's precision"; fi
expect 1 nbscope_removed.txt "${replay[@]}" --dump "$out/atoms*.dump" --contacts "$out/removed/contacts*.dump"
names nbscope_removed.txt "$id1" "$id2" "$timestep"
echo "--- $case: passed"
