#!/usr/bin/env bash
# Regenerates the screenshots of manual/gui.md and manual/lessons.md with
# `oflab --screenshot`, on a virtual screen. Usage: tools/make-screenshots.sh [path/to/oflab]
# (default build/gui/oflab; build it first, e.g. with tools/build.sh oflab).
set -euo pipefail
cd "$(dirname "$0")/.."
oflab=${1:-build/gui/oflab}
out=manual/images
if [[ ! -x "$oflab" ]]; then
  echo "make-screenshots: $oflab not found; build it first (tools/build.sh oflab)" >&2
  exit 1
fi
mkdir -p "$out"

shot() {  # shot NAME ARGS...: one screenshot into manual/images/NAME.png
  local name=$1
  shift
  xvfb-run -a -s "-screen 0 ${screen:-1600x1000}x24 -noreset" "$oflab" --screenshot "$out/$name.png" --force "$@" \
    2> >(grep -v 'XDG_RUNTIME_DIR' >&2)
}

shot window-demo --frames 0
shot flow-demo --view flow --frames 0
shot flow-whole-image --view flow --frames 0 --flow-draw arrows,texture
shot flow-first-order --view flow --frames 0 --flow-show first-order \
  --flow-draw arrows,streamlines,zoom
shot flow-second-order-wheel --view flow --frames 0 --flow-show second-order \
  --flow-draw arrows,wheel,zoom,texture
shot flow-residual --view flow --frames 0 --flow-show exact-minus-homography
shot flow-affine-residual --view flow --frames 0 --flow-show exact-minus-affine \
  --flow-draw arrows,zoom,texture
shot flow-script --view flow --script zoom-rotation --frames 20
shot basis-taylor --view basis --basis taylor --frames 0
shot basis-waxman-ullman --view basis --basis waxman-ullman --frames 0
shot basis-planar --view basis --basis planar --frames 0
shot lesson-flow-of-a-plane --lesson flow-of-a-plane --frames 0
shot lesson-basis-deformations --lesson basis-deformations --presentation --frames 12
shot animation-demo --view animation --frames 10
shot animation-difference --view animation --mode affine --animation-show difference --frames 10
shot animation-scene --view animation --scene four-cubes --script circle --frames 40
shot animation-scene-shifting --view animation --scene train-window --source scene-shifting \
  --frames 29
shot analysis-demo --view analysis --frames 40
shot analysis-presentation --view analysis --presentation --size 1920 1080 --frames 40
# The classroom's projector: the comparison layout at 1920 x 1080, normal and presentation.
screen=1920x1200 shot lesson-affine-vs-perspective --lesson affine-vs-perspective \
  --size 1920 1080 --frames 40
screen=1920x1200 shot animation-comparison --lesson affine-vs-perspective --view animation \
  --size 1920 1080 --frames 40
screen=1920x1200 shot animation-comparison-presentation --lesson affine-vs-perspective \
  --view animation --presentation --size 1920 1080 --frames 40
# The analysis view overlaying four compared policies' histories, at 1920 x 1080.
screen=1920x1200 shot analysis-comparison --script loop --animation-show comparison \
  --compare perspective,dissertation,talisman,rerender --view analysis --size 1920 1080 \
  --frames 150
screen=1920x1200 shot lesson-flow-vs-talisman --lesson flow-vs-talisman --size 1920 1080 --frames 40
screen=1920x1200 shot lesson-when-reuse-pays --lesson when-reuse-pays --presentation --size 1920 1080 \
  --frames 90
shot lesson-why-errors-accumulate --lesson why-errors-accumulate --frames 60
screen=1920x1200 shot lesson-how-much-error-can-you-see --lesson how-much-error-can-you-see \
  --size 1920 1080 --frames 50
shot lesson-occlusion --lesson occlusion --frames 20
screen=1920x1200 shot lesson-guessing-the-next-frame --lesson guessing-the-next-frame \
  --presentation --size 1920 1080 --frames 3
screen=1920x1200 shot lesson-spreading-the-work --lesson spreading-the-work \
  --presentation --size 1920 1080 --frames 12
screen=1920x1200 shot lesson-warping-what-shows --lesson warping-what-shows \
  --presentation --size 1920 1080 --frames 12
screen=1920x1200 shot lesson-shrinking-without-shimmering --lesson shrinking-without-shimmering \
  --presentation --size 1920 1080 --frames 40
shot slices --view slices --frames 10
# The window as a projector shows it, normal and presentation mode, at 1920 x 1080.
for look in normal presentation; do
  flag=$([[ $look == presentation ]] && echo --presentation || true)
  screen=1920x1200 shot window-1080-$look --size 1920 1080 --frames 30 $flag
  screen=1920x1200 shot flow-1080-$look --view flow --size 1920 1080 --frames 30 \
    --flow-draw arrows,streamlines,texture,zoom $flag
  screen=1920x1200 shot basis-1080-$look --view basis --size 1920 1080 --frames 30 $flag
  screen=1920x1200 shot slices-1080-$look --view slices --size 1920 1080 --frames 10 $flag
  screen=1920x1200 shot basis-explorer-1080-$look --view basis --basis-explorer --whole-window \
    --size 1920 1080 --frames 0 $flag
done
# The basis explorer's lessons (their steps are pictured below with the other lessons').
screen=1920x1200 shot lesson-eight-numbers-two-worlds --lesson eight-numbers-two-worlds \
  --size 1920 1080 --frames 0
screen=1920x1200 shot lesson-what-each-term-does --lesson what-each-term-does --presentation \
  --size 1920 1080 --frames 0
# The world view (the cause) at 1920 x 1080, normal and presentation, the cause-and-effect
# layout and its lesson.
screen=1920x1200 shot world-demo --view world --size 1920 1080 --frames 10
screen=1920x1200 shot world-demo-presentation --view world --presentation --size 1920 1080 \
  --frames 10
screen=1920x1200 shot world-scene --view world --scene four-cubes --script circle \
  --size 1920 1080 --frames 40
screen=1920x1200 shot cause-and-effect --cause-and-effect --size 1920 1080 --frames 10
screen=1920x1200 shot lesson-where-the-flow-comes-from --lesson where-the-flow-comes-from \
  --size 1920 1080 --frames 0
# The threshold study's window: its set-up page, and its results after a simulated observer
# (threshold 0.8 px) answered the class study.
study_trials=$(mktemp -d)
shot study-setup --study class --size 1200 800
shot study-results --study class --study-simulate 0.8 --study-seed 3 \
  --study-csv "$study_trials/trials.csv" --size 1200 800
rm -rf "$study_trials"
# Each step of each lesson, as the lesson-claims check leaves the window after measuring
# that step's claims (manual/lessons.md shows them).
steps=$(mktemp -d)
trap 'rm -rf "$steps"' EXIT
xvfb-run -a -s "-screen 0 1920x1200x24 -noreset" "$oflab" --check-lesson all --size 1920 1080 \
  --step-shots "$steps" 2> >(grep -v 'XDG_RUNTIME_DIR' >&2) | grep -v '^oflab: wrote' |
  tail -n 1
cp "$steps"/lesson-*-step-*.png "$out"/
python3 tools/lesson-steps.py
echo "make-screenshots: wrote $(ls "$out"/*.png | wc -l) images to $out"
