#!/usr/bin/env bash
# Fails if any object of the given static libraries calls a function that ends the host process
# (abort, exit and friends, std::terminate): a library embedded in an application must report every
# failure as hp::Error instead. Reads the undefined symbols with nm, so it checks what was compiled.
set -euo pipefail
banned='^(abort|exit|_exit|_Exit|quick_exit|at_quick_exit|_ZSt9terminatev)$'
status=0
for lib in "$@"; do
  found=$(nm -u --format=posix "$lib" | awk '{print $1}' | grep -E "$banned" | sort -u || true)
  if [ -n "$found" ]; then
    echo "$lib calls: $found" >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "no process-ending call in: $*"
exit $status
