#!/usr/bin/env bash
# Frame rates of every lesson and of the world view, as a lecturer's laptop would play them:
# `oflab --lesson NAME --presentation --size 1920 1080 --benchmark FRAMES` for each of the
# lessons `oflab-cli lesson list` names, then the world view, each on a virtual screen, and a
# Markdown table of frames per second and where the frame went (manual/gui.md, "Every lesson
# at 60 frames per second"). A benchmark, not a test: what it prints depends on the machine
# and on what else runs; run it on a machine that is otherwise idle.
#
# usage: tools/bench-lessons.sh [--frames N] [--threads T] [--busy-core] [--build DIR]
#   --frames N   frames per lesson (default 120)
#   --threads T  oflab's worker threads (default: the machine's cores)
#   --busy-core  keep one core busy with a spinning process meanwhile (the "another process
#                busy on one core" condition)
set -euo pipefail
cd "$(dirname "$0")/.."

frames=120
threads=""
busy=0
build=build
while [[ $# -gt 0 ]]; do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --threads) threads="--threads $2"; shift 2 ;;
    --busy-core) busy=1; shift ;;
    --build) build="$2"; shift 2 ;;
    *) echo "bench-lessons.sh: unknown option $1 (see the usage at the top of the script)" >&2; exit 2 ;;
  esac
done
for program in "$build/gui/oflab" "$build/analysis/oflab-cli"; do
  [[ -x "$program" ]] || { echo "bench-lessons.sh: $program is missing: build first (tools/build.sh)" >&2; exit 2; }
done

spinner=""
if [[ $busy == 1 ]]; then
  bash -c 'while :; do :; done' &
  spinner=$!
  trap 'kill $spinner 2>/dev/null || true' EXIT
fi

# One run: prints "| what | fps | engine | compared | exact | maps | drawing | text | other | total |".
measure() {
  local what="$1"
  shift
  local out
  # shellcheck disable=SC2086
  out=$(xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$build/gui/oflab" "$@" --presentation \
    --size 1920 1080 --benchmark "$frames" $threads 2>&1 | grep '^oflab: ')
  local fps stages
  fps=$(sed -n 's/.*: \([0-9.]*\) frames per second.*/\1/p' <<<"$out" | head -1)
  stages=$(sed -n 's/.*per frame ([^)]*): //p' <<<"$out" | head -1)
  printf '| %s | %.1f |' "$what" "$fps"
  for stage in engine "compared runs" "exact frame" maps drawing text other total; do
    printf ' %.1f |' "$(sed -n "s/.*$stage \([0-9.e+-]*\).*/\1/p" <<<"$stages" | head -1)"
  done
  echo
}

echo "| run | fps | engine | compared runs | exact frame | maps | drawing | text | other | total ms |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for lesson in $("$build/analysis/oflab-cli" lesson list | awk '{print $1}'); do
  measure "\`--lesson $lesson\`" --lesson "$lesson"
done
measure "\`--view world\`" --view world
