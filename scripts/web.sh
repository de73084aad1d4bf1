#!/usr/bin/env bash
# The browser build. Installs what it needs when missing (Debian: emscripten 3.1.6 with its
# prebuilt sysroot, binaryen, nodejs, npm, chromium; npm: puppeteer-core for the page's test, pinned
# by tests/web/package-lock.json, `npm ci` into build-web/npm), then builds into build-web/:
#   build-web/cardemo.js + cardemo.wasm, run as `node build-web/cardemo.js ARGS` with the real file
#     system and the native binary's output and exit status (scripts/web-test.sh checks them);
#   build-web/site/: the game as a page (index.html; scripts/web-page-test.sh checks it).
#
# Usage: scripts/web.sh [--serve]
#   --serve   then serves build-web/site on http://127.0.0.1:8000/ until stopped (Ctrl-C).
# Environment: CARDEMO_WEB_BUILD_DIR (default build-web in the repository).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${CARDEMO_WEB_BUILD_DIR:-$root/build-web}"
serve=0
case "${1:-}" in
  "") ;;
  --serve) serve=1 ;;
  *) echo "usage: scripts/web.sh [--serve]" >&2; exit 2 ;;
esac

"$root/scripts/ensure-packages.sh" emscripten binaryen nodejs chromium
# Debian's nodejs comes without npm; other builds of node (NodeSource's) bring their own, which
# Debian's npm package conflicts with.
command -v npm >/dev/null || "$root/scripts/ensure-packages.sh" npm
# puppeteer-core, as pinned; reinstalled only when the lock file changed.
npm_dir="$build/npm"
if ! cmp -s "$root/tests/web/package-lock.json" "$npm_dir/package-lock.json" ||
  [ ! -d "$npm_dir/node_modules/puppeteer-core" ]; then
  mkdir -p "$npm_dir"
  cp "$root/tests/web/package.json" "$root/tests/web/package-lock.json" "$npm_dir/"
  (cd "$npm_dir" && npm ci --no-audit --no-fund --loglevel=error)
fi

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
cmake --build "$build" --target cardemo cardemo_page -j"$(nproc)"
echo "built $build/cardemo.js: node $build/cardemo.js --help"
echo "built $build/site: scripts/web.sh --serve, then open http://127.0.0.1:8000/"
if [ "$serve" -eq 1 ]; then
  echo "serving $build/site on http://127.0.0.1:8000/ (Ctrl-C stops)"
  exec python3 -m http.server 8000 --bind 127.0.0.1 --directory "$build/site"
fi
