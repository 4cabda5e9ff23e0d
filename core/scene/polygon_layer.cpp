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

void SceneEngine::render_clipped(int index, const ViewerPose& view, AnimationFrame& tally) {
  PolygonLayer& s = *states_[index];
  const ScenePolygon& polygon = scene_.polygons[index];
  // The last frame's layer lends its memory to a lit content's render.
  Image memory = std::move(s.clipped_layer.layer.image);
  s.clipped_layer = PlacedLayer{};
  const LayerContent content = polygon_content(index);
  try {
    const PlanePose pose = polygon_pose(polygon, view, s.texture_size);
    s.clipped_layer = render_clipped_piece(camera_, content, scratch_textures_[polygon.texture],
                                           pose, texel_polygon(s.uv, s.texture_size), s.clipped,
                                           settings_.engine.sampling, &tally.pixels_written,
                                           &tally.model_work, &memory);
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
  const ReusePolicy& policy = *settings_.engine.policy;
  if (!policy.shares_budget && !policy.spreads_updates) return c;
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

void PolygonUpdate::add_to(AnimationFrame& report) const {
  for (int k = 0; k < kLevelCount; ++k) report.levels[k] += tally.levels[k];
  report.clipped += tally.clipped;
  RerenderCauses& c = report.rerender_causes;
  c.schedule += tally.rerender_causes.schedule;
  c.sampling_limit += tally.rerender_causes.sampling_limit;
  c.refused += tally.rerender_causes.refused;
  c.no_image += tally.rerender_causes.no_image;
  c.clipped += tally.rerender_causes.clipped;
  report.pixels_written += tally.pixels_written;
  report.pixels_not_warped += tally.pixels_not_warped;
  report.model_work += tally.model_work;
  report.update_ms += tally.update_ms;
  report.render_ms += tally.render_ms;
  report.max_photometric_error =
      std::max(report.max_photometric_error, tally.max_photometric_error);
  report.max_measured_error_px =
      std::max(report.max_measured_error_px, tally.max_measured_error_px);
}

void SceneEngine::starve(int index, PolygonUpdate& u) {
  statuses_[index] = PolygonStatus::kStarved;
  states_[index]->live = false;
  u.applied = true;
  u.level = Level::kRerender;
  u.starved = true;
}

void SceneEngine::update_polygon(int index, const ViewerPose& current, PolygonUpdate& u) {
  PolygonLayer& s = *states_[index];
  AnimationFrame& tally = u.tally;
  const auto t0 = Clock::now();
  s.updated = true;
  if (s.needs_clipping) {
    if (!s.allocated_shown) {
      s.clipped_layer = PlacedLayer{};
      starve(index, u);
      tally.update_ms += ms_since(t0);
      return;
    }
    render_clipped(index, current, tally);
    statuses_[index] = PolygonStatus::kClipped;
    levels_[index] = Level::kRerender;
    ++tally.levels[static_cast<int>(Level::kRerender)];
    ++tally.clipped;
    ++(scheduled_render_frame(frame_index_, *settings_.engine.policy)
           ? tally.rerender_causes.schedule
           : tally.rerender_causes.clipped);
    s.live = false;
    u.applied = true;
    u.level = Level::kRerender;
    u.ms = ms_since(t0);
    u.pixels = tally.pixels_written;
    u.starved = s.starved;
    tally.update_ms += u.ms;
    return;
  }
  s.animator->set_shown_pixels(settings_.engine.warp_area == WarpArea::kVisible ? &shown_pixels_
                                                                                : nullptr);
  const FrameReport r = s.animator->apply(s.allocated, s.allocated_shown);
  if (!s.allocated_shown && s.candidates.kind == LayerCandidates::Kind::kFresh) {
    starve(index, u);
    tally.update_ms += ms_since(t0);
    return;
  }
  if (r.level == Level::kRerender) {
    count_rerender_cause(s.candidates.kind == LayerCandidates::Kind::kFresh, r.note, tally);
  }
  s.live = true;
  statuses_[index] = PolygonStatus::kAnimated;
  levels_[index] = r.level;
  ++tally.levels[static_cast<int>(r.level)];
  tally.pixels_written += r.pixels_written;
  tally.pixels_not_warped += r.pixels_not_warped;
  tally.model_work += r.model_work;
  tally.render_ms += r.render_ms;
  tally.max_photometric_error = std::max(tally.max_photometric_error, r.photometric_error);
  u.applied = true;
  u.level = r.level;
  u.ms = r.time_ms;
  u.pixels = r.pixels_written;
  u.starved = s.starved;
  s.report = r;
  s.report.layer = index;
  if (r.visible)
    tally.max_measured_error_px = std::max(tally.max_measured_error_px, r.measured_error_px);
  tally.update_ms += ms_since(t0);
}

void SceneEngine::record_update(const PolygonUpdate& u, AnimationFrame& report) {
  u.add_to(report);
  if (u.applied) ledger_.applied(u.level, u.ms, u.pixels, u.starved);
}

void SceneEngine::count_rerender_cause(bool fresh, const std::string& note,
                                       AnimationFrame& tally) const {
  RerenderCauses& c = tally.rerender_causes;
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
