#!/usr/bin/env bash
# Builds the Debian package: installs what is missing, builds (tools/build.sh) and runs
# CPack, giving build/packages/oflab_<version>_amd64.deb. Install it with
# `sudo apt install ./build/packages/oflab_*_amd64.deb`. See manual/install.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh
(cd build && cpack -G DEB > cpack.log 2>&1) || { cat build/cpack.log >&2; exit 1; }
ls build/packages/oflab_*_amd64.deb
