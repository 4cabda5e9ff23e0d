#!/usr/bin/env bash
# Builds the browser page (manual/web.md): core/ compiled to WebAssembly by Debian's
# emscripten through the CMake preset `web`, assembled into one self-contained
# build-web/oflab-web.html. Installs emscripten and chromium (for tests/web) when they are
# missing, and the world view's vtk.js and esbuild from npm (web/package-lock.json) when
# web/node_modules lacks them; nothing when all are present. Idempotent; prints the page's
# size.
set -euo pipefail
cd "$(dirname "$0")/.."

# emscripten and the header-only libraries for the module, chromium and node's acorn for
# the tests and emscripten's optimiser; npm for the world view's vtk.js (Debian's, unless an
# npm is on the path already, as with NodeSource's nodejs, which conflicts with Debian's npm).
bash tools/install-deps.sh --only emscripten chromium node-acorn libglm-dev nlohmann-json3-dev \
  libstb-dev cmake
command -v npm > /dev/null || bash tools/install-deps.sh --only npm

# vtk.js and esbuild at the versions and integrity hashes of web/package-lock.json, from the
# npm registry, into web/node_modules; again only when the lock file changed since.
if [[ ! -f web/node_modules/.package-lock.json || web/package-lock.json -nt web/node_modules/.package-lock.json ]]; then
  (cd web && npm ci --no-audit --no-fund --loglevel=error)
fi

# Debian's emscripten runs its JavaScript optimiser with the machine's node, which finds
# Debian's acorn module only through NODE_PATH.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# Debian's package ships emscripten's system libraries compiled (a frozen cache), so the
# first build compiles only oflab.
emcmake cmake --preset web > build-web-configure.log 2>&1 || {
  cat build-web-configure.log >&2
  exit 1
}
cmake --build build-web -j"$(nproc 2>/dev/null || echo 2)"

page=build-web/oflab-web.html
size=$(stat -c %s "$page")
limit=$((6 * 1024 * 1024))
echo "oflab: $page, $size bytes"
if [[ $size -gt $limit ]]; then
  echo "oflab: $page is larger than the 6 MB limit ($size > $limit bytes)" >&2
  exit 1
fi
