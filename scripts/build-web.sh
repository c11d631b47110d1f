#!/usr/bin/env bash
# Builds the explorer page, build/web/aapat-explorer.html (docs/explorer.md):
# the library compiled to WebAssembly with Debian's emscripten (installed here
# when missing), and one self-contained file that opens with no server and no
# network. Prints the page's path.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v em++ >/dev/null 2>&1; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends emscripten
fi
# Debian's emscripten runs its JavaScript tools with Debian's node modules.
export NODE_PATH=/usr/share/nodejs
jobs=$(nproc 2>/dev/null || echo 2)
cmake --preset web >/dev/null
cmake --build --preset web -j "$jobs"
/usr/bin/python3 web/assemble_page.py build/web/web/aapat-module.js web/page build/web/aapat-explorer.html
echo "build/web/aapat-explorer.html"
