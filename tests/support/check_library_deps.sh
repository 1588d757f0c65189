#!/usr/bin/env bash
# Fails if the hairpipe library an engine links depends on libpng or on the tools target:
#   1. its CMake link interface (a file CMake generates, one item per line) names neither PNG nor hairpipe_tools;
#   2. its objects reference no png_* symbol and no symbol that the tools archive defines (what was compiled).
# Usage: check_library_deps.sh LIBHAIRPIPE.a LIBHAIRPIPE_TOOLS.a LINK_INTERFACE.txt
set -euo pipefail
lib=$1 tools=$2 links=$3
status=0
if grep -Ei 'png|hairpipe_tools' "$links"; then
  echo "the hairpipe target links the above (libpng or the tools target)" >&2
  status=1
fi
undefined=$(nm -u --format=posix "$lib" | awk '{print $1}' | sort -u)
if echo "$undefined" | grep -E '^png_'; then
  echo "$lib references libpng" >&2
  status=1
fi
defined_by_tools=$(nm --defined-only --format=posix "$tools" | awk '$2 ~ /^[TtDdBbRrVvWw]$/ {print $1}' | sort -u)
both=$(comm -12 <(echo "$undefined") <(echo "$defined_by_tools"))
if [ -n "$both" ]; then
  echo "$lib references symbols of the tools target:" >&2
  echo "$both" | head -20 >&2
  status=1
fi
[ $status -eq 0 ] && echo "$lib depends on neither libpng nor the tools target"
exit $status
