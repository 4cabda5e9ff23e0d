#!/usr/bin/env bash
# A fuzz campaign of SECONDS in all (default 600): builds the readers' libFuzzer harnesses
# (fuzz/, clang, ASan + UBSan) in build-fuzz/ and runs them one after the other, each for an
# equal share of SECONDS (at least one second), growing the corpus
# in build-fuzz/fuzz/corpus/. Prints each harness's executions and what it found; crashing
# inputs are written as build-fuzz/fuzz/crash-TARGET-*. Exit code 1 when any harness failed.
#   bash tools/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "tools/fuzz.sh: SECONDS must be a whole number of seconds, got '$seconds'" >&2
  exit 2
fi
harnesses=$(grep -c '^set(fuzz_.*_seeds ' fuzz/CMakeLists.txt)
per_harness=$(( seconds / harnesses > 0 ? seconds / harnesses : 1 ))
echo "tools/fuzz.sh: $harnesses harnesses, $per_harness s each"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DOFLAB_FUZZ=ON -DOFLAB_BUILD_TESTS=OFF \
  -DOFLAB_FUZZ_SECONDS="$per_harness" > build-fuzz-configure.log 2>&1 || {
  cat build-fuzz-configure.log >&2
  exit 1
}
cmake --build build-fuzz -j"$(nproc 2>/dev/null || echo 2)"
status=0
ctest --test-dir build-fuzz -L fuzz -E regressions --output-on-failure -V \
  > build-fuzz-campaign.log 2>&1 || status=1
# Per harness: "Done N runs in S second(s)" from libFuzzer's final line.
grep -E "Test command:|Done [0-9]+ runs in|stat::number_of_executed_units|SUMMARY|Test *#" \
  build-fuzz-campaign.log | sed -E 's/^[0-9]+: //' || true
echo "tools/fuzz.sh: full log in build-fuzz-campaign.log"
exit "$status"
