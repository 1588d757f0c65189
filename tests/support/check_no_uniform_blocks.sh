#!/usr/bin/env bash
# Fails if a shader declares a uniform block (push constants aside): lavapipe 22.3 inlines uniform values that
# steer branches into the shader on every pipeline bind, an LLVM compile per frame whose code stays allocated
# (docs/DESIGN.md, driver notes). Per-frame blocks are read-only storage buffers instead.
set -euo pipefail
shaders=${1:?usage: check_no_uniform_blocks.sh SHADER_DIR}
# A block's name followed by `{` on its line or at the line's end (the brace on the next); samplers and images
# end in `;`; comment lines are skipped.
found=$(grep -nE '\buniform[[:space:]]+[A-Za-z_][A-Za-z0-9_]*[[:space:]]*(\{|$)' -r "$shaders" | grep -v 'push_constant' |
  grep -vE '^[^:]+:[0-9]+:[[:space:]]*//' || true)
if [ -n "$found" ]; then
  echo "uniform blocks (read them as readonly storage buffers):" >&2
  echo "$found" >&2
  exit 1
fi
echo "no uniform block in $shaders"
