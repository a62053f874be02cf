#!/usr/bin/env bash
# Takes docs/machine.png: the Machine page of the sample lathe, online and running its part
# program (`--run --nc`), with the chuck's form open, in a real window under Xvfb with software
# rendering. Needs what `scripts/setup-debian.sh --xvfb` installs. MACHINE_TAB_X and
# EDIT_X/EDIT_Y move the clicks if the layout changes.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -q --release -p ladder-studio
Xvfb :96 -screen 0 1280x800x24 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 2
DISPLAY=:96 LANG=en_US.UTF-8 ./target/release/ladder-studio --run projects/lathe-988ta.ldp \
  --nc projects/lathe-988ta.nc &
app=$!
sleep 8
wid=$(DISPLAY=:96 xdotool search --name "Ladder Studio" | head -1)
DISPLAY=:96 xdotool windowfocus --sync "$wid" mousemove "${MACHINE_TAB_X:-836}" 108 click 1
sleep 1
# The chuck's Edit button.
DISPLAY=:96 xdotool mousemove "${EDIT_X:-945}" "${EDIT_Y:-214}" click 1
sleep 2
DISPLAY=:96 import -window root /tmp/ladder-studio-machine.png
convert /tmp/ladder-studio-machine.png -crop 1280x800+0+0 +repage docs/machine.png
echo "docs/machine.png"
