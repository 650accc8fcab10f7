#!/usr/bin/env bash
# The web page's test (check.py) from a build directory: the site built (the `web`
# target), puppeteer-core installed from tests/web/package-lock.json into
# BUILD/web-test (once, and again when the lock changes), then every check.
# Usage: run.sh BUILD [--random N]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1
shift
cmake --build "$build" --target web | { grep -v '^ninja: no work to do' || true; }
modules=$build/web-test
if [ ! -d "$modules/node_modules/puppeteer-core" ] || [ "$here/package-lock.json" -nt "$modules/package-lock.json" ]; then
  mkdir -p "$modules"
  cp "$here/package.json" "$here/package-lock.json" "$modules/"
  (cd "$modules" && npm ci --no-audit --no-fund --loglevel=error)
fi
RIGID_NODE_MODULES=$modules/node_modules python3 "$here/check.py" "$build/web" "$build/labs" "$@"
