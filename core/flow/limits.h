// One rule per value: every bounded number a person can give oflab (on the command line, in a
// session, script or scene file, or in a control of the window) has its range stated here
// once. The CLI, the file readers and the GUI's controls all check a value with its Limit, so
// a value refused in one place is refused everywhere with the same words. It lives in core's
// lowest folder so that every folder of core (content's quality, the engine's thresholds, the
// scene's memory) may check with it. Plain C++17.
#pragma once

#include <string>

namespace oflab {

// A closed range [minimum, maximum] of one kind of value, with its unit.
struct Limit {
  const char* what;  // what the value is, for messages: "threshold"
  const char* unit;  // its unit as printed after a number: "px", "u/s"; "" for none
  double minimum;
  double maximum;
  bool whole = false;  // only whole numbers are allowed

  // True when `value` is finite, inside [minimum, maximum] and, for a whole-number limit,
  // whole.
  bool allows(double value) const;
  // "" when allows(value); otherwise one phrase naming the value and the allowed range,
  // e.g. "1e+06 is outside 0..100 px" or "2.5 is not a whole number (1..256)".
  std::string problem(double value) const;
  // The range as printed: "0..100 px".
  std::string range_text() const;
};

// The limits. Units: px are image pixels, u world units, s seconds.
namespace limits {
// Per-term error thresholds of the engine (core/engine/engine.h EngineSettings), px.
inline constexpr Limit kThreshold{"threshold", "px", 0.0, 100.0};
// Camera: focal length in pixels per unit of X/Z, and image size in pixels.
inline constexpr Limit kFocalLength{"focal length", "px", 1.0, 100000.0};
inline constexpr Limit kImageSize{"image size", "px", 2.0, 8192.0, true};
// The plane's pose: the depth Z of its centre (the GUI's Distance), turn and tilt of its
// normal (gui/models/scene_parameters.h), and its width and height.
inline constexpr Limit kDistance{"distance", "u", 0.01, 10000.0};
inline constexpr Limit kTurn{"turn", "deg", -180.0, 180.0};
inline constexpr Limit kTilt{"tilt", "deg", -90.0, 90.0};
inline constexpr Limit kPlaneSize{"plane size", "u", 1e-6, 10000.0};
// Each component of the plane's velocity V and angular velocity Omega.
inline constexpr Limit kVelocity{"velocity", "u/s", -1000.0, 1000.0};
inline constexpr Limit kAngularVelocity{"angular velocity", "rad/s", -100.0, 100.0};
// Each of the eight planar flow coefficients typed in (`oflab-cli explain`): tx, ty in px/s,
// J in 1/s, px, py in 1/(px s), so no one unit.
inline constexpr Limit kFlowCoefficient{"flow coefficient", "", -1e6, 1e6};
// The basis explorer's eight planar-basis terms (session/basis/basis_explorer.h), by order:
// translation (tx, ty) in px/s, first order (scale, squash, shear, rotation) in 1/s,
// perspective (px, py) in 1/(px s).
inline constexpr Limit kTranslationRate{"translation rate", "px/s", -10000.0, 10000.0};
inline constexpr Limit kFirstOrderRate{"first-order rate", "1/s", -100.0, 100.0};
inline constexpr Limit kPerspectiveRate{"perspective rate", "1/(px s)", -0.1, 0.1};
// Frames to play or render in one run, and frames of a benchmark.
inline constexpr Limit kFrameCount{"frame count", "frames", 0.0, 1000000.0, true};
// Frames of what must play at least one (`oflab-cli animate --frames N`, a segment of a
// motion or viewer script): kFrameCount's maximum, which also caps a whole script.
inline constexpr Limit kPlayedFrames{"frame count", "frames", 1.0, kFrameCount.maximum, true};
// Frames the window plays before a screenshot (`oflab --frames N`) or times (`oflab
// --benchmark N`): each is drawn in every view it touches (about 36 ms a frame in the
// animation view on the development machine), so the largest run takes about 40 s; a longer
// run is `oflab-cli animate`'s (kFrameCount).
inline constexpr Limit kWindowFrames{"frame count", "frames", 0.0, 1000.0, true};
inline constexpr Limit kWindowPlayedFrames{"frame count", "frames", 1.0, kWindowFrames.maximum,
                                           true};
// The budget policy's frame budget (core/engine/budget.h): pixels or milliseconds per frame.
inline constexpr Limit kBudgetPixels{"frame budget", "px", 0.0, 1e9};
inline constexpr Limit kBudgetMs{"frame budget", "ms", 0.0, 1e9};
// A fixed cadence (core/engine/reuse_policy.h Schedule::kCadence): render every N-th frame and
// warp the frames between (`--cadence N`); 1 renders every frame, 8 is one render in eight.
inline constexpr Limit kCadence{"cadence", "frames", 1.0, 8.0, true};
// Each coordinate of a given stabilization plane's point and normal (EngineSettings::
// stabilization), world units.
inline constexpr Limit kStabilizationPlane{"stabilization plane coordinate", "u", -10000.0,
                                           10000.0};
// The hierarchical image cache (core/scene/cache_nodes.h CacheSettings): the angular
// threshold of a node's bounding-box corners, degrees; the grouping rule's polygons per
// cluster; the safety sphere's radius, world units (0: the automatic, conservative radius).
inline constexpr Limit kCacheAngle{"cache angle", "deg", 0.001, 10.0};
inline constexpr Limit kCacheNodePolygons{"node polygons", "polygons", 1.0, 10000.0, true};
inline constexpr Limit kSafetyRadius{"safety radius", "u", 0.0, 10000.0};
// The textured depth mesh (core/scene/depth_mesh.h DepthMeshSettings): its grid spacing,
// pixels; the split depth and the viewer travel that rebuilds it, world units (0: automatic,
// and the cadence alone); the relative depth jump of a rubber sheet.
inline constexpr Limit kMeshGrid{"mesh grid", "px", 1.0, 64.0, true};
inline constexpr Limit kMeshSplit{"mesh split", "u", 0.0, 10000.0};
inline constexpr Limit kMeshRebuild{"mesh rebuild distance", "u", 0.0, 10000.0};
inline constexpr Limit kMeshJump{"mesh depth jump", "", 0.001, 1000.0};
// Layer content quality: samples per pixel of shaded content, detail of impostors
// (core/content/layer_content.h, whose kMaxContentQuality is this maximum).
inline constexpr Limit kContentQuality{"content quality", "", 1.0, 256.0, true};
// Plays of a motion script back to back (`oflab-cli animate --repeat N`); the run's frames
// must also stay within an int.
inline constexpr Limit kRepeat{"repeat count", "plays", 1.0, 1000000.0, true};
// Timed passes of a run after its warm-up (`--repeat-timing N`).
inline constexpr Limit kTimingPasses{"timed passes", "passes", 1.0, 1000.0, true};
// Frame rate of a video file (`--fps N`).
inline constexpr Limit kVideoFps{"frame rate", "fps", 1.0, 60.0, true};
// Pixels of a video file's frame (analysis/formats/video_file.h VideoWriter): x264 keeps
// dozens of frames in its look-ahead, so 60 frames of 4096 x 2304 px ran out of the 2 GB
// address space (x264's malloc failed at 1.5 GB resident) while 2560 x 1440 px peaked at
// 706 MB (manual/robustness.md); 2560 x 1440 (and 1920 x 1080) is the largest.
inline constexpr Limit kVideoFramePixels{"video frame", "pixels", 4.0, 2560.0 * 1440.0, true};
// Cubes of a generated grid-of-cubes scene (`oflab-cli make-scene --cubes N`).
inline constexpr Limit kSceneCubes{"cube count", "cubes", 1.0, 20000.0, true};
// The flow field written for ParaView (`oflab-cli flow --vtk`, analysis/formats/vtk_export.h):
// the spacing of its grid, and the grid points one file may hold (13 doubles a point, so
// at most 109 MB of arrays; an 8192 x 8192 image needs a step of 9 or more).
inline constexpr Limit kVtkGridStep{"grid step", "px", 1.0, 1024.0, true};
inline constexpr Limit kVtkGridPoints{"grid points", "points", 1.0, 1048576.0, true};
// What the engines of one run may hold together (core/scene/scene_resources.h
// run_memory_bytes: engines x polygons x layers grown by the guard band, and the textures),
// MiB: the model's animator, its exact baseline and each compared policy's animator
// (session/player/policy_comparison.h). Within it, and the program's own 60 to 300 MB, a run
// stays within the 2 GB promise (manual/robustness.md).
inline constexpr Limit kRunMemory{"run memory", "MiB", 0.0, 1536.0};
// What one scene engine may hold (scene_memory_bytes: its layers and texture copies with every
// polygon visible and grown into the guard band), MiB: half of kRunMemory, as every run holds
// two (the animator and its exact baseline).
inline constexpr Limit kSceneEngineMemory{"scene engine memory", "MiB", 0.0,
                                          kRunMemory.maximum / 2.0};
// What a scene's impostor polygons may draw in one frame when all of them re-render
// (core/scene/scene_resources.h scene_impostor_windows): facade windows, each a few lit faces.
// A frame's time grows with it; at the limit about 10 s (manual/robustness.md). The street
// (seven impostor facades) admits quality 16.
inline constexpr Limit kSceneImpostorWindows{"scene impostor detail", "windows", 0.0, 4096.0};
// What shaded content may sample in one frame when every shaded layer re-renders
// (core/content/layer_content.h shaded_samples): quality samples per pixel of a camera-sized
// layer, summed over a scene's shaded polygons. At about 112 ns a sample (oflab-bench
// content/shaded/cost-per-unit) a frame at the limit takes about 15 s (manual/robustness.md).
inline constexpr Limit kShadedSamples{"shaded samples", "samples", 0.0, 134217728.0};
// What one lesson file may ask (session/lessons/lessons.h): its steps, and the frames it plays
// in all (its "play", and each step's "frame", reached by playing forward, and "play"). A
// window plays a lesson's frames one at a time with every view drawn (about 36 ms a frame on
// the development machine), so the largest lesson plays within about 40 s; the shipped lessons
// have at most 6 steps and play at most 492 frames.
inline constexpr Limit kLessonSteps{"lesson steps", "steps", 0.0, 64.0, true};
inline constexpr Limit kLessonFrames{"lesson frames", "frames", 0.0, 1000.0, true};
// The animation view's zoom on top of zoom-to-fit (1 fits the plane's whole loop).
inline constexpr Limit kZoom{"zoom", "x", 0.25, 8.0};
// Live play rate, frames per second.
inline constexpr Limit kPlayRate{"play rate", "fps", 1.0, 240.0, true};
}  // namespace limits

}  // namespace oflab
