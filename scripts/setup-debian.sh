#!/usr/bin/env bash
# Installs the system packages Ladder Studio needs on a fresh Debian machine (run as root, or
# it uses sudo). Rust itself comes from rustup (https://rustup.rs), version 1.95 or newer.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# A C compiler and pkg-config for crates that build C code.
PACKAGES="build-essential pkg-config"
missing=""
for p in $PACKAGES; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  $SUDO apt-get update
  $SUDO apt-get install -y --no-install-recommends $missing
fi
