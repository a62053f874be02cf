#!/usr/bin/env bash
# Takes docs/online.png and docs/online-cnc.png: the editor started online on the sample lathe
# (`--run --nc`), running its part program in a real window under Xvfb with software
# rendering; the second shows the CNC page. Needs what `scripts/setup-debian.sh --xvfb`
# installs.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -q --release -p ladder-studio
Xvfb :98 -screen 0 1400x900x24 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 2
DISPLAY=:98 LANG=zh_CN.UTF-8 ./target/release/ladder-studio --run projects/lathe-988ta.ldp \
  --nc projects/lathe-988ta.nc &
app=$!
# Cycle start is pressed at 0.24 s of virtual time; at 6 s the tool is cutting.
sleep 8
DISPLAY=:98 import -window root /tmp/ladder-studio-online.png
convert /tmp/ladder-studio-online.png -crop 1280x800+0+0 +repage docs/online.png
wid=$(DISPLAY=:98 xdotool search --name "Ladder Studio" | head -1)
# The CNC page: the third tab of the online panel, at the panel's default width (the
# Chinese toolbar takes two rows at 1280 px, so the tabs are at y 131).
DISPLAY=:98 xdotool windowfocus --sync "$wid" mousemove "${CNC_TAB_X:-895}" "${CNC_TAB_Y:-131}" click 1
sleep 2
DISPLAY=:98 import -window root /tmp/ladder-studio-online-cnc.png
convert /tmp/ladder-studio-online-cnc.png -crop 1280x800+0+0 +repage docs/online-cnc.png
echo "docs/online.png docs/online-cnc.png"
