// What a scene costs a renderer, estimated from the inputs alone before anything is
// allocated: the memory of its layers and textures, and the detail of its lit contents (the
// impostors' facade windows, the shaded polygons' samples), each against its limit in
// core/flow/limits.h (kSceneEngineMemory, kSceneImpostorWindows, kShadedSamples). The scene
// engine (core/scene/scene_animator.h) and scene shifting (core/scene_shifting/
// scene_shifting_renderer.h) refuse a scene over a limit with the phrases below.
#pragma once

#include <string>

#include "flow/camera.h"
#include "scene/scene.h"

namespace oflab {

// The bytes of every polygon's copy of its texture, 4 a pixel (a polygon whose texture index
// is out of range counts none): what a scene's engines, one a polygon, copy.
double polygon_texture_copy_bytes(const Scene& scene);

// The bytes a scene engine may hold for `scene` seen through `camera` when every polygon is
// visible, estimated from the inputs alone before anything is allocated: per polygon its
// engine's copy of its texture and kLayerImagesPerPolygon layer images (the displayed layer
// and the warp's scratch), each as large as a polygon drawn whole may grow: the camera's
// image grown by the guard band (guard_band image sizes, >= 0) on every side, so
// (1 + 2 guard_band)^2 camera images (4 at the default 0.5); and per texture the scene's
// image and the engine's scratch copy; 4 bytes a pixel.
constexpr int kLayerImagesPerPolygon = 2;
double scene_memory_bytes(const Scene& scene, const Camera& camera, double guard_band);
// "" when scene_memory_bytes is within limits::kSceneEngineMemory; otherwise one phrase
// naming the figure and the limit: "the scene's 1000 polygons at 1280 x 720 px may hold
// 28375 MiB of layers and textures, more than 768 MiB (the scene engine memory limit)".
std::string scene_memory_problem(const Scene& scene, const Camera& camera, double guard_band);
// The bytes `engines` engines of one run may hold together, each playing `scene` through
// `camera` (scene_memory_bytes each): the model's animator, its exact baseline and each
// compared policy's animator (session/player/policy_comparison.h). The limits multiply:
// engines x polygons x layer images x grown frame.
double run_memory_bytes(const Scene& scene, const Camera& camera, double guard_band, int engines);
// "" when run_memory_bytes is within limits::kRunMemory; otherwise one phrase naming the
// figure and the limit: "4 engines of the scene's 9 polygons at 1280 x 720 px may hold
// 3828 MiB of layers and textures, more than 1536 MiB (the run memory limit)".
std::string run_memory_problem(const Scene& scene, const Camera& camera, double guard_band,
                               int engines);
// The phrase of scene_memory_problem for any renderer of a scene: "" when `bytes` is within
// limits::kSceneEngineMemory; otherwise "<subject> may hold N MiB of <what>, more than
// 768 MiB (the scene engine memory limit)", N the bytes in MiB rounded up.
std::string scene_memory_limit_problem(double bytes, const std::string& subject,
                                       const std::string& what);

// The facade windows the scene's impostor polygons draw when all of them re-render at
// content quality `quality` (1 .. kMaxContentQuality): (1 + q) storeys by (1 + 2q) bays per
// impostor polygon, as facade_faces builds them (core/content/layer_content.h).
double scene_impostor_windows(const Scene& scene, int quality);
// "" when scene_impostor_windows is within limits::kSceneImpostorWindows and the shaded
// polygons' samples (shaded_samples of a camera-sized layer each, core/content/
// layer_content.h) within limits::kShadedSamples; otherwise one phrase naming the figure
// and the limit: "the scene's 7 impostor polygons at quality 32 draw 15015 facade windows a
// frame, more than 4096 (the scene impostor detail limit)".
std::string scene_content_problem(const Scene& scene, const Camera& camera, int quality);

}  // namespace oflab
