#!/usr/bin/env bash
# Installs the Debian packages COSMOS-Cell builds against, only when one is missing,
# so the README's commands work on a fresh Debian 12 machine and cost nothing after.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libopencv-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libassimp-dev libembree-dev libqhull-dev
  libgpiod-dev
  liblcm-dev liblcm-bin libglib2.0-dev iproute2
  libflatbuffers-dev flatbuffers-compiler
  clang libclang-rt-14-dev  # the libFuzzer harnesses (scripts/fuzz.sh)
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
"$(dirname "$0")/fetch_catalog.sh"
