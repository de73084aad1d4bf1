#!/usr/bin/env bash
# The browser build. Installs what it needs from Debian when missing (emscripten 3.1.6 with its
# prebuilt sysroot, binaryen, nodejs), then builds the command line into build-web/:
#   build-web/cardemo.js + cardemo.wasm, run as `node build-web/cardemo.js ARGS`
# with the real file system and the native binary's output and exit status (the commands that
# need no window; scripts/web-test.sh checks them against a native build).
#
# Usage: scripts/web.sh [--serve]
#   --serve   will serve the page (build-web/site) on 127.0.0.1:8000; the page comes with src/web.
# Environment: CARDEMO_WEB_BUILD_DIR (default build-web in the repository).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${CARDEMO_WEB_BUILD_DIR:-$root/build-web}"
case "${1:-}" in
  "") ;;
  --serve)
    echo "scripts/web.sh --serve: the page is not built yet (it comes with src/web)" >&2
    exit 2
    ;;
  *) echo "usage: scripts/web.sh [--serve]" >&2; exit 2 ;;
esac

"$root/scripts/ensure-packages.sh" emscripten binaryen nodejs
# npm: puppeteer-core for the page's browser test goes here (pinned by a committed
# package-lock.json, installed with `npm ci`), with the page.

# shellcheck source=scripts/lib.sh
. "$root/scripts/lib.sh"
# emscripten's JavaScript tools load Debian's node modules (acorn) from /usr/share/nodejs, which
# Debian's node searches by itself and other builds of node (NodeSource's) do not.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# Debian's emscripten uses its prebuilt, frozen cache (/usr/share/emscripten/cache: the sysroot and
# every system library), which it only reads, so no EM_CACHE is needed, as root or not.
# RelWithDebInfo at -O2 without -g, as CI's native tree: asserts stay on.
emcmake cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_WERROR=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 "${cardemo_launcher[@]}" >/dev/null
cmake --build "$build" --target cardemo -j"$(nproc)"
echo "built $build/cardemo.js: node $build/cardemo.js --help"
