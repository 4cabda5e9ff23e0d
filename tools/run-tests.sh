#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs every test: the full suite under a
# virtual screen (the GUI tests need one), then core/ again under AddressSanitizer and
# UndefinedBehaviorSanitizer, then the readers' fuzz harnesses (clang, libFuzzer, ASan +
# UBSan) for a short bounded time each (`ctest -L fuzz`; longer campaigns: tools/fuzz.sh).
# Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh

xvfb-run -a -s "-screen 0 1600x1000x24" \
  ctest --test-dir build --output-on-failure --timeout 600

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DOFLAB_CORE_ONLY=ON \
  -DOFLAB_SANITIZE=ON > build-sanitize-configure.log 2>&1 || {
  cat build-sanitize-configure.log >&2
  exit 1
}
cmake --build build-sanitize -j"$(nproc 2>/dev/null || echo 2)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure --timeout 600

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DOFLAB_FUZZ=ON -DOFLAB_BUILD_TESTS=OFF \
  -DOFLAB_FUZZ_SECONDS=15 > build-fuzz-configure.log 2>&1 || {
  cat build-fuzz-configure.log >&2
  exit 1
}
cmake --build build-fuzz -j"$(nproc 2>/dev/null || echo 2)"
ctest --test-dir build-fuzz -L fuzz --output-on-failure
