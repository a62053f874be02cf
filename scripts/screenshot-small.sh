#!/usr/bin/env bash
# Takes docs/small-f3.png and docs/small-version.png: the editor in a 900×600 window under Xvfb
# with software rendering, in Chinese, with the F3 dialog open on the sample's level 1, then
# on the version page. Needs what `scripts/setup-debian.sh --xvfb` installs.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -q --release -p ladder-studio
Xvfb :97 -screen 0 900x600x24 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 2
DISPLAY=:97 ./target/release/ladder-studio --lang zh projects/lathe-988ta.ldp &
app=$!
sleep 8
wid=$(DISPLAY=:97 xdotool search --name "Ladder Studio" | head -1)
DISPLAY=:97 xdotool windowmove --sync "$wid" 0 0 windowsize --sync "$wid" 900 600
sleep 2
# F3 on the first cell of level 1, the timer chosen from the instruction line.
DISPLAY=:97 xdotool windowfocus --sync "$wid" key F3
sleep 2
DISPLAY=:97 xdotool type --delay 40 "TMRB T0000 DT0004 X0000.0"
sleep 2
DISPLAY=:97 import -window root docs/small-f3.png
DISPLAY=:97 xdotool key Escape
sleep 1
# The version page: the last entry of the project tree, scrolled into view.
DISPLAY=:97 xdotool mousemove 100 350 click --repeat 8 --delay 80 5
sleep 1
DISPLAY=:97 xdotool mousemove "${VERSION_X:-60}" "${VERSION_Y:-408}" click 1
sleep 2
DISPLAY=:97 import -window root "${PROBE:-docs/small-version.png}"
echo "docs/small-f3.png docs/small-version.png"
