#!/usr/bin/env bash
# The build identity (engine/build_identity.cmake) follows what it hashes: the same sources and compiler give the
# same identity wherever they lie; a changed byte in a source or a changed compiler line gives another.
# Usage: check_build_identity.sh SOURCE_DIR CMAKE
set -euo pipefail
script="$1/engine/build_identity.cmake"
cmake=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
identity() {  # identity ROOT COMPILER_LINE: the identity of ROOT's a.cpp and b.h
  printf '%s\n%s\n' "$1/a.cpp" "$1/b.h" > "$work/sources.txt"
  printf '%s\n' "$2" > "$work/compiler.txt"
  "$cmake" -DSOURCES="$work/sources.txt" -DCOMPILER="$work/compiler.txt" -DROOT="$1" -DOUTPUT="$work/id.h" -P "$script"
  sed -n 's/^#define HAIRPIPE_BUILD_IDENTITY "\([0-9a-f]\{32\}\)"$/\1/p' "$work/id.h"
}
mkdir -p "$work/one" "$work/two"
printf 'int a;\n' > "$work/one/a.cpp"
printf 'int b;\n' > "$work/one/b.h"
cp "$work/one/a.cpp" "$work/one/b.h" "$work/two/"
base=$(identity "$work/one" "GNU 12.2.0 -O3")
fail() { echo "check_build_identity: $*"; exit 1; }
[ ${#base} = 32 ] || fail "no 32-digit identity written (got '$base')"
[ "$(identity "$work/two" "GNU 12.2.0 -O3")" = "$base" ] || fail "the same sources elsewhere give another identity"
[ "$(identity "$work/one" "GNU 12.2.0 -O2")" != "$base" ] || fail "another compiler line gives the same identity"
printf 'int b;\n ' > "$work/two/b.h"
[ "$(identity "$work/two" "GNU 12.2.0 -O3")" != "$base" ] || fail "a changed header gives the same identity"
printf 'int b;\n' > "$work/two/b.h"
[ "$(identity "$work/two" "GNU 12.2.0 -O3")" = "$base" ] || fail "restoring the header does not restore the identity"
echo "check_build_identity: ok ($base)"
