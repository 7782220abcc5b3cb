#!/usr/bin/env bash
# The plugin library's dynamic symbol table holds its API and nothing else (ctest label
# "package"): every defined dynamic symbol must be one of the API's, and none may be a glad,
# gl*, YAML or stb symbol.
#   symbols_test.sh <path to libcubefx.so>
set -euo pipefail
lib=$1
syms=$(nm -D --defined-only "$lib" | awk '{print $3}' | c++filt)
echo "$syms" | sed 's/^/  /'
allowed='^(CUBEFX_1|fxApiVersion@@CUBEFX_1|fxCreatePlugin\(fx::PluginImports const&, fx::ErrorCode\*\)@@CUBEFX_1|fx::errorCodeName\(fx::ErrorCode\)@@CUBEFX_1|fx::Diagnostic::str.*@@CUBEFX_1)$'
unexpected=$(echo "$syms" | grep -Ev "$allowed" || true)
forbidden=$(echo "$syms" | grep -Ei '(^|[^a-z])(glad|gl[A-Z]|YAML|stbi)' || true)
if [ -n "$unexpected" ] || [ -n "$forbidden" ]; then
  echo "symbols_test: FAIL: exported beyond the API:"; echo "$unexpected$forbidden"; exit 1
fi
for must in fxApiVersion fxCreatePlugin; do
  echo "$syms" | grep -q "^$must" || { echo "symbols_test: FAIL: $must is not exported"; exit 1; }
done
echo "symbols_test: $(echo "$syms" | wc -l) symbols, all API"
