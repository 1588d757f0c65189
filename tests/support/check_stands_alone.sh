#!/usr/bin/env bash
# Fails if a tracked file refers to a path outside the repository (a sibling folder such as ../shared, or
# notes that live only beside the checkout): the project's docs say everything it needs in its own words.
# Usage: check_stands_alone.sh SOURCE_DIR
set -euo pipefail
cd "$1"
found=$(git ls-files -z | xargs -0 grep -InE '\.\./shared|shared/(REFERENCES|ARCHITECTURE|seed)|(REFERENCES|ARCHITECTURE)\.md' \
  -- 2>/dev/null | grep -v '^tests/support/check_stands_alone.sh:' || true)
if [ -n "$found" ]; then
  echo "$found" >&2
  echo "the files above refer to something outside the repository" >&2
  exit 1
fi
echo "no tracked file refers to a path outside the repository"
