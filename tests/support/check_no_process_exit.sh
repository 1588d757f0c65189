#!/usr/bin/env bash
# Fails if any function in the given static libraries calls a function that ends the host process
# (abort, exit and friends, std::terminate): a library embedded in an application must report every
# failure as hp::Error instead. Reads the compiled code's relocations (objdump), so it checks what was
# compiled and names the calling function.
# One caller is the language's, not ours: clang emits __clang_call_terminate, the handler that calls
# std::terminate when an exception reaches a noexcept boundary (gcc does the same inside its personality
# routine, with no symbol to see). It is not a call the library makes, so it is not counted.
set -euo pipefail
banned='^(abort|exit|_exit|_Exit|quick_exit|at_quick_exit|_ZSt9terminatev)(@.*)?$'
status=0
for lib in "$@"; do
  found=$(objdump -dr --no-show-raw-insn "$lib" | awk -v banned="$banned" '
    /^[0-9a-f]+ <.*>:$/ { caller = substr($2, 2, length($2) - 3) }
    / R_X86_64_[A-Z0-9_]+\t/ {
      callee = $NF; sub(/[-+]0x[0-9a-f]+$/, "", callee)
      if (callee ~ banned && caller != "__clang_call_terminate") print caller " -> " callee
    }' | sort -u || true)
  if [ -n "$found" ]; then
    echo "$lib calls:" >&2
    echo "$found" >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "no process-ending call in: $*"
exit $status
