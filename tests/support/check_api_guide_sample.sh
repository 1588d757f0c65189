#!/usr/bin/env bash
# Fails unless the API guide's frame loop (docs/API.md, the ```cpp block between <!-- embed-sample-begin -->
# and <!-- embed-sample-end -->) is, line for line, the region of samples/embed/main.cpp between
# "// [embed-readme-begin]" and "// [embed-readme-end]": the guide shows what the tested sample does.
# Usage: check_api_guide_sample.sh SOURCE_DIR
set -euo pipefail
cd "$1"
sample=$(sed -n '/^\/\/ \[embed-readme-begin\]$/,/^\/\/ \[embed-readme-end\]$/p' samples/embed/main.cpp | sed '1d;$d')
readme=$(sed -n '/^<!-- embed-sample-begin -->$/,/^<!-- embed-sample-end -->$/p' docs/API.md | sed '1,2d' | sed '$d' | sed '$d')
if [ -z "$sample" ] || [ -z "$readme" ]; then
  echo "markers missing: samples/embed/main.cpp [embed-readme-begin/end], docs/API.md embed-sample-begin/end" >&2
  exit 1
fi
if ! diff <(echo "$readme") <(echo "$sample"); then
  echo "docs/API.md's frame loop differs from samples/embed/main.cpp (diff above: < guide, > sample)" >&2
  exit 1
fi
echo "docs/API.md frame loop = samples/embed/main.cpp's marked region ($(echo "$sample" | wc -l) lines)"
