#!/usr/bin/env bash
# Rebuilds projects/lathe-988ta.ldp from its sources in projects/src/ (the program as IL,
# the symbol table, the data tables and the message table as CSV).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run -q -p ladder-engine --example build_sample -- projects/src/lathe-988ta projects/lathe-988ta.ldp
