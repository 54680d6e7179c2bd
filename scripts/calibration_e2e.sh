#!/usr/bin/env bash
# The calibration end to end (docs/calibration.md): the deliberately mis-mounted simulated
# cell of config/cell-miscalibrated.yaml (laser plane 1° off, scanner rolled 0.5° and pitched
# 0.5°, encoder 2 % off, T_cell_scanner unknown) runs `cosmos calibrate check` (the cell on the hardware
# twins, poses against the ground truth in the cell frame) three times:
#   (a) told the design, as an uncalibrated cell is;
#   (b) after `cosmos calibrate simulate` and the four `cosmos calibrate` steps on its frames;
#   (c) told its true geometry (`cosmos calibrate truth`): the perfectly calibrated cell.
# Prints one table row each: parts identified and the pose errors of the identified parts.
#
# Environment: COSMOS_BUILD_DIR (default build; builds `cosmos` there), E2E_PARTS (default
# 100), E2E_DIR (work files, default $COSMOS_BUILD_DIR/calibration-e2e). The first run builds
# three model bases of the regression catalog (one per grid), cached for the next.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${COSMOS_BUILD_DIR:-$root/build}
parts=${E2E_PARTS:-100}
work=${E2E_DIR:-$build_dir/calibration-e2e}
cosmos=$build_dir/apps/cosmos

cmake --build "$build_dir" --parallel 2 --target cosmos > /dev/null
rm -rf "$work"
mkdir -p "$work"
for row in a b c; do
  sed "s#catalog: parts-regression.yaml#catalog: $root/config/parts-regression.yaml#" \
    "$root/config/cell-miscalibrated.yaml" > "$work/cell-$row.yaml"
  cp "$root/config/hardware-sim.yaml" "$work/hw-$row.yaml"
done

# (b): the procedure of docs/calibration.md on the simulated targets.
"$cosmos" calibrate simulate --config "$work/cell-b.yaml" --out "$work/frames" > /dev/null
"$cosmos" calibrate camera --images "$work/frames/camera" --hardware "$work/hw-b.yaml" \
  --report "$work/report/camera" > /dev/null
"$cosmos" calibrate laser --views "$work/frames/laser" --hardware "$work/hw-b.yaml" \
  --report "$work/report/laser" > /dev/null
"$cosmos" calibrate belt --belt "$work/frames/belt" --block "$work/frames/block" \
  --block-turned "$work/frames/block-turned" --target "$work/frames/ramp.yaml" --hardware "$work/hw-b.yaml" --config "$work/cell-b.yaml" \
  --report "$work/report/belt" > /dev/null
"$cosmos" calibrate cell --scan "$work/frames/spheres" --target "$work/frames/spheres.yaml" \
  --hardware "$work/hw-b.yaml" --config "$work/cell-b.yaml" --report "$work/report/cell" > /dev/null
# (c): the truth.
"$cosmos" calibrate truth --config "$work/cell-c.yaml" --hardware "$work/hw-c.yaml" > /dev/null

declare -A label=([a]="(a) nominal, uncalibrated" [b]="(b) after cosmos calibrate"
  [c]="(c) perfect calibration")
printf '%-28s %12s %12s %12s %12s %12s\n' "cell" "identified" "t med mm" "t p90 mm" \
  "R med deg" "R p90 deg"
for row in a b c; do
  line=$("$cosmos" calibrate check --config "$work/cell-$row.yaml" --hardware "$work/hw-$row.yaml" \
    --parts "$parts" 2> "$work/check-$row.log")
  echo "$line" >> "$work/check-$row.log"
  # "calibrate check: 97 of 100 parts identified (97.0 %); ... translation median 0.123 mm,
  # p90 0.456 mm; rotation median 0.078 deg, p90 0.321 deg"
  read -r identified t_median t_p90 r_median r_p90 < <(echo "$line" | sed -E \
    's/.*\(([0-9.]+) %\).*translation median ([-0-9.naN]+) mm, p90 ([-0-9.naN]+) mm; rotation median ([-0-9.naN]+) deg, p90 ([-0-9.naN]+) deg.*/\1 \2 \3 \4 \5/')
  printf '%-28s %11s%% %12s %12s %12s %12s\n' "${label[$row]}" "$identified" "$t_median" \
    "$t_p90" "$r_median" "$r_p90"
done
echo "reports: $work/report; logs: $work/check-*.log"
