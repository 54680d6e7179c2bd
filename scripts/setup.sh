#!/usr/bin/env bash
# Installs the Debian packages COSMOS-Cell builds against, only when one is missing,
# so the README's commands work on a fresh Debian 12 machine and cost nothing after.
# apt's and dpkg's output goes to a log (one line per step here; the log's end on failure).
#
#   scripts/setup.sh                      what the build and `scripts/test.sh` need
#   scripts/setup.sh --client-kit-checks  also what scripts/check_client_kit.sh runs: an X
#                                         server (Xvfb) and the AWT part of the JRE for lcm-spy
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

packages=(
  build-essential cmake pkg-config git
  # Compiles shared by the build trees (the hardware-only build, a rebuild after a checkout).
  ccache
  libeigen3-dev libopencv-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libembree-dev libqhull-dev
  libgpiod-dev
  liblcm-dev liblcm-bin libglib2.0-dev iproute2
  libflatbuffers-dev flatbuffers-compiler
  libcpp-httplib-dev
  # The client kit: the Java message classes (cosmos_lcm_types.jar) are compiled against LCM's
  # Java runtime.
  default-jdk-headless liblcm-java
  clang libclang-rt-14-dev  # the libFuzzer harnesses (scripts/fuzz.sh)
)
for argument in "$@"; do
  case $argument in
    --client-kit-checks) packages+=(xvfb default-jre) ;;
    *)
      echo "setup: unknown option '$argument' (expected --client-kit-checks)" >&2
      exit 2
      ;;
  esac
done

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]})); then
  log_dir=${COSMOS_BUILD_DIR:-$root/build}/logs
  mkdir -p "$log_dir"
  log=$log_dir/setup.log
  echo "setup: installing Debian packages: ${missing[*]} (apt's output in $log)"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  {
    "${sudo_cmd[@]}" apt-get update -qq &&
      DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq \
        --no-install-recommends "${missing[@]}"
  } > "$log" 2>&1 || {
    tail -n 20 "$log" >&2
    echo "setup: apt-get failed (the whole output is in $log)" >&2
    exit 1
  }
fi
"$root/scripts/fetch_catalog.sh"
