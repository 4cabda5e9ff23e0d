// The scene engine's frames under the depth-mesh policy (core/scene/scene_animator.h; the mesh
// itself is core/scene/depth_mesh.h): the far part rendered alone and meshed at a build, the
// near part rendered every frame, both merged by depth. The rest of the frame loop is
// scene_animator.cpp.
#include <algorithm>
#include <limits>

#include "engine/wall_clock.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

using Clock = WallClock;

std::vector<char> complement(const std::vector<char>& part) {
  std::vector<char> other(part.size());
  for (std::size_t i = 0; i < part.size(); ++i) other[i] = !part[i];
  return other;
}

// The far render shown as it is (the frame of a build): its pixels showing a surface.
MeshDraw far_render_as_drawn(const Image& rendered, const DepthFrame& depth) {
  MeshDraw d;
  d.image = rendered;
  d.inverse_depth = depth.inverse_depth;
  d.source.assign(depth.polygon.size(), -1);
  for (std::size_t k = 0; k < d.source.size(); ++k) {
    if (depth.polygon[k] >= 0) d.source[k] = static_cast<int>(k);
  }
  return d;
}

}  // namespace

void SceneEngine::set_aside_polygons() {
  // 2: set aside and seen now (culled neither way), for mark_meshed.
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (!set_aside_[i]) continue;
    const bool seen = statuses_[i] != PolygonStatus::kBackFacing &&
                      statuses_[i] != PolygonStatus::kOutsideFrustum;
    set_aside_[i] = seen ? 2 : 1;
    if (seen) statuses_[i] = PolygonStatus::kOutsideFrustum;
  }
}

void SceneEngine::build_mesh(const ViewerPose* previous, const RigidMotion* motion,
                             const ViewerPose& current, AnimationFrame& report) {
  if (!(split_ > 0.0)) {
    split_ = settings_.mesh.split > 0.0
                 ? settings_.mesh.split
                 : automatic_split(render_depth(scene_, camera_, current, settings_.near));
    // Nothing seen at frame 0: no far part, every polygon rendered.
    if (!(split_ > 0.0)) split_ = std::numeric_limits<double>::infinity();
  }
  far_ = far_polygons(scene_, current, split_);
  set_aside_ = complement(far_);
  AnimationFrame pass;
  pass.frame = frame_index_;
  pass.layers = report.layers;
  render_frame(previous, motion, current, pass);
  rendered_frame_ = frame_;
  rendered_depth_ = render_depth(scene_, camera_, current, settings_.near, &far_);
  rendered_view_ = current;
  rendered_index_ = frame_index_;
  has_render_ = true;
  const DepthMeshSettings& m = settings_.mesh;
  mesh_ =
      build_depth_mesh(rendered_depth_, camera_, m.grid_px, m.max_depth_jump, m.drop_rubber_sheets);
  PolygonUpdate far_pass;
  far_pass.tally = pass;
  far_pass.add_to(report);
  report.visibility_ms += pass.visibility_ms;
  report.composite_ms += pass.composite_ms;
  report.hidden += pass.hidden;
  report.hidden_area_px += pass.hidden_area_px;
}

double SceneEngine::mesh_frame(const ViewerPose* previous, const RigidMotion* motion,
                               const ViewerPose& current, AnimationFrame& report) {
  const double travel =
      has_render_ ? glm::length(eye_position(current) - eye_position(rendered_view_)) : 0.0;
  const bool build =
      !has_render_ || cadence_frame() ||
      (settings_.mesh.rebuild_distance > 0.0 && travel > settings_.mesh.rebuild_distance);
  const auto t0 = Clock::now();
  if (build) build_mesh(previous, motion, current, report);
  // The near part, rendered and given its depth for the merge.
  set_aside_ = far_;
  render_frame(previous, motion, current, report);
  const std::vector<char> near = complement(far_);
  const DepthFrame near_depth = render_depth(scene_, camera_, current, settings_.near, &near);
  const RigidStep3 step = viewer_step(rendered_view_, current);
  const MeshDraw drawn = build ? far_render_as_drawn(rendered_frame_, rendered_depth_)
                               : draw_depth_mesh(mesh_, rendered_frame_, rendered_depth_, camera_,
                                                 step, settings_.near);
  MeshFrame f = merge_near_and_mesh(frame_, near_depth, drawn);
  report.update_ms += ms_since(t0);
  // The error of the mesh's pixels shown: a diagnostic, its time left out.
  const auto t1 = Clock::now();
  double max_error_px = 0.0;
  for (std::size_t d = 0; d < f.mesh_shown.size() && !build; ++d) {
    if (!f.mesh_shown[d]) continue;
    max_error_px = std::max(max_error_px, mesh_pixel_error(rendered_depth_, camera_, step,
                                                           drawn.source[d], static_cast<int>(d)));
  }
  double diagnostics_ms = ms_since(t1);
  const std::int64_t mesh_pixels = build ? 0 : drawn.pixels_written;
  const std::int64_t near_pixels = report.pixels_written;
  const double near_work = report.model_work;
  diagnostics_ms += show_splats(std::move(f.image), std::move(f.source), f.unreached, mesh_pixels,
                                mesh_pixels, max_error_px, current, report);
  report.pixels_written += near_pixels;
  report.model_work += near_work;
  mark_meshed(build, report);
  set_aside_.clear();
  // A frame merged as a whole: its one error is the frame's (the near layers' are exact).
  report.layer_reports.clear();
  return diagnostics_ms;
}

void SceneEngine::mark_meshed(bool built, AnimationFrame& report) {
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (set_aside_[i] != 2) continue;
    statuses_[i] = PolygonStatus::kAnimated;
    levels_[i] = built ? Level::kRerender : Level::kPerspective;
    if (!built) ++report.levels[static_cast<int>(Level::kPerspective)];
  }
}

}  // namespace oflab
