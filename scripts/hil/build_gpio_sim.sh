#!/usr/bin/env bash
# Builds the gpio-sim GPIO simulator for the guest kernel, out of tree. Debian's 6.1 kernels
# do not build it (CONFIG_GPIO_SIM unset), nor the interrupt simulator it needs (IRQ_SIM, a
# hidden option only simulators select). Both come from Debian's linux-source-6.1
# (drivers/gpio/gpio-sim.c with gpiolib.h, kernel/irq/irq_sim.c) and are compiled against
# the matching linux-headers and linux-kbuild packages, all fetched with `apt-get download`
# and unpacked with `dpkg -x`. Two changes make irq_sim.c a module: a module may not call
# irq_to_desc() (not exported), so generic_handle_irq() does the same dispatch, and a module
# needs a MODULE_LICENSE.
#
# Output: KERNEL_DIR/gpio-sim/{irq_sim.ko,gpio-sim.ko}, kept until the kernel changes.
#
# Usage: build_gpio_sim.sh KERNEL_DIR LOG_FILE   (KERNEL_DIR from fetch_kernel.sh)
set -euo pipefail
kernel_dir=$1
log=$2
out=$kernel_dir/gpio-sim

fail() {
  echo "hil: $*" >&2
  exit 1
}

if [[ -f $out/.complete ]]; then exit 0; fi
release=$(basename "$kernel_dir")                # 6.1.0-57-amd64
version=$(< "$kernel_dir/version")               # 6.1.192-3
common=${release%-amd64}-common                  # 6.1.0-57-common
series=$(echo "$version" | cut -d. -f1,2)         # 6.1

work=$(mktemp -d "${TMPDIR:-/tmp}/cosmos-hil-gpio-sim.XXXXXX")
trap 'rm -rf "$work"' EXIT
packages=("linux-source-$series=$version" "linux-headers-$release=$version"
  "linux-headers-$common=$version" "linux-kbuild-$series")
echo "build_gpio_sim: apt-get download ${packages[*]}" >> "$log"
# A stale package index may name versions the archive no longer has: refresh it once.
download() { (cd "$work" && apt-get download -q "${packages[@]}" >> "$log" 2>&1); }
download || { apt-get update -qq >> "$log" 2>&1 && download; } ||
  fail "'apt-get download ${packages[*]}' failed (see $log)"
for deb in "$work"/linux-headers-*.deb "$work"/linux-kbuild-*.deb; do dpkg -x "$deb" "$work/root"; done
dpkg-deb --fsys-tarfile "$work"/linux-source-*.deb |
  tar -x -C "$work" "./usr/src/linux-source-$series.tar.xz"

headers=$work/root/usr/src/linux-headers-$release
[[ -f $headers/Makefile ]] || fail "linux-headers-$release has no Makefile"
# The flavour's Makefile includes the common one by its installed, absolute path.
sed -i "s|^include /usr/src/|include $work/root/usr/src/|" "$headers/Makefile"

src=$work/gpio-sim
mkdir -p "$src"
tar -xJf "$work/usr/src/linux-source-$series.tar.xz" -C "$src" --strip-components=3 \
  "linux-source-$series/drivers/gpio/gpio-sim.c" "linux-source-$series/drivers/gpio/gpiolib.h" \
  "linux-source-$series/kernel/irq/irq_sim.c"
grep -q 'handle_simple_irq(irq_to_desc(irqnum))' "$src/irq_sim.c" ||
  fail "kernel/irq/irq_sim.c of linux-source-$series $version no longer dispatches with irq_to_desc()"
sed -i 's/handle_simple_irq(irq_to_desc(irqnum))/generic_handle_irq(irqnum)/' "$src/irq_sim.c"
printf '\n#include <linux/module.h>\nMODULE_LICENSE("GPL");\n' >> "$src/irq_sim.c"
echo 'obj-m := irq_sim.o gpio-sim.o' > "$src/Kbuild"

echo "build_gpio_sim: make -C $headers M=$src modules" >> "$log"
make -C "$headers" M="$src" modules >> "$log" 2>&1 ||
  fail "building gpio-sim against linux-headers-$release failed (see $log)"

staging=$work/out
mkdir -p "$staging"
cp "$src/irq_sim.ko" "$src/gpio-sim.ko" "$staging/"
touch "$staging/.complete"
rm -rf "$out"
mv "$staging" "$out"
