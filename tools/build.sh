#!/usr/bin/env bash
# Configures and builds oflab in build/ (Release). Extra arguments are build targets.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build-configure.log 2>&1 || {
  cat build-configure.log >&2
  exit 1
}
jobs=$(nproc 2>/dev/null || echo 2)
if [[ $# -gt 0 ]]; then
  for t in "$@"; do cmake --build build -j"$jobs" --target "$t"; done
else
  cmake --build build -j"$jobs"
fi
