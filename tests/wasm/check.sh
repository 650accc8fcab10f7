#!/usr/bin/env bash
# The lab libraries under node: build tests/wasm with emscripten into WASM_DIR,
# run its lab_report with node and compare every number with NATIVE (the same
# program built natively). Usage: check.sh WASM_DIR NATIVE
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wasm_dir=$1
native=$2
# Debian's emscripten runs its optimizer with this image's node from its own modules.
export NODE_PATH=/usr/share/nodejs
if [ ! -f "$wasm_dir/build.ninja" ]; then
  emcmake cmake -S "$here" -B "$wasm_dir" -G Ninja >/dev/null
fi
cmake --build "$wasm_dir" -j "$(nproc)" | { grep -v '^ninja: no work to do' || true; }
node --no-experimental-fetch "$wasm_dir/lab_report.js" >"$wasm_dir/wasm.json"
"$native" >"$wasm_dir/native.json"
python3 "$here/compare.py" "$wasm_dir/native.json" "$wasm_dir/wasm.json"
