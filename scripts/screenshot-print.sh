#!/usr/bin/env bash
# Takes docs/print-preview.png: the print preview of the sample lathe project in a real window
# under Xvfb with software rendering (File → Print preview, the first page of level 2 at 100 %). Needs what
# `scripts/setup-debian.sh --xvfb` installs. MENU_Y is the height of "Print preview" in the
# open File menu, NEXT_X and ZOOM_X where ▶ and + are in the preview's bar.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -q --release -p ladder-studio
Xvfb :97 -screen 0 1400x900x24 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 2
DISPLAY=:97 ./target/release/ladder-studio --lang zh projects/lathe-988ta.ldp &
app=$!
sleep 8
wid=$(DISPLAY=:97 xdotool search --name "Ladder Studio" | head -1)
DISPLAY=:97 xdotool windowfocus --sync "$wid" mousemove 20 12 click 1
sleep 1
DISPLAY=:97 xdotool mousemove 60 "${MENU_Y:-264}" click 1
sleep 2
# Two pages on (▶) to the first page of level 2; the preview opens at fit width.
for x in "${NEXT_X:-140}" "${NEXT_X:-140}"; do
  DISPLAY=:97 xdotool mousemove "$x" 67 click 1
  sleep 0.7
done
sleep 1
DISPLAY=:97 import -window root /tmp/ladder-studio-print.png
convert /tmp/ladder-studio-print.png -crop 1280x800+0+0 +repage docs/print-preview.png
echo "docs/print-preview.png"
