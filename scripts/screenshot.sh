#!/usr/bin/env bash
# Takes docs/screenshot.png: the editor on the sample project in a real window under Xvfb with
# software rendering, after F9. Needs what `scripts/setup-debian.sh --xvfb` installs.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -q --release -p ladder-studio
Xvfb :99 -screen 0 1400x900x24 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 2
DISPLAY=:99 ./target/release/ladder-studio --lang zh projects/lathe-988ta.ldp &
app=$!
sleep 8
wid=$(DISPLAY=:99 xdotool search --name "Ladder Studio" | head -1)
DISPLAY=:99 xdotool windowfocus --sync "$wid" key F9
sleep 2
DISPLAY=:99 import -window root /tmp/ladder-studio-screen.png
convert /tmp/ladder-studio-screen.png -crop 1280x800+0+0 +repage docs/screenshot.png
echo "docs/screenshot.png"
