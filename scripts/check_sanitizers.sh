#!/usr/bin/env bash
# The test suite under the sanitizers (docs/reliability.md):
#   - AddressSanitizer + UndefinedBehaviorSanitizer over the unit tests, built with clang in
#     the fuzzers' tree (build-fuzz/, which scripts/fuzz.sh configures the same way: every
#     target there is compiled with -fsanitize=address,undefined), so CI compiles the
#     libraries the fuzzers and the tests share once;
#   - ThreadSanitizer over the realtime tests that run threads: the cell loop and its
#     acquisition and recognizer threads, the rings, the LCM threads (build-tsan/, GCC).
# Any report fails the run (the builds abort on the first one: -fno-sanitize-recover).
#   scripts/check_sanitizers.sh           CI: the suites below, in a bounded time
#   scripts/check_sanitizers.sh --full    every test of every binary under ASan + UBSan
# Built at -O1 without debug information: most of the time is the two builds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
full=false
if [[ ${1:-} == --full ]]; then full=true; fi
jobs=${COSMOS_BUILD_JOBS:-$(nproc)}
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

configure() {  # DIR SANITIZERS
  cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
    -DCOSMOS_SANITIZE="$2" "${launcher[@]}" > /dev/null
}

# The regression model base the recognition tests share: the Release build's copy when there
# is one (its content does not depend on the build), else built by the instrumented binary.
model_base() {  # BUILD_DIR
  mkdir -p "$1/test-data"
  if [[ ! -f $1/test-data/regression-80.cmb && -f $root/build/test-data/regression-80.cmb ]]; then
    cp "$root/build/test-data/regression-80.cmb" "$1/test-data/"
  fi
}

run() {  # BINARY FILTER
  echo "sanitizers: $(basename "$1") --gtest_filter=$2"
  "$1" --gtest_filter="$2" --gtest_brief=1
}

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1

# ASan + UBSan. The CI run builds and runs the binaries of the method, the scanner, the
# firmware bridge and the realtime loop; it leaves out test_sim and test_apps (whole
# simulated scans, model-base builds, the 100-scan regression run through the CLI) and the
# recognizer's runs over the regression base: instrumented -O1 code runs them several times
# slower, and the code they add is mostly the simulator's, which --full covers.
asan=${COSMOS_FUZZ_BUILD_DIR:-$root/build-fuzz}
if ! command -v clang++ > /dev/null; then
  echo "sanitizers: clang++ not found (scripts/setup.sh installs it)" >&2
  exit 1
fi
CC=clang CXX=clang++ cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCOSMOS_FUZZ=ON "${launcher[@]}" > /dev/null
if $full; then
  cmake --build "$asan" --parallel "$jobs"
  model_base "$asan"
  for binary in test_core test_scanner test_firmware_bridge test_realtime test_sim test_apps; do
    run "$asan/tests/$binary" '*'
  done
else
  cmake --build "$asan" --parallel "$jobs" --target test_core test_scanner test_firmware_bridge \
    test_realtime
  model_base "$asan"
  run "$asan/tests/test_core" "${COSMOS_ASAN_CORE_FILTER:-*-RecognizerOnRegressionBase*}"
  run "$asan/tests/test_scanner" '*'
  run "$asan/tests/test_firmware_bridge" '*'
  run "$asan/tests/test_realtime" "${COSMOS_ASAN_REALTIME_FILTER:-*}"
fi

# ThreadSanitizer: the realtime tests that start threads.
tsan=$root/build-tsan
configure "$tsan" thread
cmake --build "$tsan" --parallel "$jobs" --target test_realtime
model_base "$tsan"
run "$tsan/tests/test_realtime" \
  "${COSMOS_TSAN_FILTER:-CellLoop*:CellStatusLive*:SpscRing*:DeadlinePacer*:LcmConnection*:LcmMemqRoundTrip*:HardwareSource*:ReplaySource*}"
echo "sanitizers: clean"
