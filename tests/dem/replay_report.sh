#!/usr/bin/env bash
# nbscope tests/dem: what a dump replay prints and reports, on a real LAMMPS run (docs/dem.md, issue 39.5).
#
#   replay_report.sh NBSCOPE_BIN SRC_DIR OUT_DIR
#
# lmp runs tests/dem/lammps_periodic.in in OUT_DIR (emptied first): a pour periodic in x, atoms every 500
# steps and contacts every 250, so two contact frames have no atoms frame. Then:
# 1. replay of them all: exit 0, one note on stderr naming both skipped timesteps; the summary says
#    `periodic: x; touching: strict (<)` and nothing of Box2D (F, G/T, A-in-F).
# 2. one contact across x's period deleted: exit 1; the violation is named by its timestep and gives the
#    pair's distance - radii, equal to this script's own minimum-image arithmetic; so does the report
#    (frame_unit, periodic, the violation's gap), which has no Box2D keys; --violation 1 says the timestep.
# Exit 77 (CTest's skip) when lmp is missing, unless CI=true: CI must run it, so there it fails.
set -euo pipefail

[ $# -eq 3 ] || { echo "usage: $0 NBSCOPE_BIN SRC_DIR OUT_DIR" >&2; exit 2; }
nbscope=$1 src=$2 out=$3
input=$(realpath "$src/tests/dem/lammps_periodic.in")
python=${PYTHON:-python3}
[ -x "$nbscope" ] || { echo "replay_report.sh: error: '$nbscope' is not an executable" >&2; exit 2; }
nbscope=$(realpath "$nbscope")

fail() { echo "FAIL (replay_report): $*" >&2; exit 1; }
lmp=${LMP:-$(command -v lmp || true)}
if [ ! -x "$lmp" ]; then
  if [ "${CI:-}" = "true" ]; then fail "lmp is not installed (CI=true: this test must run)"; fi
  echo "SKIP (replay_report): lmp is not installed (apt-get install lammps; scripts/dev deps)"
  exit 77
fi

rm -rf "$out" && mkdir -p "$out"
cd "$out"
"$lmp" -in "$input" -log log.lammps -echo none -screen /dev/null >lammps.out 2>&1 ||
  { tail -n 20 log.lammps >&2 || true; fail "lmp exited non-zero (see $out/log.lammps)"; }
[ -f atoms.6500.dump ] && [ -f contacts.6250.dump ] || fail "lmp wrote no atoms.6500.dump or contacts.6250.dump"

# expect WANT NAME COMMAND...: run COMMAND, stdout into NAME.out and stderr into NAME.err (both shown); exit WANT.
expect() {
  local want=$1 name=$2 rc=0
  shift 2
  "$@" >"$name.out" 2>"$name.err" || rc=$?
  echo "--- ${*:2}: exit $rc"
  cat "$name.out" "$name.err"
  [ "$rc" -eq "$want" ] || fail "exited $rc, expected $want"
}
holds() { grep -qF -- "$2" "$1" || fail "$1 does not say '$2'"; }
lacks() { ! grep -qF -- "$2" "$1" || fail "$1 says '$2'"; }

replay=("$nbscope" replay --headless --quiet --touching strict)

# 1. Every contact frame: the two without an atoms frame skipped, said in one line.
expect 0 all "${replay[@]}" --dump "$out/atoms.*.dump" --contacts "$out/contacts.*.dump"
[ "$(wc -l <all.err)" -eq 1 ] || fail "all.err has $(wc -l <all.err) lines, expected the one note"
holds all.err "nbscope: note: $out/contacts.6250.dump:1: 2 timesteps have contacts but no atoms frame (6250, 6750); skipped"
holds all.out "A==R held in every frame"
holds all.out "3 frames"
holds all.out "; periodic: x; touching: strict (<)"
for box2d in "A-in-F" " F " "G/T" "T-in-A" "AABB-in-cells" "physics"; do lacks all.out "$box2d"; done

# 2. A contact across x's period deleted from timestep 6500's list; its gap by this script's arithmetic.
mkdir -p removed && cp contacts.6000.dump contacts.6500.dump contacts.7000.dump removed/
read -r line id1 id2 gap < <("$python" - <<'EOF'
import math
def rows(path):
    lines = open(path).read().split("\n")
    return lines, int(lines[3])
atoms, n = rows("atoms.6500.dump")
lo, hi = map(float, atoms[5].split())
period = hi - lo
at = {}
for row in atoms[9:9 + n]:
    w = row.split()
    at[int(w[0])] = [float(v) for v in w[2:6]]
contacts, m = rows("contacts.6500.dump")
for k in range(9, 9 + m):
    i, j = sorted(int(float(v)) for v in contacts[k].split())
    dx = at[i][0] - at[j][0]
    if abs(dx) <= period / 2:
        continue  # not across the period
    dx -= period * round(dx / period)
    dy, dz = at[i][1] - at[j][1], at[i][2] - at[j][2]
    print(k + 1, i, j, repr(math.sqrt(dx * dx + dy * dy + dz * dz) - (at[i][3] + at[j][3])))
    break
EOF
)
[ -n "${gap:-}" ] || fail "no contact across x's period in contacts.6500.dump"
awk -v n="$line" 'NR == 4 { $0 = $0 - 1 } NR != n' contacts.6500.dump >removed/contacts.6500.dump
echo "--- deleted contact ($id1, $id2) of timestep 6500 (line $line), distance - radii $gap"

expect 1 removed "${replay[@]}" --dump "$out/atoms.*.dump" --contacts "$out/removed/contacts.*.dump" --report "$out/removed.json"
holds removed.out "first in timestep 6500: A==R (atoms $id1, $id2) in contact (in R) but missing from the recorded pairs; distance - radii = "
printed=$(sed -n 's/.*missing from the recorded pairs; distance - radii = \([^ ]*\) (in contact).*/\1/p' removed.out)
"$python" -c "import sys; p, g = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if g < 0 and abs(p - g) <= 1e-5 * abs(g) else 1)" \
  "$printed" "$gap" || fail "printed distance - radii '$printed' is not $gap (minimum image)"
for box2d in "A-in-F" " F " "G/T" "physics"; do lacks removed.out "$box2d"; done
"$python" - "$gap" "$id1" "$id2" <<'EOF' || fail "removed.json does not report what applies (see above)"
import json, sys
gap, ids = float(sys.argv[1]), [int(sys.argv[2]), int(sys.argv[3])]
r = json.load(open("removed.json"))
problems = []
def want(what, ok):
    if not ok: problems.append(what)
want("frame_unit timestep", r.get("frame_unit") == "timestep")
want("periodic [x]", r.get("periodic") == ["x"])
want("touching strict", r.get("touching") == "strict")
want("no a_in_f_scope", "a_in_f_scope" not in r)
want("invariants without Box2D's", [i["name"] for i in r["invariants"]] == ["A==R", "cells", "contract"])
run = r["runs"][0]
want("first violation at timestep 6500", run["violations"]["first_frame"] == 6500)
want("no physics time", "physics" not in run["timing_ms"])
want("no F in the check's parts", "F" not in run["check_ms_parts"])
frame = [f for f in run["frames"] if f["frame"] == 6500][0]
want("pairs A and R only", sorted(frame["pairs"]) == ["A", "R"])
want("no left_out_of_A_in_F", "left_out_of_A_in_F" not in frame)
want("held without A-in-F", "A-in-F" not in frame["held"] and frame["held"]["A==R"] is False)
v = frame["violations"][0]
want("the violation's ids", v["ids"] == ids)
want("the violation's gap", abs(v["gap"] - gap) <= 1e-12 + 1e-9 * abs(gap))
if problems:
    print("removed.json:", "; ".join(problems), file=sys.stderr)
    sys.exit(1)
EOF
expect 1 went "${replay[@]}" --dump "$out/atoms.*.dump" --contacts "$out/removed/contacts.*.dump" --violation 1
holds went.out "; went to violation 1, timestep 6500: A==R (atoms $id1, $id2)"
echo "--- replay_report: passed"
