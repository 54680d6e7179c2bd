#!/usr/bin/env bash
# The acceptance run on the full catalog: a model base of the 20 parts of
# config/parts-acceptance.yaml (320 views each), then `cosmos eval` with 1,000 seeded scans
# of them plus scans of the 5 catalog parts outside the base, which must be rejected.
# Writes metrics.json and report.html under $COSMOS_ACCEPTANCE_DIR (default
# build/acceptance). Extra arguments go to `cosmos eval` (e.g. --threads 2 --tests 200).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build_dir=${COSMOS_BUILD_DIR:-$root/build}
out=${COSMOS_ACCEPTANCE_DIR:-$build_dir/acceptance}
mkdir -p "$out"
base="$out/acceptance-320.cmb"
if [ ! -f "$base" ]; then
  "$build_dir/apps/cosmos" modelbase build --catalog "$root/config/parts-acceptance.yaml" \
    --views 320 --out "$base.partial"
  mv "$base.partial" "$base"
fi
"$build_dir/apps/cosmos" modelbase info "$base" | head -5
exec "$build_dir/apps/cosmos" eval --modelbase "$base" --catalog "$root/config/parts.yaml" \
  --tests 1000 --seed 1 --unknown bunny,camel,homer,anchor,dragknob --out "$out" "$@"
