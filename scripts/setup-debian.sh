#!/usr/bin/env bash
# Installs the system packages Ladder Studio needs on a fresh Debian machine (run as root, or
# it uses sudo). Rust itself comes from rustup (https://rustup.rs): the release rust-toolchain.toml pins.
#   scripts/setup-debian.sh          build tools and the libraries the editor's window needs
#   scripts/setup-debian.sh --build  build tools only (enough for the tests, which need no display)
#   scripts/setup-debian.sh --xvfb   the window libraries plus a virtual X server and the tools
#                                    scripts/screenshot.sh uses (a real window, no screen)
#   scripts/setup-debian.sh --bench  build tools plus valgrind, for instruction counts
#                                    (`bench --instructions`, `cargo bench --bench native`)
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# A C compiler and pkg-config for crates that build C code.
PACKAGES="build-essential pkg-config"
if [ "${1:-}" != "--build" ] && [ "${1:-}" != "--bench" ]; then
  # The window: OpenGL/Vulkan through Mesa (software rendering works too), X11 and Wayland
  # input, and fontconfig.
  PACKAGES="$PACKAGES libgl1-mesa-dri libegl1 libxkbcommon-x11-0 libxcursor1 libxrandr2 libxi6 libx11-xcb1 libwayland-client0 fontconfig"
fi
if [ "${1:-}" = "--bench" ]; then
  PACKAGES="$PACKAGES valgrind"
fi
if [ "${1:-}" = "--xvfb" ]; then
  # Software rendering in a virtual X server, and the tools to drive and capture it.
  PACKAGES="$PACKAGES xvfb xdotool imagemagick"
fi
missing=""
for p in $PACKAGES; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  $SUDO apt-get update
  $SUDO apt-get install -y --no-install-recommends $missing
fi
# rust-toolchain.toml pins Rust 1.95.0. Where rustup has that release only as "stable" (a
# machine set up before the pin), the name is linked to it instead of downloading it again.
if command -v rustup >/dev/null 2>&1 && ! rustup toolchain list | grep -q '^1\.95\.0-'; then
  stable="$(rustup run stable rustc --version 2>/dev/null || true)"
  case "$stable" in
    "rustc 1.95.0 "*)
      host="$(rustup run stable rustc -vV | sed -n 's/^host: //p')"
      ln -s "$(rustup run stable rustc --print sysroot)" "$(rustup show home)/toolchains/1.95.0-$host"
      ;;
  esac
fi
