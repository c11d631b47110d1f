#!/usr/bin/env bash
# The explorer page (docs/explorer.md) built and tested: scripts/build-web.sh,
# then web/test/explorer.test.mjs in Debian's headless Chromium through
# puppeteer-core (npm, the version pinned in web/test/package-lock.json; it
# downloads no browser), checked against the native CLI.
#   scripts/test-web.sh [AAPAT_BINARY] [--bench] [--screenshot PNG]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=$root/build/release/aapat
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  aapat=$1
  shift
fi
[ -x "$aapat" ] || { echo "test-web: $aapat is not built (cmake --build --preset release)"; exit 1; }
command -v chromium >/dev/null || { echo "test-web: chromium is not installed (scripts/install-deps.sh)"; exit 1; }
"$root/scripts/build-web.sh" >/dev/null
(cd "$root/web/test" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
node "$root/web/test/explorer.test.mjs" "$root/build/web/aapat-explorer.html" "$aapat" \
  "$root/build/web/web/aapat-module.js" "$@"
