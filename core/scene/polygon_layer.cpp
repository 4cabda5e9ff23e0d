// The scene engine's per-polygon layers (core/scene/polygon_layer.h): each polygon's state,
// and the steps of a frame the scene engine (core/scene/scene_animator.h) takes polygon by
// polygon: the measure phase (its engine's candidates, or a clipped polygon's fresh render),
// the allocation over the polygons, and the update (its engine's apply at the allocated
// level, or its clipped exact render, or nothing when starved). The frame loop that calls
// them, culling, visibility and compositing, is core/scene/scene_animator.cpp.
#include "scene/polygon_layer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "engine/wall_clock.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

using Clock = WallClock;

glm::ivec2 texture_size(const Image& texture) { return {texture.width(), texture.height()}; }

// True in a frame whose re-renders are all the schedule's: frame 0, and every frame in which
// a per-pixel depth warp renders (it renders every polygon afresh, clipped or not).
bool scheduled_render_frame(int frame_index, const ReusePolicy& policy) {
  return frame_index == 0 || policy.frame_warp == FrameWarp::kPerPixelDepth;
}

}  // namespace

const char* polygon_status_name(PolygonStatus status) {
  switch (status) {
    case PolygonStatus::kBackFacing:
      return "back-facing";
    case PolygonStatus::kOutsideFrustum:
      return "outside-frustum";
    case PolygonStatus::kHidden:
      return "hidden";
    case PolygonStatus::kAnimated:
      return "animated";
    case PolygonStatus::kClipped:
      return "clipped";
    case PolygonStatus::kStarved:
      return "starved";
  }
  return "animated";
}

std::vector<std::unique_ptr<PolygonLayer>> make_polygon_layers(const Scene& scene) {
  std::vector<std::unique_ptr<PolygonLayer>> layers;
  std::vector<int> opaque_texture(scene.textures.size(), -1);  // -1: not looked at yet
  for (const ScenePolygon& polygon : scene.polygons) {
    auto state = std::make_unique<PolygonLayer>();
    state->world_vertices = polygon_vertices(polygon);
    state->uv = polygon_outline(polygon);
    const Image& texture = scene.textures[polygon.texture];
    state->texture_size = texture_size(texture);
    // Rectangles of one texture share the answer; only outlines need a look of their own.
    if (polygon.outline.empty()) {
      if (opaque_texture[polygon.texture] < 0) {
        opaque_texture[polygon.texture] = polygon_is_opaque(polygon, texture);
      }
      state->opaque = opaque_texture[polygon.texture] == 1;
    } else {
      state->opaque = polygon_is_opaque(polygon, texture);
    }
    layers.push_back(std::move(state));
  }
  return layers;
}

void SceneEngine::render_clipped(int index, const ViewerPose& view, AnimationFrame& report) {
  PolygonLayer& s = *states_[index];
  const ScenePolygon& polygon = scene_.polygons[index];
  s.clipped_layer = PlacedLayer{};
  const LayerContent content = polygon_content(index);
  try {
    const PlanePose pose = polygon_pose(polygon, view, s.texture_size);
    s.clipped_layer =
        render_clipped_piece(camera_, content, scratch_textures_[polygon.texture], pose,
                             texel_polygon(s.uv, s.texture_size), s.clipped,
                             settings_.engine.sampling, &report.pixels_written, &report.model_work);
  } catch (const std::invalid_argument&) {
    // A sliver beyond the warps' fixed-point range: drawn as nothing this frame.
  }
}

PlaneEngine& SceneEngine::polygon_engine(int index) {
  PolygonLayer& s = *states_[index];
  if (!s.animator) {
    const ScenePolygon& polygon = scene_.polygons[index];
    EngineSettings engine = settings_.engine;
    engine.content = polygon_content(index);
    s.animator = std::make_unique<PlaneEngine>(
        camera_, make_layer(scene_.textures[polygon.texture], texel_polygon(s.uv, s.texture_size)),
        engine);
  }
  return *s.animator;
}

LayerCandidates SceneEngine::clipped_candidates(int index) {
  LayerCandidates c;
  c.kind = LayerCandidates::Kind::kFresh;
  if (!settings_.engine.policy->shares_budget) return c;
  const ConvexPolygon& region = polygon_region(index);
  c.pixels[static_cast<int>(Level::kRerender)] = box_pixels(region);
  if (!region.empty()) {
    const BoundingBox b = region.bounds();
    c.extent_px = std::hypot(b.x_max - b.x_min, b.y_max - b.y_min);
  }
  return c;
}

void SceneEngine::measure_polygons(const ViewerPose* previous, const RigidMotion* motion,
                                   const ViewerPose& current, AnimationFrame& report) {
  const auto t0 = Clock::now();
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (statuses_[i] == PolygonStatus::kBackFacing ||
        statuses_[i] == PolygonStatus::kOutsideFrustum) {
      continue;
    }
    PolygonLayer& s = *states_[i];
    const int index = static_cast<int>(i);
    if (s.needs_clipping) {
      s.candidates = clipped_candidates(index);
      continue;
    }
    const ScenePolygon& polygon = scene_.polygons[i];
    PlaneEngine& animator = polygon_engine(index);
    if (uses_frame_plane_) animator.set_frame_plane(frame_plane_);
    const PlanePose pose = polygon_pose(polygon, current, s.texture_size);
    s.candidates = s.live && previous && motion
                       ? animator.measure_advance(polygon_pose(polygon, *previous, s.texture_size),
                                                  *motion, pose)
                       : animator.measure_start(pose);
  }
  report.update_ms += ms_since(t0);
}

void SceneEngine::allocate_polygons(AnimationFrame& report) {
  std::vector<int> measured;
  std::vector<LayerCandidates> candidates;
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (statuses_[i] == PolygonStatus::kBackFacing ||
        statuses_[i] == PolygonStatus::kOutsideFrustum) {
      continue;
    }
    measured.push_back(static_cast<int>(i));
    candidates.push_back(states_[i]->candidates);
  }
  const FrameAllocation a = ledger_.allocate(report.frame, candidates);
  for (std::size_t k = 0; k < measured.size(); ++k) {
    PolygonLayer& s = *states_[measured[k]];
    s.allocated = a.levels[k];
    s.allocated_shown = a.shown[k] != 0;
    s.starved = a.starved[k] != 0;
  }
}

void SceneEngine::starve(int index) {
  statuses_[index] = PolygonStatus::kStarved;
  states_[index]->live = false;
  ledger_.applied(Level::kRerender, 0.0, 0, true);
}

void SceneEngine::update_polygon(int index, const ViewerPose& current, AnimationFrame& report) {
  PolygonLayer& s = *states_[index];
  const auto t0 = Clock::now();
  s.updated = true;
  if (s.needs_clipping) {
    if (!s.allocated_shown) {
      s.clipped_layer = PlacedLayer{};
      starve(index);
      report.update_ms += ms_since(t0);
      return;
    }
    const std::int64_t before = report.pixels_written;
    render_clipped(index, current, report);
    statuses_[index] = PolygonStatus::kClipped;
    levels_[index] = Level::kRerender;
    ++report.levels[static_cast<int>(Level::kRerender)];
    ++report.clipped;
    ++(scheduled_render_frame(frame_index_, *settings_.engine.policy)
           ? report.rerender_causes.schedule
           : report.rerender_causes.clipped);
    s.live = false;
    ledger_.applied(Level::kRerender, ms_since(t0), report.pixels_written - before, s.starved);
    report.update_ms += ms_since(t0);
    return;
  }
  const FrameReport r = s.animator->apply(s.allocated, s.allocated_shown);
  if (!s.allocated_shown && s.candidates.kind == LayerCandidates::Kind::kFresh) {
    starve(index);
    report.update_ms += ms_since(t0);
    return;
  }
  if (r.level == Level::kRerender) {
    count_rerender_cause(s.candidates.kind == LayerCandidates::Kind::kFresh, r.note, report);
  }
  s.live = true;
  statuses_[index] = PolygonStatus::kAnimated;
  levels_[index] = r.level;
  ++report.levels[static_cast<int>(r.level)];
  report.pixels_written += r.pixels_written;
  report.model_work += r.model_work;
  report.render_ms += r.render_ms;
  report.max_photometric_error = std::max(report.max_photometric_error, r.photometric_error);
  ledger_.applied(r.level, r.time_ms, r.pixels_written, s.starved);
  s.report = r;
  if (r.visible)
    report.max_measured_error_px = std::max(report.max_measured_error_px, r.measured_error_px);
  report.update_ms += ms_since(t0);
}

void SceneEngine::count_rerender_cause(bool fresh, const std::string& note,
                                       AnimationFrame& report) const {
  RerenderCauses& c = report.rerender_causes;
  const auto starts = [&](const char* prefix) { return note.rfind(prefix, 0) == 0; };
  if (fresh) {
    ++(scheduled_render_frame(frame_index_, *settings_.engine.policy) ? c.schedule : c.no_image);
  } else if (starts("sampling limit")) {
    ++c.sampling_limit;
  } else if (starts("re-rendered after a refusal")) {
    ++c.refused;
  } else {
    ++c.schedule;
  }
}

LayerContent SceneEngine::polygon_content(int polygon) const {
  LayerContent content = settings_.engine.content;
  content.kind = scene_.polygons[polygon].content;
  return content;
}

}  // namespace oflab
