#!/usr/bin/env bash
# The tests under the sanitizers (docs/reliability.md):
#   - AddressSanitizer + UndefinedBehaviorSanitizer, built with clang in the fuzzers' tree
#     (build-fuzz/, which scripts/fuzz.sh configures the same way: every target there is
#     compiled with -fsanitize=address,undefined), so the libraries the fuzzers already
#     compiled are linked as they are;
#   - ThreadSanitizer, built with GCC into build-tsan/.
# CI runs test_firmware_bridge, test_scanner and test_realtime_threads (the realtime tests that
# start threads, linked without the simulator: tests/CMakeLists.txt) under ASan + UBSan, and
# test_realtime_threads under TSan. Any report fails the run (-fno-sanitize-recover).
#   scripts/check_sanitizers.sh           CI: the suites above, in a bounded time
#   scripts/check_sanitizers.sh --full    every test of every binary under ASan + UBSan
# The recognition tests read the regression model base of the Release build (build/, which
# scripts/test.sh makes); an instrumented build would spend minutes making its own.
# Built at -O1 without debug information: most of the time is the two builds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
full=false
if [[ ${1:-} == --full ]]; then full=true; fi
jobs=${COSMOS_BUILD_JOBS:-$(nproc)}
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
release_base=${COSMOS_BUILD_DIR:-$root/build}/test-data/regression-80.cmb

# The regression model base the recognition tests share, copied from the Release build.
model_base() {  # BUILD_DIR
  mkdir -p "$1/test-data"
  if [[ ! -f $1/test-data/regression-80.cmb ]]; then
    if [[ ! -f $release_base ]]; then
      echo "sanitizers: $release_base is missing: run scripts/test.sh first" >&2
      exit 1
    fi
    cp "$release_base" "$1/test-data/"
  fi
}

run() {  # BINARY FILTER
  echo "sanitizers: $(basename "$1") --gtest_filter=$2"
  "$1" --gtest_filter="$2" --gtest_brief=1
}

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1

# `cosmos listen` is not built in the instrumented trees: the one test that runs it is left out.
threads_filter=${COSMOS_THREADS_FILTER:-*-LcmConnection.ListenWithABadUrlPrintsOneLineAndFails}

# ASan + UBSan.
asan=${COSMOS_FUZZ_BUILD_DIR:-$root/build-fuzz}
if ! command -v clang++ > /dev/null; then
  echo "sanitizers: clang++ not found (scripts/setup.sh installs it)" >&2
  exit 1
fi
CC=clang CXX=clang++ cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCOSMOS_FUZZ=ON "${launcher[@]}" > /dev/null
model_base "$asan"
if $full; then
  cmake --build "$asan" --parallel "$jobs"
  for binary in test_core test_scanner test_firmware_bridge test_realtime test_sim test_apps; do
    run "$asan/tests/$binary" '*'
  done
else
  cmake --build "$asan" --parallel "$jobs" --target test_firmware_bridge test_scanner \
    test_realtime_threads
  run "$asan/tests/test_firmware_bridge" '*'
  run "$asan/tests/test_scanner" '*'
  run "$asan/tests/test_realtime_threads" "$threads_filter"
fi

# ThreadSanitizer.
tsan=$root/build-tsan
cmake -S "$root" -B "$tsan" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DCOSMOS_SANITIZE=thread "${launcher[@]}" > /dev/null
cmake --build "$tsan" --parallel "$jobs" --target test_realtime_threads
model_base "$tsan"
run "$tsan/tests/test_realtime_threads" "$threads_filter"
echo "sanitizers: clean"
