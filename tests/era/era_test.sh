#!/usr/bin/env bash
# The headers against older language standards, with every compiler found (ctest: era_compilers):
#   - tests/era/C89Host.c as C89 (-std=c89 -pedantic-errors -Wall -Wextra -Werror, less
#     -Wmissing-field-initializers, which FX_DESC_INIT's C89 form trips: fx/fx.h says why) with
#     gcc and clang, linked against the libcubefx.so of this build and run (it renders smoke);
#   - tests/era/Api20Host.c, a host of API 2.0 built against the frozen 2.0 header, as C99 with
#     gcc and clang, run against the same library;
#   - tests/era/CxxLayerHost.cpp, a host of the C++ layer (fx/Plugin.h, fx/detail/*.h), compiled
#     as C++11, C++14 and C++17 with -pedantic-errors -Wall -Wextra -Werror by g++ and clang++
#     (-fsyntax-only: the templates the host uses are still instantiated and checked).
# A compiler that is not installed is reported and left out; at least one C and one C++ compiler
# must be found.
#   era_test.sh <source root> <libcubefx.so> <reactions.yaml> <scratch folder> [glm include dir...]
set -euo pipefail
src=$(cd "$1" && pwd)
lib=$2
reactions=$3
work=$4
shift 4
glm_flags=()
for d in "$@"; do [ -n "$d" ] && glm_flags+=("-I$d"); done
rm -rf "$work"
mkdir -p "$work"
log() { echo "era_test: $*"; }
failed=0
read -r -a osmesa <<<"$(pkg-config --cflags --libs osmesa)"
libdir=$(dirname "$lib")

c_found=0
for cc in gcc clang; do
  if ! command -v "$cc" >/dev/null; then log "$cc not installed: left out"; continue; fi
  c_found=1
  if "$cc" -std=c89 -pedantic-errors -Wall -Wextra -Wno-missing-field-initializers -Werror \
       -I"$src/fx_plugin/include" "$src/tests/era/C89Host.c" -o "$work/c89_host_$cc" \
       "$lib" "${osmesa[@]}" -lm 2>"$work/c89_$cc.log"; then
    if LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$work/c89_host_$cc" "$reactions"; then
      log "C89 host, $cc: built and passed"
    else
      log "FAIL: C89 host built by $cc failed its checks"; failed=1
    fi
  else
    cat "$work/c89_$cc.log"; log "FAIL: $cc -std=c89 -pedantic-errors"; failed=1
  fi
  # The API 2.0 host, against the frozen 2.0 header beside it (not fx_plugin/include).
  if "$cc" -std=c99 -pedantic-errors -Wall -Wextra -Werror "$src/tests/era/Api20Host.c" -o "$work/api20_host_$cc" \
       "$lib" 2>"$work/api20_$cc.log"; then
    if LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$work/api20_host_$cc" "$reactions" 2>/dev/null; then
      log "API 2.0 host, $cc: built and passed"
    else
      log "FAIL: API 2.0 host built by $cc failed its checks"; failed=1
    fi
  else
    cat "$work/api20_$cc.log"; log "FAIL: $cc -std=c99, API 2.0 host"; failed=1
  fi
done

cxx_found=0
for cxx in g++ clang++; do
  if ! command -v "$cxx" >/dev/null; then log "$cxx not installed: left out"; continue; fi
  cxx_found=1
  for std in c++11 c++14 c++17; do
    if "$cxx" -std=$std -pedantic-errors -Wall -Wextra -Werror -fsyntax-only -I"$src/fx_plugin/include" "${glm_flags[@]}" \
         "$src/tests/era/CxxLayerHost.cpp" 2>"$work/cxx_${cxx}_$std.log"; then
      log "C++ layer, $cxx -std=$std -pedantic-errors: compiled"
    else
      head -20 "$work/cxx_${cxx}_$std.log"; log "FAIL: C++ layer, $cxx -std=$std"; failed=1
    fi
  done
done

[ "$c_found" = 1 ] && [ "$cxx_found" = 1 ] || { log "FAIL: no C or no C++ compiler found"; exit 1; }
[ "$failed" = 0 ] || exit 1
log "passed"
