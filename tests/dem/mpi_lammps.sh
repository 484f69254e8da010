#!/usr/bin/env bash
# nbscope tests/dem: a LAMMPS run under MPI, one dump file per rank (docs/dem.md#mpi).
#
#   mpi_lammps.sh NBSCOPE_BIN SRC_DIR OUT_DIR NP PX PY
#
# mpirun -np NP lmp runs tests/dem/lammps_mpi.in on a PX x PY x 1 processor grid while `nbscope watch`
# follows its per-rank files (rank 0's dump local with its header, the others' bare rows); then:
# 1. the watched run and `replay` of its files: every frame whole (490 atoms from NP ranks' files), A==R;
# 2. a ghost cut-off too short, as a rank would lose them: every contact whose atoms are in two ranks
#    (the `proc` column) removed from the files: exit 1, the diagnosis saying all the missing contacts
#    straddle a subdomain boundary, naming both ranks;
# 3. a contact listed by both ranks (as newton off lets a code write it): read once, A==R still holds.
# Exit 77 (CTest's skip) when lmp or mpirun is missing, unless CI=true.
set -euo pipefail

[ $# -eq 6 ] || { echo "usage: $0 NBSCOPE_BIN SRC_DIR OUT_DIR NP PX PY" >&2; exit 2; }
nbscope=$(realpath "$1") here=$(realpath "$2/tests/dem") out=$3 np=$4 px=$5 py=$6
python=${PYTHON:-python3}
fail() { echo "FAIL (mpi $np): $*" >&2; exit 1; }
skip() {
  if [ "${CI:-}" = "true" ]; then fail "$* (CI=true: this test must run)"; fi
  echo "SKIP (mpi $np): $*"
  exit 77
}
simulator=${LMP:-$(command -v lmp || true)}
[ -x "$simulator" ] || skip "lmp is not installed (apt-get install lammps; scripts/dev deps)"
command -v mpirun >/dev/null || skip "mpirun is not installed (apt-get install openmpi-bin)"
rm -rf "$out" && mkdir -p "$out/ghost" "$out/twice" && cd "$out"
holds() { grep -qF -- "$2" "$1" || { cat "$1" >&2; fail "$1 does not say '$2'"; }; }

# The input dumps timesteps 4000..12000 every 1000: the watch ends at its 9th frame (--idle would end it
# too, but a loaded machine can take longer than any short idle between two of a run's frames).
"$nbscope" watch 'atoms.*.dump' --contacts 'contacts.*.dump' --headless --frames 9 --idle 60 --touching strict >watch.txt 2>watch.err & watch=$!
sleep 0.3
mpirun --allow-run-as-root --oversubscribe -np "$np" "$simulator" -in "$here/lammps_mpi.in" -var px "$px" -var py "$py" \
  -log log.lammps -echo none -screen none >lmp.out 2>&1 || { tail -n 20 log.lammps lmp.out >&2; fail "mpirun lmp exited non-zero"; }
grep -q "$px by $py by 1 MPI processor grid" log.lammps || fail "lmp did not run on a $px by $py by 1 grid"
frames=$(ls atoms.0.*.dump | wc -l)
[ "$frames" -eq 9 ] || fail "lmp wrote $frames frames, the watch waits for 9"
[ "$(ls atoms.*.dump | wc -l)" -eq $((frames * np)) ] || fail "expected $np files a frame"
head -n 1 "contacts.1.$(sed -n 2p atoms.0.*.dump | head -n 1).dump" | grep -q ITEM && fail "rank 1's dump local has ITEM lines: not the case tested"

rc=0; wait "$watch" || rc=$?
cat watch.txt watch.err
[ "$rc" -eq 0 ] || fail "watch exited $rc"
holds watch.txt "watch: atoms.*, recorded, $frames frames, 490 elements: A==R held in every frame"
holds watch.err "$np ranks' files (MPI)"

replay=("$nbscope" replay --headless --touching strict --dump 'atoms.*.dump')
"${replay[@]}" --contacts 'contacts.*.dump' >replay.txt 2>&1 || { cat replay.txt; fail "replay of the per-rank files failed"; }
holds replay.txt "replay: atoms.*, recorded, $frames frames, 490 elements: A==R held in every frame"

# 2. the ghost cut-off bug: the contacts whose atoms are in two ranks, gone from every rank's file.
"$python" - ghost <<'PY'
import glob, re, sys
out = sys.argv[1]
rank = {}
for p in glob.glob('atoms.*.*.dump'):
    t = re.search(r'atoms\.\d+\.(\d+)\.dump', p).group(1)
    lines = open(p).read().split('\n')
    cols = next(l for l in lines if l.startswith('ITEM: ATOMS')).split()[2:]
    for l in lines[lines.index(next(l for l in lines if l.startswith('ITEM: ATOMS'))) + 1:]:
        if l.strip():
            w = l.split()
            rank[(t, w[cols.index('id')])] = w[cols.index('proc')]
dropped = 0
for p in glob.glob('contacts.*.*.dump'):
    t = re.search(r'contacts\.\d+\.(\d+)\.dump', p).group(1)
    lines = open(p).read().rstrip('\n').split('\n') if open(p).read().strip() else []
    head = 9 if lines and lines[0].startswith('ITEM:') else 0
    rows = [l for l in lines[head:] if l.strip()]
    keep = [l for l in rows if rank[(t, str(int(float(l.split()[0]))))] == rank[(t, str(int(float(l.split()[1]))))]]
    dropped += len(rows) - len(keep)
    top = lines[:head]
    if head: top[3] = str(int(top[3]) - sum(1 for l in lines[head:head + int(top[3])] if l not in keep))
    open(out + '/' + p, 'w').write('\n'.join(top + keep) + ('\n' if top or keep else ''))
print('dropped', dropped, 'contacts across subdomains')
PY
rc=0; "${replay[@]}" --contacts 'ghost/contacts.*.dump' >ghost.txt 2>&1 || rc=$?
cat ghost.txt
[ "$rc" -eq 1 ] || fail "replay with the cross-subdomain contacts gone exited $rc, expected 1"
holds ghost.txt "missing contacts straddle a subdomain boundary"
grep -q "all [0-9]* missing contacts straddle" ghost.txt || fail "not every missing contact was said to straddle a boundary"
grep -Eq "of rank [0-9]+ and [0-9]+ of rank [0-9]+" ghost.txt || fail "the ranks of the first are not named"

# 3. rank 0's first contact written again in rank 1's rows, as both ranks would list it: one pair.
cp contacts.*.dump twice/
first=$(ls contacts.0.*.dump | head -n 1)
sed -n 10p "$first" >>"twice/${first/contacts.0./contacts.1.}"
"${replay[@]}" --contacts 'twice/contacts.*.dump' >twice.txt 2>&1 || { cat twice.txt; fail "a contact listed by two ranks was not read as one"; }
holds twice.txt "A==R held in every frame"
echo "--- mpi $np: passed"
