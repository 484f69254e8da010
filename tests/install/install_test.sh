#!/usr/bin/env bash
# The install tree, the CMake package and the .deb, each checked from outside the source tree
# (tests/install/CMakeLists.txt adds one CTest test per stage):
#   install_test.sh tree   BUILD_DIR SOURCE_DIR CMAKE GENERATOR C_COMPILER
#   install_test.sh plugin BUILD_DIR SOURCE_DIR CMAKE GENERATOR C_COMPILER
#   install_test.sh deb    BUILD_DIR SOURCE_DIR CMAKE GENERATOR C_COMPILER
# Each stage installs the current build into its own temporary prefix P (cmake --install, nothing
# else copied) and runs P/bin/nbscope from an empty directory with no NBSCOPE_* variables and no
# display, so whatever it reads must come from P.
set -euo pipefail
stage="$1" build="$2" source="$3" cmake="$4" generator="$5" cc="$6"
cpack="$(dirname "$cmake")/cpack" ctest="$(dirname "$cmake")/ctest"

fail() { printf 'install test (%s): %s\n' "$stage" "$*" >&2; exit 1; }
work="$(mktemp -d "${TMPDIR:-/tmp}/nbscope-install-$stage.XXXXXX")"
work="$(cd "$work" && pwd -P)"  # as /proc/self/exe will name it
trap 'rm -rf "$work"' EXIT
case "$work" in "$source"/*) fail "the scratch directory $work is inside the source tree" ;; esac
prefix="$work/prefix"
mkdir -p "$work/cwd"
cd "$work/cwd"
unset NBSCOPE_DATA_DIR NBSCOPE_SHADER_DIR DISPLAY WAYLAND_DISPLAY
export HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config"  # no settings file of the user's

install_tree() { "$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install failed"; }

# Fails unless file $1 exists.
need() { [ -e "$1" ] || fail "$1 is missing"; }

stage_tree() {
  install_tree
  need "$prefix/bin/nbscope"
  need "$prefix/libexec/nbscope/nbscope-plugin-host"
  need "$prefix/share/nbscope/assets/scenes/default.json"
  need "$prefix/share/nbscope/assets/examples/nine.csv"
  need "$prefix/share/nbscope/shaders/circle.vert"
  need "$prefix/include/nbscope/detector.h"
  [ -n "$(find "$prefix" -path '*/cmake/nbscope/nbscopeConfig.cmake')" ] || fail "no lib/cmake/nbscope/nbscopeConfig.cmake"
  [ ! -e "$prefix/share/nbscope/assets/golden" ] || fail "the golden screenshots are the tests', not the binary's"
  local version
  version="$("$prefix/bin/nbscope" --version)" || fail "nbscope --version failed"
  [[ "$version" == *"data: $prefix/share/nbscope (installed)"* ]] || fail "the installed binary reads other data: $version"
  [[ "$version" == *"shaders: $prefix/share/nbscope/shaders (installed)"* ]] || fail "the installed binary reads other shaders: $version"
  # A bundled scene by its name alone, from a directory that has no such file.
  "$prefix/bin/nbscope" headless --scene default.json --frames 5 --quiet --report report.json || fail "headless --scene default.json failed"
  grep -q "\"path\": *\"$prefix/share/nbscope/assets/scenes/default.json\"" report.json || fail "the report names another scene: $(head -c 600 report.json)"
  # A file of that name in the current directory wins over the bundled one.
  cp "$prefix/share/nbscope/assets/scenes/pile.json" default.json
  "$prefix/bin/nbscope" headless --scene default.json --frames 1 --quiet --report own.json || fail "headless --scene ./default.json failed"
  grep -q '"path": *"default.json"' own.json || fail "./default.json lost to the bundled one: $(head -c 600 own.json)"
  rm default.json
  # The built binary (not installed) still reads the source tree, from any directory.
  version="$("$build/src/app/nbscope" --version)" || fail "the built nbscope --version failed"
  [[ "$version" == *"data: $source (build tree)"* ]] || fail "the built binary does not read the source tree: $version"
  "$build/src/app/nbscope" headless --scene assets/scenes/pile.json --frames 1 --quiet || fail "the built binary misses assets/scenes/pile.json"
  # Shaders: the window's frame drawn off-screen (no display) by the installed binary.
  "$prefix/bin/nbscope" gui --scene default.json --frames 3 --screenshot shot.png >"$work/gui.log" 2>&1 || fail "gui --screenshot failed: $(cat "$work/gui.log")"
  [ "$(head -c 8 shot.png | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "shot.png is not a PNG"
  [ "$(stat -c %s shot.png)" -gt 10000 ] || fail "shot.png is too small to hold the frame"
}

stage_plugin() {
  install_tree
  "$cmake" -S "$source/tests/install/plugin_project" -B plugin-build -G "$generator" -DCMAKE_C_COMPILER="$cc" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >"$work/plugin-configure.log" 2>&1 ||
    fail "the plugin project does not configure: $(tail -20 "$work/plugin-configure.log")"
  "$cmake" --build plugin-build >"$work/plugin-build.log" 2>&1 || fail "the plugin does not build: $(tail -20 "$work/plugin-build.log")"
  local so=plugin-build/brute_plugin.so
  need "$so"
  local exported
  exported="$(nm -D --defined-only "$so" | awk '{print $3}' | sort)"
  for symbol in nbscope_api_version nbscope_detector_describe nbscope_detect; do
    grep -qx "$symbol" <<<"$exported" || fail "$so does not export $symbol (it exports: $(tr '\n' ' ' <<<"$exported"))"
  done
  # Hidden visibility: nothing but the API leaves the plugin.
  [ "$(grep -cv '^nbscope_' <<<"$exported" || true)" -eq 0 ] || fail "$so exports more than the API: $(tr '\n' ' ' <<<"$exported")"
  # README's one line, with the compiler alone against the installed header.
  "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror -shared -fPIC -I"$prefix/include" \
    "$source/tests/install/plugin_project/brute_plugin.c" -o one_line.so || fail "the one-line cc build failed"
  nm -D --defined-only one_line.so | grep -q ' nbscope_detect$' || fail "one_line.so does not export nbscope_detect"
  # The example plugins installed as documentation build the same way from the installed copy: each
  # file that defines nbscope_detect, with the .c files of its folder that do not (shared helpers).
  local example count=0 c helpers
  while IFS= read -r example; do
    helpers=()
    for c in "$(dirname "$example")"/*.c; do grep -q 'int nbscope_detect(' "$c" || helpers+=("$c"); done
    "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror -shared -fPIC -I"$prefix/include" "$example" "${helpers[@]}" \
      -o example.so || fail "the installed example $example does not build against the installed header"
    count=$((count + 1))
  done < <(grep -rl 'int nbscope_detect(' "$prefix/share/doc/nbscope/examples" --include='*.c')
  [ "$count" -gt 0 ] || fail "no example plugin was installed under share/doc/nbscope/examples"
  # The plugin project's own tests run the installed binary (nbscope_EXECUTABLE, nbscope::nbscope):
  # its --version, and headless --detector-lib on the plugin (exit 0: every frame held).
  (cd plugin-build && "$ctest" --output-on-failure >"$work/plugin-ctest.log" 2>&1) ||
    fail "the plugin project's tests failed: $(tail -30 "$work/plugin-ctest.log")"
  grep -q "100% tests passed, 0 tests failed out of 2" "$work/plugin-ctest.log" ||
    fail "the plugin project did not run its two tests: $(cat "$work/plugin-ctest.log")"
}

stage_deb() {
  "$cpack" --config "$build/CPackConfig.cmake" -G DEB -B "$work/deb" >"$work/cpack.log" 2>&1 || fail "cpack failed: $(tail -20 "$work/cpack.log")"
  local deb
  deb="$(find "$work/deb" -maxdepth 1 -name 'nbscope_*.deb' | head -1)"
  [ -n "$deb" ] || fail "cpack made no nbscope_*.deb: $(ls "$work/deb")"
  local info files
  info="$(dpkg-deb -I "$deb")" || fail "dpkg-deb -I $deb failed"
  files="$(dpkg-deb -c "$deb")" || fail "dpkg-deb -c $deb failed"
  local depends
  depends="$(sed -n 's/^ Depends: //p' <<<"$info")"
  for package in libglfw3 libbox2d2 libstdc++6 libgl1; do
    [[ ", $depends," == *", $package "* || ", $depends," == *", $package,"* ]] || fail "Depends lacks $package: $depends"
  done
  [[ "$depends" == *libosmesa6* || "$depends" == *libegl1* ]] || fail "Depends names no off-screen GL library: $depends"
  for path in ./usr/bin/nbscope ./usr/libexec/nbscope/nbscope-plugin-host ./usr/share/nbscope/assets/scenes/default.json ./usr/share/nbscope/shaders/circle.vert \
              ./usr/include/nbscope/detector.h /cmake/nbscope/nbscopeConfig.cmake; do
    grep -q -- "$path" <<<"$files" || fail "the package lacks $path"
  done
  # Unpacked anywhere, the packaged (stripped) binary runs and reads the packaged data.
  dpkg-deb -x "$deb" root || fail "dpkg-deb -x $deb failed"
  local version
  version="$(root/usr/bin/nbscope --version)" || fail "the packaged nbscope --version failed"
  [[ "$version" == *"data: $work/cwd/root/usr/share/nbscope (installed)"* ]] || fail "the packaged binary reads other data: $version"
  root/usr/bin/nbscope headless --scene default.json --frames 2 --quiet || fail "the packaged binary cannot run default.json"
  # A plugin runs in the packaged host process (usr/libexec/nbscope), found from the packaged binary.
  "$cc" -std=c99 -shared -fPIC -I"root/usr/include" "$source/tests/install/plugin_project/brute_plugin.c" -o brute.so ||
    fail "the plugin does not build against the packaged header"
  root/usr/bin/nbscope headless --scene default.json --frames 2 --quiet --detector-lib ./brute.so >"$work/deb-plugin.log" 2>&1 ||
    fail "the packaged binary cannot run a plugin: $(cat "$work/deb-plugin.log")"
  echo "install test (deb): $(basename "$deb"), Depends: $depends"
}

case "$stage" in
  tree) stage_tree ;;
  plugin) stage_plugin ;;
  deb) stage_deb ;;
  *) fail "unknown stage" ;;
esac
