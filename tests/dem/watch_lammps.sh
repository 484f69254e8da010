#!/usr/bin/env bash
# nbscope tests/dem: `nbscope watch` follows a LAMMPS run while it is written (docs/watch.md).
#
#   watch_lammps.sh NBSCOPE_BIN SRC_DIR OUT_DIR
#
# lmp runs tests/dem/lammps_watch.in in the background; before its first frame is written:
# 1. watch --headless on atoms.dump (one file that grows, held open by LAMMPS): every frame checked
#    (exit 0, as many frames as the file has at the end), the run's end found by the writer's exit
#    (--idle 60 is far away), and the latency from write to check quoted;
# 2. watch --headless on frames/atoms.*.dump (new files joining the glob) with a planted fault
#    (drop-pair on the code's own list) and --stop-at-violation: exit 1 at the first frame, the
#    violation named by atom ids and the report written;
# 3. the window (its own Xvfb) on the same glob, --frames 4 --screenshot: a picture of the fourth frame;
# 4. a `dimension 2` run watched without --2d (read as 2D, one note), its frames exported (--export-vtk).
# Then the two watched runs are held to `replay` of the same files: the same frames, the same verdicts.
# Exit 77 (CTest's skip) when lmp is missing, unless CI=true.
set -euo pipefail

[ $# -eq 3 ] || { echo "usage: $0 NBSCOPE_BIN SRC_DIR OUT_DIR" >&2; exit 2; }
nbscope=$(realpath "$1") here=$(realpath "$2/tests/dem") out=$3
fail() { echo "FAIL (watch): $*" >&2; exit 1; }
skip() {
  if [ "${CI:-}" = "true" ]; then fail "$* (CI=true: this test must run)"; fi
  echo "SKIP (watch): $*"
  exit 77
}
simulator=${LMP:-$(command -v lmp || true)}
[ -x "$simulator" ] || skip "lmp is not installed (apt-get install lammps; scripts/dev deps)"
rm -rf "$out" && mkdir -p "$out/frames" && cd "$out"

holds() { grep -qF -- "$2" "$1" || { cat "$1" >&2; fail "$1 does not say '$2'"; }; }

# The watchers start first: they wait for files that do not exist yet.
"$nbscope" watch atoms.dump --contacts contacts.dump --headless --idle 60 --touching strict \
  >grow.txt 2>grow.err & grow=$!
"$nbscope" watch 'frames/atoms.*.dump' --contacts 'frames/contacts.*.dump' --headless --idle 20 --touching strict \
  --inject-fault drop-pair --stop-at-violation --report stop.json >stop.txt 2>stop.err & stop=$!
window=
# The window where this nbscope has one (a build with NBSCOPE_GUI=OFF, as the sanitizer build, has none).
if command -v Xvfb >/dev/null && "$nbscope" --version | grep -q "^window: yes"; then
  # A display of its own (-displayfd picks a free one), for as long as this script runs.
  # Another server starting at the same moment can take the display it chose: tried again then.
  display=
  for attempt in 1 2 3 4 5; do
    exec 3< <(exec Xvfb -displayfd 1 -screen 0 1280x720x24 -nolisten tcp 2>/dev/null)
    if read -r -t 10 display <&3; then break; fi
    display=
    sleep 0.2
  done
  [ -n "$display" ] || fail "Xvfb did not start (5 tries)"
  trap 'pkill -P $$ Xvfb 2>/dev/null || true' EXIT
  DISPLAY=":$display" "$nbscope" watch 'frames/atoms.*.dump' --contacts 'frames/contacts.*.dump' --touching strict \
    --frames 4 --screenshot window.png --size 960x600 >window.txt 2>&1 & window=$!
fi
sleep 0.5
"$simulator" -in "$here/lammps_watch.in" -log log.lammps -echo none -screen /dev/null >lmp.out 2>&1 ||
  { tail -n 20 log.lammps >&2; fail "lmp exited non-zero"; }
written=$(grep -c "ITEM: TIMESTEP" atoms.dump)
[ "$written" -ge 8 ] || fail "lmp wrote $written frames, expected more"

rc=0; wait "$grow" || rc=$?
cat grow.txt grow.err
[ "$rc" -eq 0 ] || fail "watch of atoms.dump exited $rc, expected 0"
holds grow.txt "watch: atoms, recorded, $written frames, 490 elements: A==R held in every frame"
holds grow.err "has ended: the run is over"  # the writer's exit, not --idle 60
holds grow.txt "checked a median of"         # the latency, quoted below
echo "--- latency: $(grep -o '[0-9]* frames checked a median of [0-9]* ms (at most [0-9]* ms)' grow.txt)"

rc=0; wait "$stop" || rc=$?
cat stop.txt stop.err
[ "$rc" -eq 1 ] || fail "watch --stop-at-violation exited $rc, expected 1"
holds stop.txt "stopped at the first violation"
holds stop.json '"stopped_at_violation": '

if [ -n "$window" ]; then
  rc=0; wait "$window" || rc=$?
  cat window.txt
  [ "$rc" -eq 0 ] || fail "the watch window exited $rc, expected 0"
  [ -s window.png ] || fail "the watch window wrote no screenshot"
  holds window.txt "nbscope: window: 4 frames"
fi

# A `dimension 2` run (tests/dem/lammps_pour2d.in: z all 0 in a thin z box, ITEM: UNITS first) watched
# without --2d: read as 2D with one note, exported for ParaView as it lands.
mkdir -p flat && (
  cd flat
  # lammps_pour2d.in dumps timesteps 0..5000 every 1000: 6 frames (no short --idle: a loaded machine is slow).
  "$nbscope" watch 'atoms.*.dump' --contacts 'contacts.*.dump' --headless --frames 6 --idle 60 --touching strict --export-vtk vtk \
    >flat.txt 2>flat.err & flat=$!
  sleep 0.3
  "$simulator" -in "$here/lammps_pour2d.in" -log log.lammps -echo none -screen /dev/null >lmp.out 2>&1 || fail "lmp (2D) exited non-zero"
  rc=0; wait "$flat" || rc=$?
  cat flat.txt flat.err
  [ "$rc" -eq 0 ] || fail "watch of the 2D run exited $rc, expected 0"
  frames=$(ls atoms.*.dump | wc -l)
  [ "$frames" -eq 6 ] || fail "lmp wrote $frames frames of the 2D run, the watch waits for 6"
  holds flat.txt "watch: atoms.*, recorded, $frames frames, 240 elements: A==R held in every frame"
  holds flat.err "every z is 0 in a thin z box (a \`dimension 2\` run): read as 2D"
  [ "$(ls vtk/frame_*.vtp | wc -l)" -eq "$frames" ] || fail "--export-vtk wrote $(ls vtk | wc -l) files for $frames frames"
  holds vtk/series.pvd "frame_0.vtp"
)

# What was watched is what replay of the finished files says.
"$nbscope" replay --headless --dump atoms.dump --contacts contacts.dump --touching strict >replay.txt 2>&1 ||
  { cat replay.txt; fail "replay of the watched files failed"; }
holds replay.txt "replay: atoms, recorded, $written frames, 490 elements: A==R held in every frame"
echo "--- watch: passed"
