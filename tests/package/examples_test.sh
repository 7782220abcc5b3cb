#!/usr/bin/env bash
# The C and Irrlicht examples against the package that package_test.sh installed and moved (ctest
# fixture "cubefx_package"; label "package"). Each builds with only CMAKE_PREFIX_PATH pointing at
# the prefix (find_package(CubeFx CONFIG REQUIRED)) and runs:
#   c_host         C99 through fx/fx.h on OSMesa: a Z-up world, linear fog, a two-player split
#                  screen (two viewports, a scissor each, one renderView each). Its exit status
#                  checks smoke pixels in each half, the occluding post intact, no plugin or GL
#                  error; here each half's printed smoke count must be > 0, and its adapter lines
#                  (examples/count_adapter_lines.sh on its main.c) 1 .. MAX_C_HOST_ADAPTER_LINES.
#                  Built twice, neither with glm:
#                  by CMake (find_package(CubeFx COMPONENTS C), glm made unfindable with
#                  CMAKE_DISABLE_FIND_PACKAGE_glm) on its own smoke.yaml, and by its Makefile
#                  through pkg-config alone, with a pkg-config path that holds no glm.pc and
#                  a dependency list (-MD) that must name no glm header, run on the package's
#                  installed burnout_smoke.yaml (cubefx.pc's reactionsdir).
#   irrlicht_host  Irrlicht 1.8 under xvfb-run, three 320x240 screenshots after 90 frames:
#                  --no-plugin (never created), --no-smoke (plugin running, last frame without
#                  renderView) and the smoke frame. Checks: no-smoke == no-plugin (0 pixels off:
#                  the plugin leaves Irrlicht's GL state as it found it); smoke differs from
#                  no-smoke at more than MIN_SMOKE_PIXELS pixels; the GUI label's rectangle is
#                  identical in both (the GUI is drawn over the smoke); so is a rectangle inside
#                  the crate that stands in front of the trail (the smoke is hidden behind it:
#                  before the plugin turned off a compatibility context's alpha test, 673 of its
#                  896 pixels changed); no plugin error.
#                  Exit 77 (ctest: skipped) only when Irrlicht's headers or xvfb-run are missing.
#   examples_test.sh <source root> <installed prefix> <scratch folder> c_host|irrlicht_host
set -euo pipefail
src=$(cd "$1" && pwd)
prefix=$2
work=$3
example=$4
MIN_SMOKE_PIXELS=1500  # of 76800; the trail covers several thousand at 320x240
MAX_C_HOST_ADAPTER_LINES=40  # a Z-up host with fog and a split screen
log() { echo "examples_test: $*"; }
fail() { echo "examples_test: FAIL: $*"; exit 1; }
[ -e "$prefix/lib/cmake/CubeFx/CubeFxConfig.cmake" ] || fail "no installed package at $prefix (package_test.sh installs it)"
prefix=$(cd "$prefix" && pwd)
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
export LD_LIBRARY_PATH="$prefix/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

build() {  # build <example> [cmake options]
  cmake -S "$src/examples/$1" -B "$work/$1" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${@:2}" \
        >"$work/$1-configure.log" || { cat "$work/$1-configure.log"; fail "$1 did not configure"; }
  cmake --build "$work/$1" -j"$(nproc)" >"$work/$1-build.log" 2>&1 || { cat "$work/$1-build.log"; fail "$1 did not build"; }
  # Warnings are defects in an example people copy from.
  if grep -q "warning:" "$work/$1-build.log"; then cat "$work/$1-build.log"; fail "$1 builds with warnings"; fi
}

case "$example" in
c_host)
  log "examples/c_host (C99, fx/fx.h only) against $prefix"
  build c_host -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON
  grep -q "CubeFx example reactions: $prefix/share/cubefx/reactions" "$work/c_host-configure.log" ||
    fail "CubeFx_REACTIONS_DIR does not name the installed reactions"
  "$work/c_host/c_host" "$work/c_host/smoke.yaml" "$work/c_host.png" | tee "$work/c_host.out"
  [ -s "$work/c_host.png" ] || fail "c_host wrote no PNG"
  for player in 1 2; do  # "player N: renderView None; smoke pixels P of ..."
    px=$(sed -n "s/^player $player: .*smoke pixels \([0-9]*\) of.*/\1/p" "$work/c_host.out")
    [ -n "$px" ] && [ "$px" -gt 0 ] || fail "no smoke in player $player's half (${px:-no count printed})"
  done
  bash "$src/examples/count_adapter_lines.sh" "$src/examples/c_host/main.c" | tee "$work/c_host_adapter.txt"
  adapter=$(sed -n 's/^total //p' "$work/c_host_adapter.txt")
  log "c_host adapter lines: $adapter (need <= $MAX_C_HOST_ADAPTER_LINES)"
  [ "${adapter:-0}" -gt 0 ] || fail "no adapter lines counted in c_host/main.c (markers missing?)"
  [ "$adapter" -le "$MAX_C_HOST_ADAPTER_LINES" ] || fail "c_host's adapter is $adapter lines"

  log "examples/c_host/Makefile: pkg-config only, no glm.pc on the pkg-config path"
  noglm=$work/pkgconfig-without-glm  # the host's other packages, and not glm
  mkdir -p "$noglm" "$work/c_make"
  for pc in osmesa stb; do cp "$(pkg-config --variable=pcfiledir "$pc")/$pc.pc" "$noglm/"; done
  export PKG_CONFIG_LIBDIR="$prefix/lib/pkgconfig:$noglm"
  ! pkg-config --exists cubefx-cxx || fail "glm.pc is still visible (cubefx-cxx.pc resolves)"
  make -C "$work/c_make" -f "$src/examples/c_host/Makefile" "CFLAGS=-O2 -MD" >"$work/c_make.log" 2>&1 ||
    { cat "$work/c_make.log"; fail "the Makefile build failed"; }
  if grep -q "warning:" "$work/c_make.log"; then cat "$work/c_make.log"; fail "the Makefile build warns"; fi
  if grep -q "glm" "$work/c_make/c_host.d"; then fail "the C host read a glm header"; fi
  reactions=$(pkg-config --variable=reactionsdir cubefx)
  unset PKG_CONFIG_LIBDIR
  # The Makefile's rpath finds the library: run without LD_LIBRARY_PATH.
  env -u LD_LIBRARY_PATH "$work/c_make/c_host" "$reactions/burnout_smoke.yaml" "$work/c_host_make.png"
  [ -s "$work/c_host_make.png" ] || fail "the Makefile's c_host wrote no PNG"
  ;;
irrlicht_host)
  if [ ! -e /usr/include/irrlicht/irrlicht.h ]; then
    log "SKIP: Irrlicht 1.8 headers missing (apt-get install libirrlicht-dev; scripts/deps.sh does)"; exit 77
  fi
  command -v xvfb-run >/dev/null || { log "SKIP: xvfb-run missing (apt-get install xvfb; scripts/deps.sh does)"; exit 77; }
  log "examples/irrlicht_host (Irrlicht 1.8, OpenGL driver, under xvfb-run) against $prefix"
  build irrlicht_host
  run() {  # run <name> [options]: a 320x240 screenshot after 90 frames
    local name=$1; shift
    (cd "$work/irrlicht_host" &&
      xvfb-run -a ./irrlicht_host --frames 90 --size 320x240 --screenshot "$work/$name.png" "$@") \
      >"$work/$name.out" 2>"$work/$name.err" || { cat "$work/$name.out" "$work/$name.err"; fail "irrlicht_host $* failed"; }
    if grep -q "^\[fx 2\]" "$work/$name.err"; then cat "$work/$name.err"; fail "the plugin logged an error ($name)"; fi
    grep -q "api_errors 0" "$work/$name.out" || { cat "$work/$name.out"; fail "API errors counted ($name)"; }
  }
  run no_plugin --no-plugin
  run no_smoke --no-smoke
  run smoke
  diff_px() { python3 "$src/tests/package/png_diff.py" "$@" | cut -d' ' -f1; }
  read -r _ x0 y0 x1 y1 < <(grep "^label_rect" "$work/smoke.out")
  read -r _ ox0 oy0 ox1 oy1 < <(grep "^occluder_rect" "$work/smoke.out")
  off=$(diff_px "$work/no_smoke.png" "$work/no_plugin.png")
  smoke=$(diff_px "$work/smoke.png" "$work/no_smoke.png")
  label=$(diff_px "$work/smoke.png" "$work/no_smoke.png" --rect "$x0" "$y0" "$x1" "$y1")
  hidden=$(diff_px "$work/smoke.png" "$work/no_smoke.png" --rect "$ox0" "$oy0" "$ox1" "$oy1")
  log "no-smoke vs no-plugin: $off pixels off (need 0); smoke vs no-smoke: $smoke pixels (need > $MIN_SMOKE_PIXELS);" \
      "label ($x0,$y0)-($x1,$y1): $label pixels changed (need 0); crate in front ($ox0,$oy0)-($ox1,$oy1):" \
      "$hidden pixels changed (need 0)"
  grep -h "^frame_ms" "$work/no_plugin.out" "$work/smoke.out" || true
  [ "$off" -eq 0 ] || fail "a frame without smoke differs from Irrlicht without the plugin"
  [ "$smoke" -gt "$MIN_SMOKE_PIXELS" ] || fail "too few smoke pixels"
  [ "$label" -eq 0 ] || fail "the GUI label changed under the smoke"
  [ "$hidden" -eq 0 ] || fail "smoke drawn over the crate in front of it"
  ;;
*) fail "unknown example '$example'" ;;
esac
log "$example passed"
