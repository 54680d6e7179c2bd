#!/bin/busybox sh
# /init of the hardware-in-the-loop guest (scripts/hil.sh packs it into the initramfs). Loads
# vivid as one HDMI capture node looped from one HDMI output node, builds a gpio-sim chip
# with the cell's lines through configfs, routes multicast over lo for LCM, runs the checks
# named by the kernel command line's hil_steps (default: all) and powers off. Every check
# prints "hil: PASS ..." or "hil: FAIL ..."; the last line is "hil: guest exit N", N the
# number of failed steps, which scripts/hil.sh turns into its exit status.
/bin/busybox mkdir -p /usr/bin /sbin /usr/sbin
/bin/busybox --install -s
export PATH=/opt/cosmos/bin:/bin:/sbin:/usr/bin:/usr/sbin
export HOME=/tmp COSMOS_CACHE_DIR=/opt/cosmos/cache
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
mount -t tmpfs tmpfs /tmp
config=/opt/cosmos/config
hardware=$config/hardware-hil.yaml
gpio_sim=/sys/kernel/config/gpio-sim/cosmos
failed=0

say() { echo "hil: $*"; }
finish() {
  say "guest exit $failed"
  sync
  poweroff -f
}
uptime_s() { cut -d' ' -f1 /proc/uptime; }

say "guest up at $(uptime_s) s ($(nproc) CPUs, kernel $(uname -r))"
for module in $(cat /lib/modules/hil/load-order); do
  parameters=""
  # One vivid instance: an HDMI capture node (/dev/video0) and an HDMI output node
  # (/dev/video1), cropping on the capture side only (the camera's ROI).
  [ "$module" = vivid.ko ] && parameters="n_devs=1 node_types=0x101 num_inputs=1 input_types=0x3 \
num_outputs=1 output_types=0x1 ccs_cap_mode=1 ccs_out_mode=0 vid_cap_nr=0 vid_out_nr=1"
  if ! insmod "/lib/modules/hil/$module" $parameters 2> /tmp/insmod.log; then
    say "FAIL insmod $module: $(cat /tmp/insmod.log)"
    failed=$((failed + 1))
    finish
  fi
done
say "modules loaded at $(uptime_s) s: $(cat /sys/class/video4linux/video0/name) on /dev/video0, \
$(cat /sys/class/video4linux/video1/name) on /dev/video1"

# The cell's GPIO chip: one bank of eight named lines (config/hardware-hil.yaml's names).
mount -t configfs configfs /sys/kernel/config
mkdir "$gpio_sim" "$gpio_sim/bank0"
echo 8 > "$gpio_sim/bank0/num_lines"
echo cosmos-hil > "$gpio_sim/bank0/label"
line=0
for name in ENC_A ENC_B PHOTO_EYE LASER_EN CAM_TRIG RESULT_RDY; do
  mkdir "$gpio_sim/bank0/line$line"
  echo "$name" > "$gpio_sim/bank0/line$line/name"
  line=$((line + 1))
done
echo 1 > "$gpio_sim/live"
say "gpio-sim chip $(cat "$gpio_sim/bank0/chip_name") (label cosmos-hil) live on $(cat "$gpio_sim/dev_name")"

# LCM's multicast group over loopback: the guest has no other network.
ip link set lo up
ip route add 224.0.0.0/4 dev lo

run_step() {
  name=$1
  shift
  start=$(uptime_s)
  "$@"
  status=$?
  if [ "$status" -eq 0 ]; then
    say "step $name done in $(awk "BEGIN {print $(uptime_s) - $start}") s"
  else
    failed=$((failed + 1))
    say "FAIL step $name (exit status $status)"
  fi
}

# The bridge on the player's faults: a short conveyor, HardwareSource on devices the probe
# holds, so that the camera's and the decoder's counters can be read.
faults_run() {
  rm -f /tmp/probe.plan /tmp/probe.log
  hil_player --tape /opt/cosmos/tapes/probe.tape --hardware "$hardware" --faults probe \
    --plan /tmp/probe.plan --log /tmp/probe.log > /tmp/probe.out 2>&1 &
  player=$!
  hil_probe faults --hardware "$hardware" --config "$config/cell-hil.yaml" \
    --plan /tmp/probe.plan --player-log /tmp/probe.log
  probe_status=$?
  wait $player
  player_status=$?
  cat /tmp/probe.out
  [ $probe_status -eq 0 ] && [ $player_status -eq 0 ]
}

# The cell's run: the player plays the conveyor (with the cell's faults), lcm-logger records
# what the cell publishes, and the cell scans for as long as the player's plan says.
cell_run() {
  rm -f /tmp/plan /tmp/player.log /tmp/cell.lcm
  hil_player --tape /opt/cosmos/tapes/cell.tape --hardware "$hardware" --faults cell \
    --plan /tmp/plan --log /tmp/player.log > /tmp/player.out 2>&1 &
  player=$!
  waited=0
  while [ ! -f /tmp/plan ] && [ $waited -lt 600 ] && kill -0 $player 2> /dev/null; do
    sleep 0.1
    waited=$((waited + 1))
  done
  if [ ! -f /tmp/plan ]; then
    say "FAIL the player made no plan: $(cat /tmp/player.out)"
    return 1
  fi
  duration=$(awk '{print $7}' /tmp/plan)
  say "player: $(cat /tmp/plan) (cell runs $duration s of data time)"
  lcm-logger -q -f /tmp/cell.lcm &
  logger=$!
  cosmos cell --config "$config/cell-hil.yaml" --source hardware --hardware "$hardware" \
    --parts "$parts" --unpaced --duration-s "$duration" > /tmp/cell.out 2>&1
  cell_status=$?
  sed 's/^/cell: /' /tmp/cell.out
  # A cell that failed leaves the player waiting for captures that never come.
  [ $cell_status -ne 0 ] && kill $player 2> /dev/null
  wait $player
  player_status=$?
  cat /tmp/player.out
  sleep 1
  kill $logger
  wait $logger
  if [ $cell_status -ne 0 ]; then
    say "FAIL cosmos cell exited with status $cell_status"
    return 1
  fi
  [ $player_status -eq 0 ] || return 1
  hil_check --config "$config/cell-hil.yaml" --tape /opt/cosmos/tapes/cell.tape \
    --player-log /tmp/player.log --lcm-log /tmp/cell.lcm
}

parts=${hil_parts:-10}
steps=${hil_steps:-loop,lifecycle,formats,gpio,faults,cell}
for step in $(echo "$steps" | tr ',' ' '); do
  case $step in
    loop) run_step loop hil_probe loop --hardware "$hardware" --output /dev/video1 ;;
    lifecycle) run_step lifecycle hil_probe lifecycle --hardware "$hardware" ;;
    formats) run_step formats hil_probe formats --hardware "$hardware" ;;
    gpio) run_step gpio hil_probe gpio --hardware "$hardware" --gpio-sim "$gpio_sim" ;;
    faults) run_step faults faults_run ;;
    cell) run_step cell cell_run ;;
    *)
      say "FAIL unknown step $step"
      failed=$((failed + 1))
      ;;
  esac
done
finish
