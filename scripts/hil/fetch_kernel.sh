#!/usr/bin/env bash
# Fetches the guest kernel of the hardware-in-the-loop run: Debian's current 6.1 amd64 image
# (the one linux-image-amd64 depends on) and busybox-static, through `apt-get download` and
# `dpkg -x` (never installed). Keeps the kernel, the modules the guest loads (vivid and its
# dependencies, configfs for gpio-sim) in dependency order, and busybox in
#   $1/<kernel release>/
# and prints that folder. Nothing is downloaded when it is already complete.
#
# Usage: fetch_kernel.sh CACHE_DIR LOG_FILE
set -euo pipefail
cache=$1
log=$2

fail() {
  echo "hil: $*" >&2
  exit 1
}

image_package=$(apt-cache depends linux-image-amd64 2> /dev/null |
  awk '/Depends: linux-image-[0-9]/ {print $2; exit}')
[[ -n $image_package ]] ||
  fail "Debian's package index has no linux-image-amd64 (run 'apt-get update')"
release=${image_package#linux-image-}
dir=$cache/$release
if [[ -f $dir/.complete ]]; then
  echo "$dir"
  exit 0
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/cosmos-hil-kernel.XXXXXX")
trap 'rm -rf "$work"' EXIT
echo "fetch_kernel: apt-get download $image_package busybox-static" >> "$log"
# A stale package index may name versions the archive no longer has: refresh it once.
download() { (cd "$work" && apt-get download -q "$image_package" busybox-static >> "$log" 2>&1); }
download || { apt-get update -qq >> "$log" 2>&1 && download; } ||
  fail "'apt-get download $image_package busybox-static' failed (see $log)"
for deb in "$work"/*.deb; do dpkg -x "$deb" "$work/root"; done

modules=$work/root/lib/modules/$release
[[ -f $work/root/boot/vmlinuz-$release && -d $modules/kernel ]] ||
  fail "$image_package holds no kernel or modules for $release"

# A module's dependencies, from its .modinfo section ("depends=a,b"), resolved depth first
# so that each module follows everything it needs.
module_path() {
  find "$modules/kernel" \( -name "${1//_/-}.ko" -o -name "${1//-/_}.ko" \) -print -quit
}
order=()
add_module() {
  local path
  path=$(module_path "$1")
  [[ -n $path ]] || fail "$image_package has no module $1"
  local depends
  depends=$(tr '\0' '\n' < "$path" | sed -n 's/^depends=//p' | head -n 1)
  local dependency
  for dependency in ${depends//,/ }; do add_module "$dependency"; done
  local known
  for known in "${order[@]}"; do [[ $known == "$path" ]] && return 0; done
  order+=("$path")
}
add_module vivid
add_module configfs

staging=$work/staging
mkdir -p "$staging/modules"
cp "$work/root/boot/vmlinuz-$release" "$staging/vmlinuz"
cp "$work/root/boot/config-$release" "$staging/config"
for path in "${order[@]}"; do
  cp "$path" "$staging/modules/"
  basename "$path" >> "$staging/modules/load-order"
done
cp "$work/root/bin/busybox" "$staging/busybox"
dpkg-deb -f "$work/${image_package}"_*.deb Version > "$staging/version"
echo "$image_package" > "$staging/package"
touch "$staging/.complete"

mkdir -p "$cache"
rm -rf "$dir"
mv "$staging" "$dir"
echo "$dir"
