#!/usr/bin/env bash
# Fails unless the README's embedding code (the ```cpp block between <!-- embed-sample-begin --> and
# <!-- embed-sample-end -->) is, line for line, the region of samples/embed/main.cpp between
# "// [embed-readme-begin]" and "// [embed-readme-end]": the README shows what the tested sample does.
# Usage: check_readme_embed.sh SOURCE_DIR
set -euo pipefail
cd "$1"
sample=$(sed -n '/^\/\/ \[embed-readme-begin\]$/,/^\/\/ \[embed-readme-end\]$/p' samples/embed/main.cpp | sed '1d;$d')
readme=$(sed -n '/^<!-- embed-sample-begin -->$/,/^<!-- embed-sample-end -->$/p' README.md | sed '1,2d' | sed '$d' | sed '$d')
if [ -z "$sample" ] || [ -z "$readme" ]; then
  echo "markers missing: samples/embed/main.cpp [embed-readme-begin/end], README.md embed-sample-begin/end" >&2
  exit 1
fi
if ! diff <(echo "$readme") <(echo "$sample"); then
  echo "README.md's embedding code differs from samples/embed/main.cpp (diff above: < README, > sample)" >&2
  exit 1
fi
echo "README embedding code = samples/embed/main.cpp's marked region ($(echo "$sample" | wc -l) lines)"
