#!/usr/bin/env bash
# Regenerates projects/stress-5000.ldp: a generated program of about 5000 steps (seed 1) for
# the benchmarks. The same command always gives the same file.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cargo run -q -p ladder-engine --example gen_il -- 5000 > "$tmp/stress.il"
cargo run -q -p ladder-studio -- import-il "$tmp/stress.il" -o projects/stress-5000.ldp
rm -f projects/stress-5000.ldp.bak
