#!/usr/bin/env bash
# The plugin library's dynamic symbol table holds its C boundary (fx/fx.h) and nothing else
# (ctest label "package"): exactly fxApiVersion, fxGetApi and fxErrorCodeName, no C++-mangled
# name at all, and no glad, gl*, YAML or stb symbol.
#   symbols_test.sh <path to libcubefx.so>
set -euo pipefail
lib=$1
raw=$(nm -D --defined-only "$lib" | awk '{print $3}')
echo "$raw" | sed 's/^/  /'
allowed='^(CUBEFX_2|fxApiVersion@@CUBEFX_2|fxGetApi@@CUBEFX_2|fxErrorCodeName@@CUBEFX_2)$'
unexpected=$(echo "$raw" | grep -Ev "$allowed" || true)
mangled=$(echo "$raw" | grep -E '^_Z' || true)
forbidden=$(echo "$raw" | grep -Ei '(^|[^a-z])(glad|gl[A-Z]|YAML|stbi)' || true)
if [ -n "$unexpected" ] || [ -n "$mangled" ] || [ -n "$forbidden" ]; then
  echo "symbols_test: FAIL: exported beyond the C API:"; echo "$unexpected$mangled$forbidden"; exit 1
fi
for must in fxApiVersion fxGetApi fxErrorCodeName; do
  echo "$raw" | grep -q "^$must@@" || { echo "symbols_test: FAIL: $must is not exported"; exit 1; }
done
echo "symbols_test: $(echo "$raw" | wc -l) symbols, all C API, none mangled"
