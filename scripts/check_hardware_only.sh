#!/usr/bin/env bash
# Builds `cosmos` without the simulator (COSMOS_SIMULATOR=OFF, what a cell's embedded machine
# runs) and checks that it links no simulator library (Embree, Qhull) and runs the
# hardware cell up to its devices: on a machine without a camera it must stop at once with
# one line naming the device and the config key.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
build_dir=${COSMOS_HARDWARE_BUILD_DIR:-$root/build-hardware-only}
export CCACHE_BASEDIR=$root  # the main build's compiles (scripts/build.sh) are reused
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCOSMOS_SIMULATOR=OFF \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache > /dev/null
cmake --build "$build_dir" --parallel "$(nproc)" --target cosmos > "$build_dir/build.log" 2>&1 ||
  { tail -n 30 "$build_dir/build.log"; exit 1; }
cosmos="$build_dir/apps/cosmos"
fail() { echo "check_hardware_only: $*" >&2; exit 1; }

if simulator_libraries=$(ldd "$cosmos" | grep -Ei 'embree|qhull'); then
  fail "the hardware-only cosmos links a simulator library: $simulator_libraries"
fi
if "$cosmos" cell --source sim > /dev/null 2> "$build_dir/sim.err"; then
  fail "--source sim ran in a build without the simulator"
fi
grep -q "built without the simulator" "$build_dir/sim.err" ||
  fail "--source sim refused without saying why: $(cat "$build_dir/sim.err")"
if [[ ! -e /dev/video0 ]]; then
  if "$cosmos" cell --source hardware --hardware "$root/config/hardware-example.yaml" \
      > /dev/null 2> "$build_dir/hardware.err"; then
    fail "the hardware cell ran without a camera"
  fi
  grep -q "/dev/video0: open: .*camera.device" "$build_dir/hardware.err" ||
    fail "no one-line device error: $(cat "$build_dir/hardware.err")"
fi
echo "check_hardware_only: $(readelf -d "$cosmos" | grep -c NEEDED) libraries needed, none of" \
  "Embree, Qhull; the hardware cell stops at its missing camera in one line"
