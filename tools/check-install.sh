#!/usr/bin/env bash
# Installs a built tree into a temporary prefix and uses the install as a user would:
# builds and runs the consumer project tests/install/ against find_package(oflab), and runs
# the installed oflab-cli from / on the shipped `loop` script, writing its report into a
# temporary directory, and imports the installed Python module when it was built.
# Usage: bash tools/check-install.sh [BUILD_DIR] (default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log" >&2; exit 1; }
for f in bin/oflab bin/oflab-cli share/oflab/datasets/scripts/loop.json share/oflab/manual/install.md \
         include/oflab/flow/flow_field.h lib/cmake/oflab/oflabConfig.cmake; do
  [[ -e "$prefix/$f" ]] || { echo "check-install: $prefix/$f is missing" >&2; exit 1; }
done
# The browser page is installed when tools/build-web.sh has built it (manual/web.md).
page=$(sed -n 's/^OFLAB_WEB_PAGE:[A-Z]*=//p' "$build/CMakeCache.txt")
if [[ -n "$page" && -f "$page" ]]; then
  cmp -s "$page" "$prefix/share/oflab/web/oflab-web.html" ||
    { echo "check-install: $prefix/share/oflab/web/oflab-web.html is not $page" >&2; exit 1; }
fi

# The consumer: configure, build and run against the installed package only.
cmake -S tests/install -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; exit 1; }
cmake --build "$work/consumer" > "$work/consumer-build.log" 2>&1 ||
  { cat "$work/consumer-build.log" >&2; exit 1; }
"$work/consumer/oflab_consumer"

# The installed CLI from /: it finds `loop` beside itself, not in the source tree.
(cd / && env -u OFLAB_DATASETS "$prefix/bin/oflab-cli" animate --script loop --frames 40 \
   --out "$work/report" --quiet)
for f in frames.csv summary.json; do
  [[ -s "$work/report/$f" ]] || { echo "check-install: the run wrote no $f" >&2; exit 1; }
done
rows=$(($(wc -l < "$work/report/frames.csv") - 1))
[[ $rows -eq 40 ]] || { echo "check-install: frames.csv has $rows rows, expected 40" >&2; exit 1; }
# A script that exists only in the install: found, so the installed datasets are the ones used.
cp "$prefix/share/oflab/datasets/scripts/zoom.json" "$prefix/share/oflab/datasets/scripts/installed-only.json"
(cd / && env -u OFLAB_DATASETS "$prefix/bin/oflab-cli" animate --script installed-only --frames 2 \
   > /dev/null) || { echo "check-install: the installed oflab-cli does not use its installed datasets" >&2; exit 1; }
# The installed Python module, when it was built (manual/python.md): imported from the
# install (not the build tree), it plays the shipped rotation script from the installed
# datasets.
pydir=$(sed -n 's/^OFLAB_INSTALL_PYTHONDIR:[A-Z]*=//p' "$build/CMakeCache.txt")
python=$(sed -n 's/^OFLAB_PYTHON_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")
if [[ -n "$pydir" ]]; then
  frames=$(cd / && PYTHONPATH="$prefix/$pydir" OFLAB_DATASETS="$prefix/share/oflab/datasets" \
    "${python:-python3}" -c "import oflab; assert oflab.__file__.startswith('$prefix'), oflab.__file__
print(oflab.run('rotation', 'perspective', frames=4, repeat_timing=1).summary['frames'])") ||
    { echo "check-install: the installed Python module does not run" >&2; exit 1; }
  [[ "$frames" == 4 ]] || { echo "check-install: the installed module played $frames frames, not 4" >&2; exit 1; }
fi
echo "check-install: the consumer and the installed oflab-cli work from $prefix"
