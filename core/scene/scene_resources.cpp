// What a scene costs a renderer, estimated before anything is allocated
// (core/scene/scene_resources.h).
#include "scene/scene_resources.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "content/layer_content.h"
#include "flow/limits.h"

namespace oflab {

double polygon_texture_copy_bytes(const Scene& scene) {
  double bytes = 0.0;
  for (const ScenePolygon& p : scene.polygons) {
    const bool known = p.texture >= 0 && p.texture < static_cast<int>(scene.textures.size());
    if (known) bytes += 4.0 * scene.textures[static_cast<std::size_t>(p.texture)].pixel_count();
  }
  return bytes;
}

double scene_memory_bytes(const Scene& scene, const Camera& camera, double guard_band) {
  double bytes = 0.0;
  for (const Image& t : scene.textures) bytes += 2.0 * 4.0 * t.pixel_count();
  const double grown = (1.0 + 2.0 * guard_band) * (1.0 + 2.0 * guard_band);
  const double layers = kLayerImagesPerPolygon * grown * 4.0 * camera.width * camera.height;
  return bytes + layers * scene.polygons.size() + polygon_texture_copy_bytes(scene);
}

namespace {

// "<subject> may hold N MiB of <what>, more than M MiB (the <limit> limit)", or "" when
// `bytes` is within `limit` (MiB), N the bytes in MiB rounded up.
std::string memory_limit_problem(const Limit& limit, double bytes, const std::string& subject,
                                 const std::string& what) {
  const double mib = bytes / (1024.0 * 1024.0);
  if (limit.allows(mib)) return "";
  std::ostringstream text;
  text << subject << " may hold " << static_cast<long>(std::ceil(mib)) << " MiB of " << what
       << ", more than " << limit.maximum << " MiB (the " << limit.what << " limit)";
  return text.str();
}

std::string polygons_subject(const Scene& scene, const Camera& camera) {
  std::ostringstream subject;
  subject << "the scene's " << scene.polygons.size() << " polygons at " << camera.width << " x "
          << camera.height << " px";
  return subject.str();
}

}  // namespace

std::string scene_memory_limit_problem(double bytes, const std::string& subject,
                                       const std::string& what) {
  return memory_limit_problem(limits::kSceneEngineMemory, bytes, subject, what);
}

std::string scene_memory_problem(const Scene& scene, const Camera& camera, double guard_band) {
  return scene_memory_limit_problem(scene_memory_bytes(scene, camera, guard_band),
                                    polygons_subject(scene, camera), "layers and textures");
}

double run_memory_bytes(const Scene& scene, const Camera& camera, double guard_band, int engines) {
  return engines * scene_memory_bytes(scene, camera, guard_band);
}

std::string run_memory_problem(const Scene& scene, const Camera& camera, double guard_band,
                               int engines) {
  return memory_limit_problem(
      limits::kRunMemory, run_memory_bytes(scene, camera, guard_band, engines),
      std::to_string(engines) + " engines of " + polygons_subject(scene, camera),
      "layers and textures");
}

double scene_impostor_windows(const Scene& scene, int quality) {
  const double q = quality;
  double windows = 0.0;
  for (const ScenePolygon& p : scene.polygons) {
    if (p.content == ContentKind::kImpostor) windows += (1.0 + q) * (1.0 + 2.0 * q);
  }
  return windows;
}

std::string scene_content_problem(const Scene& scene, const Camera& camera, int quality) {
  const auto count = [&](ContentKind kind) {
    return std::count_if(scene.polygons.begin(), scene.polygons.end(),
                         [&](const auto& p) { return p.content == kind; });
  };
  LayerContent shaded;
  shaded.kind = ContentKind::kShaded;
  shaded.quality = quality;
  const auto shaded_polygons = count(ContentKind::kShaded);
  const double samples = static_cast<double>(shaded_polygons) *
                         shaded_samples(shaded, static_cast<double>(camera.width) * camera.height);
  std::ostringstream subject;
  subject << "the scene's " << shaded_polygons << " shaded polygons at quality " << quality
          << " on a " << camera.width << " x " << camera.height << " px camera";
  if (const std::string problem = shaded_samples_problem(samples, subject.str());
      !problem.empty()) {
    return problem;
  }
  const double windows = scene_impostor_windows(scene, quality);
  const Limit& limit = limits::kSceneImpostorWindows;
  if (limit.allows(windows)) return "";
  std::ostringstream text;
  text << "the scene's " << count(ContentKind::kImpostor) << " impostor polygons at quality "
       << quality << " draw " << static_cast<long>(windows) << " facade windows a frame, more than "
       << limit.maximum << " (the " << limit.what << " limit)";
  return text.str();
}

}  // namespace oflab
