#!/usr/bin/env bash
# Counts an example's host-side adapter lines: the lines of code between a
# "// fx-adapter begin: <part>" line and the next "// fx-adapter end" line, per part and in all.
# Not counted: blank lines, lines holding only a comment (// ..., or a /* ... */ block, which may
# span lines). A line of code with a comment after it counts once. The parts are named after what
# they hold: callbacks, setup, per-frame, teardown. Shared by the C and C++ examples:
#   count_adapter_lines.sh c_host/main.c
#   count_adapter_lines.sh irrlicht_host/main.cpp
set -euo pipefail
[ $# -eq 1 ] && [ -r "$1" ] || { echo "usage: count_adapter_lines.sh <source file>" >&2; exit 2; }
awk '/^[[:space:]]*\/\/ fx-adapter begin: / { part = $4; inside = 1; next }
     /^[[:space:]]*\/\/ fx-adapter end/      { inside = 0; next }
     !inside { next }
     block   { if (!sub(/^.*\*\//, "")) next; block = 0 }  # the rest after the block ends
     /^[[:space:]]*\/\*/ { if (!sub(/^[[:space:]]*\/\*.*\*\//, "")) { block = 1; next } }
     /^[[:space:]]*$/ || /^[[:space:]]*\/\// { next }
     { n[part]++; total++ }
     END { for (p in n) printf "%s %d\n", p, n[p]; printf "total %d\n", total + 0 }' "$1" | sort
