#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs every test: the full suite under a
# virtual screen (the GUI tests need one), then core/ and analysis/ (everything but the GUI)
# again under AddressSanitizer and UndefinedBehaviorSanitizer, then the readers' fuzz
# harnesses (clang, libFuzzer, ASan + UBSan) for a short bounded time each (`ctest -L fuzz`;
# longer campaigns: tools/fuzz.sh), and the browser page: built with emscripten and tested in
# headless Chromium (manual/web.md). Idempotent. manual/robustness.md, "Sanitizers".
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage prints its time, and the whole run its total, so the time a change costs shows.
run_start=$SECONDS
stage_start=$SECONDS
stage_done() {
  echo "oflab: stage '$1' took $((SECONDS - stage_start)) s (total $((SECONDS - run_start)) s)"
  stage_start=$SECONDS
}

bash tools/install-deps.sh
stage_done "install"
bash tools/build.sh
stage_done "build"

jobs=$(nproc 2>/dev/null || echo 2)

# As many tests at a time as the machine has cores: every GUI test opens its own window on the
# one virtual screen, and no two tests share a scratch folder. -noreset: by default the X
# server resets whenever its last client leaves, and a test that connects during that reset
# is dropped ("could not connect to display"); between two tests there is often no client.
xvfb-run -a -s "-screen 0 1600x1000x24 -noreset" \
  ctest --test-dir build --output-on-failure --timeout 600 -j"$jobs"
stage_done "tests"

# The browser page (manual/web.md): emscripten and chromium installed when missing, the page
# built, the golden outputs checked against this build's oflab-cli, then the page's self-test
# (its views' frame rates among it) and screenshots in headless Chromium. The page's benchmark
# (`node tests/web/web_test.js --bench`) is run by hand for manual/web.md's figures.
bash tools/build-web.sh
node tests/web/make_golden.js --check build/analysis/oflab-cli
node tests/web/web_test.js --out build-web/test-failures
stage_done "browser"

# The sanitized tree: OFLAB_HEADLESS (core, analysis, oflab-cli and their tests; no Qt, GUI
# or benchmarks), Debug (assertions on) compiled at -O1 with line tables only (-g1): the
# stack traces keep file and line, and the build and the tests take far less time than at
# -O0 -g. OFLAB_CORE_ONLY=OFF overrides what an older build-sanitize/ cached.
# The sanitized stage runs every test but two labels (ctest -LE below), left out because they
# cannot run under ASan:
# - soak: peak-memory comparisons of long runs; ASan's shadow memory and its quarantine of
#   freed blocks (256 MB) are what they would measure.
# - address-space-limit: the child's address space is capped at 2 GB, and an ASan binary
#   reserves terabytes of address space for its shadow memory at start.
# and whole runs that took most of the stage's time under the sanitizers, with their code run
# there by smaller tests (the main suite above runs them whole). Those are left out of the
# sanitized tree's test list by name (OFLAB_TEST_SKIP, cmake/OflabTestBatches.cmake: a regular
# expression of GoogleTest names), with the experiments' published-figure checks (ctest -E):
# - the golden scene-shifting run (Runs/Golden...train_window_scene_shifting, 166 s): the
#   other golden runs, the scene-shifting tests of core and analysis and `animate --mode
#   scene-shifting` cover it;
# - the quick experiments report (ExperimentsCommand.QuickRun..., 137 s): each experiment's
#   own tests and the report and chart tests cover it;
# - the published-figure checks of experiments 1 and 2 (Experiment1Published.*,
#   Experiment2Published.*, the one test analysis.experiments_published_figures; whole
#   experiment runs, several times longer under the sanitizers): numbers against the
#   dissertation's tables, whose code paths the engines' and experiments' smaller tests run
#   under the sanitizers;
# - the threshold study's simulated-observer statistics (StudySimulation.*, 8 s here, several
#   times that sanitized): the trial loop, methods, fit and bootstrap they run are run there
#   by the study's smaller tests and `study simulate`'s golden test;
# - the sweep over every engine claim of every lesson (Lab.EveryEngineClaimOfEveryLesson...,
#   11 s here): the lab and the claim kinds are run there by the session tests' single
#   lessons and steps;
# - the two whole four-cubes runs of the reprojection command tests (Reprojection.
#   DepthReprojectionHasHoles..., Reprojection.SummariesAndThePerFrameCsv..., 28 s here):
#   core's depth-reprojection tests run the splat, holes and fills there;
# - frame generation on every shipped scene and viewer script
#   (FrameGenerationCommand.RunsOnEveryShippedSceneAndViewerScript, 4 s of CPU here): 24 runs
#   of whole 640 x 480 frames; the core tests of frame generation and
#   FrameGenerationCommand.CompareRows... run its code under the sanitizers;
# - the longest whole-motion sweeps (28 to 83 s each sanitized, together about a third of the
#   stage's test time): the stabilization plane matched frame for frame over a whole run
#   (Reprojection.AutomaticStabilizationPlane...), the default books on every shipped scene
#   (Scenes.DefaultPolicyBooksHold...), the golden four-cubes budget and compound runs, every
#   script in every mode (AnimateCommand.AllScriptsRunInAllModes), every listed policy as an
#   animate mode (PoliciesCommand.EveryListedName...) and every scene with every viewer script
#   (AnimateScene.EveryShippedSceneRuns...): each repeats, over more frames or more inputs,
#   code that smaller sanitized tests of the same engines, policies and scenes run;
# - ten more whole runs of 8-20 s each sanitized (about 60 s of the stage on 2 cores): the
#   lab's loop over every source (Lab.TheLoopIsTheSourcesLength), the study kinds' sessions
#   (Lab.TheStudyKindsMeasure...), the simulated run through the study's pictures
#   (TrialRunner.ASimulatedRun...), four cubes compound in every mode, the impostor cubes on
#   one and two threads, scene shifting's JSON summary, every policy on a scene, and three
#   compare runs of scenes (CompareCommand.SceneRows..., .ContentAndQuality...,
#   FrameGenerationCommand.CompareRows...): their code runs sanitized in the smaller tests of
#   the lab, the study, the engines and compare.
sanitize_skip='Golden.AnimateOutputsAreUnchanged/train_window_scene_shifting|ExperimentsCommand.QuickRunWritesAReportThatParsesWithEveryChart|StudySimulation\.|Lab.EveryEngineClaimOfEveryLesson|Reprojection.DepthReprojectionHasHoles|Reprojection.SummariesAndThePerFrameCsv|FrameGenerationCommand.RunsOnEveryShippedSceneAndViewerScript|Reprojection.AutomaticStabilizationPlaneOfOnePlane|Scenes.DefaultPolicyBooksHoldOnEveryShippedScene|Golden.AnimateOutputsAreUnchanged/four_cubes_(budget|compound)|AnimateCommand.AllScriptsRunInAllModes|PoliciesCommand.EveryListedNameIsAnAnimateMode|AnimateScene.EveryShippedSceneRunsWithEveryShippedViewerScript|Lab.TheLoopIsTheSourcesLength|Lab.TheStudyKindsMeasureTheStudyTheStateOpens|TrialRunner.ASimulatedRunThroughThePicturesIsTheHeadlessSimulation|AnimateScene.FourCubesCompoundRunsInEveryModeWithTheContractedSummary|GoldenThreads.ImpostorCubesAreTheSameOnOneAndTwoThreads|AnimateSceneShifting.JsonSummaryHasEveryFieldOfTheOtherModes|PolicyRuns.EveryPolicyPlaysTheSameFramesOfAScene|CompareCommand.SceneRowsAreAnimateRunAloneAtTheScenesContentQuality|CompareCommand.ContentAndQualityReachEveryPolicyAndModelWorkMatchesAnimate|FrameGenerationCommand.CompareRowsCarryHolesInpaintingPsnrSsimAndLatency'
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DCMAKE_C_FLAGS_DEBUG="-O1 -g1" -DOFLAB_CORE_ONLY=OFF -DOFLAB_HEADLESS=ON \
  -DOFLAB_SANITIZE=ON -DOFLAB_TEST_SKIP="$sanitize_skip" > build-sanitize-configure.log 2>&1 || {
  cat build-sanitize-configure.log >&2
  exit 1
}
cmake --build build-sanitize -j"$jobs"
# The analysis tests draw charts and render with VTK, so they run under the virtual screen.
# They run as many at a time as the machine has cores: under the sanitizers they take about
# twice as long as their build, and none shares a scratch folder with another.
# intercept_tls_get_addr=0: GCC 12's sanitizer runtime takes a dynamic TLS block (Mesa's
# driver, loaded with dlopen, has them) that happens to start 16 bytes past a page boundary
# for a glibc older than 2.25 and reads two words before it as the block's bounds; the
# leak checker's tracer then dies at exit with "Tracer caught signal 11" after a test passed
# (rarely: it depends on where malloc puts the block). Without the interception the leak
# checker does not scan dynamic TLS blocks, which hold none of this project's allocations.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 \
  xvfb-run -a -s "-screen 0 1600x1000x24 -noreset" \
  ctest --test-dir build-sanitize --output-on-failure --timeout 1200 -j"$jobs" \
  -LE 'soak|address-space-limit' -E 'analysis\.experiments_published_figures'
stage_done "sanitizers"

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DOFLAB_FUZZ=ON -DOFLAB_BUILD_TESTS=OFF \
  -DOFLAB_FUZZ_SECONDS=5 > build-fuzz-configure.log 2>&1 || {
  cat build-fuzz-configure.log >&2
  exit 1
}
cmake --build build-fuzz -j"$jobs"
ctest --test-dir build-fuzz -L fuzz --output-on-failure -j"$jobs"
stage_done "fuzz"
