#!/usr/bin/env bash
# Regenerates every generated file into a scratch tree and compares it with
# the committed one, from the API definitions vendored in third_party/ (or
# the directory given). Exits 77 (skipped) only without python3.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
api=${1:-$root/third_party/anari-api}
if [ ! -d "$api" ] || ! command -v python3 >/dev/null; then
  echo "skipped: no API definitions at $api (or no python3)"
  exit 77
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$root/.clang-format" "$scratch/"
python3 "$root/tools/codegen/generate_headers.py" "$api" "$scratch"
python3 "$root/tools/codegen/generate_introspection.py" "$api" "$scratch"
status=0
while IFS= read -r file; do
  rel=${file#"$scratch"/}
  if ! cmp -s "$file" "$root/$rel"; then
    echo "out of date: $rel (run tools/codegen/generate_*.py)"
    status=1
  fi
done < <(find "$scratch" -type f ! -name .clang-format)
[ $status -eq 0 ] && echo "generated files are up to date"
exit $status
