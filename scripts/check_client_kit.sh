#!/usr/bin/env bash
# CI step after scripts/test.sh: the client kit's integration tests (ctest label
# `integration`). In a private network namespace, the example Java subscriber (on
# cosmos_lcm_types.jar) and the example C++ subscriber (a standalone CMake project on the kit's
# package) must decode every field of the poses `cosmos cell` publishes alike; lcm-spy under
# Xvfb must show them decoded as part_pose_t (screenshot: build/test-artifacts/lcm-spy.png).
# The tests stay out of the README's test command: the build is switched back afterwards.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" --client-kit-checks
build_dir=${COSMOS_BUILD_DIR:-$root/build}
mkdir -p "$build_dir/logs"
log=$build_dir/logs/check_client_kit.log
restore() { cmake -S "$root" -B "$build_dir" -DCOSMOS_CLIENT_KIT_TESTS=OFF >> "$log" 2>&1; }
trap restore EXIT
if ! { cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCOSMOS_CLIENT_KIT_TESTS=ON &&
  cmake --build "$build_dir" --parallel "$(nproc)" --target test_clients; } > "$log" 2>&1; then
  tail -n 60 "$log"
  echo "check_client_kit: build failed (the whole output is in $log)" >&2
  exit 1
fi
ctest --test-dir "$build_dir" --label-regex integration --output-on-failure --timeout 300
echo "check_client_kit: Java and C++ subscribers and lcm-spy decode the cell's poses;" \
  "screenshot in $build_dir/test-artifacts/lcm-spy.png"
