#!/usr/bin/env bash
# The example writers in docs/verify and the planted-bug files in assets/examples, end to end.
#
#   verify_writers.sh STAGE WHAT NBSCOPE SOURCE_DIR OUT_DIR PYTHON [COMPILER]
#     STAGE  shape:  build the writer (warnings are errors), run it, and hold its JSON to
#                    `nbscope dump` (tests/compare_arrays.py); the bug build must differ from the
#                    dump in exactly the entries its bug touches.
#            verify: `nbscope verify` must pass the writer's arrays (exit 0) and fail the bug
#                    build's (exit 1), naming the entry the bug wrote.
#     WHAT   c (screen, docs/verify/write_arrays.c), fortran (nbs y-lists, write_arrays.F90),
#            examples (assets/examples/nine_*_bug*.json; no compiler)
# Everything it writes goes to OUT_DIR.
set -euo pipefail

[ $# -ge 6 ] || { echo "usage: $0 shape|verify c|fortran|examples NBSCOPE SOURCE_DIR OUT_DIR PYTHON [COMPILER]" >&2; exit 2; }
stage=$1 what=$2 nbscope=$3 src=$4 out=$5 python=$6 compiler=${7:-}
nine="$src/assets/examples/nine.csv"
grid=(--cell-size 1 --origin 0,0 --cells 10,10)
rm -rf "$out" && mkdir -p "$out"

fail() { echo "FAIL: $*" >&2; exit 1; }

# compare REFERENCE ACTUAL [--set 'KEY[i]=V' ...]: equal after the sets, or fail.
compare() { "$python" "$src/tests/compare_arrays.py" "$@" || fail "compare_arrays.py $*"; }

dump() {  # dump ALGORITHM > FILE: nbscope's own arrays for nine.csv on the 10 x 10 grid
  "$nbscope" dump --input "$nine" --algorithm "$1" "${grid[@]}" || fail "nbscope dump --algorithm $1"
}

# verify_expect ALGORITHM ARRAYS EXIT [TEXT]: verify's exit code is EXIT and its stdout holds TEXT.
verify_expect() {
  local algorithm=$1 arrays=$2 want=$3 text=${4:-} rc=0
  "$nbscope" verify --input "$nine" --arrays "$arrays" --algorithm "$algorithm" "${grid[@]}" \
    >"$out/verify.out" 2>"$out/verify.err" || rc=$?
  echo "--- nbscope verify --arrays $arrays: exit $rc"
  cat "$out/verify.out" "$out/verify.err"
  [ "$rc" -eq "$want" ] || fail "verify exited $rc, expected $want"
  if [ -n "$text" ]; then
    grep -qF -- "$text" "$out/verify.out" || fail "verify's output does not name $text"
  fi
}

# build_and_run NAME [FLAGS...]: compile the writer into $out/NAME and run it into $out/NAME.json.
build_and_run() {
  local name=$1
  shift
  case $what in
    c) "$compiler" -std=c99 -Wall -Wextra -pedantic -Werror "$@" \
         "$src/docs/verify/write_arrays.c" -o "$out/$name" ;;
    # -J: the module file goes to the output dir, not the working directory.
    fortran) mkdir -p "$out/$name.mod" && "$compiler" -std=f2008 -Wall -Wextra -Werror "$@" \
         -J "$out/$name.mod" "$src/docs/verify/write_arrays.F90" -o "$out/$name" ;;
  esac || fail "compiling the $what writer ($name) failed or warned"
  "$out/$name" >"$out/$name.json" || fail "$name exited $?"
}


case $what in
  c)
    build_and_run writer
    build_and_run writer_bug -DPLANT_BUG
    if [ "$stage" = shape ]; then
      dump screen >"$out/dump.json"
      compare "$out/dump.json" "$out/writer.json"
      # The bug build prints the worked example's file: element 3 one row low, on C[4][5]'s list.
      compare "$src/assets/examples/nine_screen_bug.json" "$out/writer_bug.json"
    else
      verify_expect screen "$out/writer.json" 0
      # C[4][5] -> 5 -> 3: E[5] = 3 links element 3 of cell (4,6) into cell (4,5)'s list.
      verify_expect screen "$out/writer_bug.json" 1 "E[5]"
    fi
    ;;
  fortran)
    build_and_run writer
    build_and_run writer_bug -DPLANT_BUG
    if [ "$stage" = shape ]; then
      dump nbs >"$out/dump.json"
      compare "$out/dump.json" "$out/writer.json"
      # Element 4 (1-based) on row 6's y-list: Y(4), Y(5), Y(6) change (0-based entries 3, 4, 5).
      compare "$out/dump.json" "$out/writer_bug.json" --set 'y_next[3]=-1' --set 'y_next[4]=2' --set 'y_next[5]=3'
    else
      verify_expect nbs "$out/writer.json" 0
      # y_heads[6] -> 8 -> 6 -> 4 (1-based): Y[6] = 4 links row 7's element 4 into row 6's list.
      verify_expect nbs "$out/writer_bug.json" 1 "Y[6]"
    fi
    ;;
  examples)
    screen_bug="$src/assets/examples/nine_screen_bug.json"
    nbs_bug="$src/assets/examples/nine_nbs_bug_base1.json"
    if [ "$stage" = shape ]; then
      dump screen >"$out/dump_screen.json"
      dump nbs >"$out/dump_nbs.json"
      # Each file is the dump but for the entries its bug wrote (0-based here).
      compare "$out/dump_screen.json" "$screen_bug" --set 'heads[4][6]=1' --set 'next[3]=-1' --set 'next[5]=3'
      compare "$out/dump_nbs.json" "$nbs_bug" --set 'y_next[6]=8'
    else
      verify_expect screen "$screen_bug" 1 "E[5]"
      # y_heads[7] -> 9 -> 7 -> 9 (1-based): Y[7] = 9 closes the cycle.
      verify_expect nbs "$nbs_bug" 1 "Y[7]"
    fi
    ;;
  *) echo "$0: unknown WHAT '$what'" >&2; exit 2 ;;
esac
echo "ok: $stage $what"
