#!/usr/bin/env bash
# The page (build-web/site) in headless Debian chromium, driven by puppeteer-core
# (tests/web/page-test.js says what it checks), served by python3's http.server on a free local
# port for the run. scripts/web.sh builds the page and installs chromium and puppeteer-core.
#
# Usage: scripts/web-page-test.sh NATIVE_CARDEMO [WEB_BUILD_DIR]   (default: build-web)
# Writes WEB_BUILD_DIR/page-test/page.png, the screenshot.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: scripts/web-page-test.sh NATIVE_CARDEMO [WEB_BUILD_DIR]" >&2; exit 2; }
native=$(realpath "$1")
build=$(realpath "${2:-$root/build-web}")
[ -f "$build/site/index.html" ] || { echo "web-page-test: no $build/site (scripts/web.sh builds it)" >&2; exit 2; }
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$build/site" >"$build/page-test-server.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" \
    2>/dev/null && break
  sleep 0.1
done
NODE_PATH="$build/npm/node_modules" node "$root/tests/web/page-test.js" "http://127.0.0.1:$port" \
  "$build/site" "$native" "$build/page-test"
