#!/usr/bin/env bash
# The README's main job (until the simulated cell exists): synthesize analytic surfaces,
# run `cosmos inspect` on each, and say where the pictures are.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build_dir=${COSMOS_BUILD_DIR:-$root/build}
cosmos="$build_dir/apps/cosmos"
out=${COSMOS_DEMO_DIR:-$root/demo-output}
mkdir -p "$out"
for shape in sphere cylinder saddle torus capsule box-corner ellipsoid; do
  "$cosmos" synth "$shape" --out "$out/$shape.tiff" --noise-mm 0.02 --seed 7 --rotate-deg 20
  "$cosmos" inspect "$out/$shape.tiff" --out "$out/$shape"
  echo "$shape: pictures in $out/$shape/ (range.png shape_index.png csmps.png gauss_map.png spectrum.png), features in $out/$shape/cosmos.json"
done
