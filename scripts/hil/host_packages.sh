#!/usr/bin/env bash
# Installs what the hardware-in-the-loop run needs on the host and the project's own set-up
# (scripts/setup.sh) does not: qemu (the guest runs under TCG, no KVM needed), and what an
# out-of-tree module build against Debian's kernel headers needs (make, the headers' gcc-12,
# libelf for kbuild's tools, xz for the kernel source tarball). Only missing packages are
# installed, quietly; apt's output goes to the log file.
#
# Usage: host_packages.sh LOG_FILE
set -euo pipefail
log=$1
packages=(qemu-system-x86 make gcc-12 libelf1 xz-utils)
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2> /dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
((${#missing[@]})) || exit 0
echo "hil: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
{
  "${sudo_cmd[@]}" apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
      "${missing[@]}"
} >> "$log" 2>&1 || {
  echo "hil: FAIL installing ${missing[*]} failed (see $log)" >&2
  exit 1
}
