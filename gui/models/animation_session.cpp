#include "models/animation_session.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/composite.h"

namespace oflab {

int AnimationSource::frame_count() const {
  return static_cast<int>(is_scene() ? viewer.frames.size() : plane_script.frames.size());
}

std::string animation_source_problem(const AnimationSource& source) {
  if (source.frame_count() == 0) return "the script has no frames";
  if (const char* problem = camera_problem(source.camera()); problem && *problem) {
    return std::string("camera: ") + problem;
  }
  if (!source.is_scene()) {
    if (source.plane_texture.empty()) return "the plane has no texture";
    return "";
  }
  if (source.scene->polygons.empty()) return "the scene has no polygons";
  for (const ScenePolygon& polygon : source.scene->polygons) {
    const PolygonProblem p = scene_polygon_problem(*source.scene, polygon);
    if (!p.field.empty()) return "polygon '" + polygon.name + "': " + p.field + ": " + p.message;
  }
  return "";
}

AnimationSession::AnimationSession(AnimationSource source, const EngineSettings& settings)
    : source_(std::move(source)), settings_(settings) {
  if (source_.is_scene()) {
    reference_scene_ = source_.scene;
  } else {
    reference_scene_ = std::make_shared<const Scene>(
        plane_as_scene(source_.plane_script.frames.front().pose, source_.plane_texture));
  }
  restart();
}

AnimationSession::~AnimationSession() = default;

void AnimationSession::restart() {
  history_.clear();
  frame_ = 0;
  if (source_.is_scene()) {
    SceneSettings scene_settings;
    scene_settings.engine = settings_;
    scene_ = std::make_unique<SceneAnimator>(*source_.scene, source_.camera(), scene_settings);
    record_scene(scene_->start(source_.viewer.frames.front().pose));
  } else {
    plane_ = std::make_unique<PlaneAnimator>(source_.camera(), make_layer(source_.plane_texture),
                                             settings_);
    record_plane(plane_->start(source_.plane_script.frames.front().pose));
  }
}

void AnimationSession::step() {
  const size_t k = static_cast<size_t>(frame_);
  ++frame_;
  if (source_.is_scene()) {
    const auto& frames = source_.viewer.frames;
    record_scene(scene_->advance(frames[k].pose, frames[k].motion, frames[k + 1].pose));
  } else {
    const auto& frames = source_.plane_script.frames;
    record_plane(plane_->advance(frames[k].pose, frames[k].motion, frames[k + 1].pose));
  }
}

void AnimationSession::seek(int frame) {
  frame = std::clamp(frame, 0, frame_count() - 1);
  if (frame < frame_) restart();
  while (frame_ < frame) step();
}

void AnimationSession::record_plane(const FrameReport& report) {
  FrameRecord r;
  r.frame = frame_;
  r.time_ms = report.time_ms;
  if (report.visible) {
    r.levels[static_cast<size_t>(report.level)] = 1;
    r.drawn = 1;
    r.approximated_percent = report.level == Level::kRerender ? 0.0 : 100.0;
  }
  r.measured_error_px = report.measured_error_px;
  r.plane = report;
  r.has_books = true;
  history_.push_back(r);
  const PlacedLayer& shown = plane_->displayed();
  plane_frame_ = Image(source_.camera().width, source_.camera().height);
  if (!shown.layer.empty()) {
    composite_over(plane_frame_, shown.layer, shown.offset_x, shown.offset_y);
  }
}

void AnimationSession::record_scene(const AnimationFrame& report) {
  FrameRecord r;
  r.frame = frame_;
  r.time_ms = report.time_ms;
  r.levels = report.levels;
  r.drawn = report.drawn();
  const int rerendered = report.levels[static_cast<size_t>(Level::kRerender)];
  r.approximated_percent = r.drawn > 0 ? 100.0 * (r.drawn - rerendered) / r.drawn : 0.0;
  r.measured_error_px =
      r.drawn > 0 ? report.max_measured_error_px : std::numeric_limits<double>::quiet_NaN();
  r.plane.frame = frame_;
  r.plane.visible = r.drawn > 0;
  history_.push_back(r);
}

const Image& AnimationSession::frame_image() const {
  return source_.is_scene() ? scene_->frame() : plane_frame_;
}

std::vector<PolygonOutline> AnimationSession::outlines() const {
  std::vector<PolygonOutline> result;
  const Camera& camera = source_.camera();
  if (!source_.is_scene()) {
    if (!current().plane.visible) return result;
    const Mat3 warp = plane_->displayed_warp();
    const double w = source_.plane_texture.width(), h = source_.plane_texture.height();
    PolygonOutline outline;
    outline.level = current().plane.level;
    for (const Vec2& t : {Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)}) {
      outline.points.push_back(apply_homography(warp, t));
    }
    result.push_back(outline);
    return result;
  }
  const ViewerPose view = reference_view();
  for (size_t i = 0; i < source_.scene->polygons.size(); ++i) {
    const PolygonStatus status = scene_->statuses()[i];
    if (status != PolygonStatus::kAnimated && status != PolygonStatus::kClipped) continue;
    PolygonOutline outline;
    outline.level = scene_->levels()[i];
    bool in_front = true;
    for (const Vec3& v : polygon_vertices(source_.scene->polygons[i])) {
      const Vec3 r = to_view(view, v);
      if (r.z <= 1e-3) in_front = false;
      if (in_front) outline.points.push_back(centred_to_pixel(camera, project_centred(camera, r)));
    }
    if (in_front) result.push_back(outline);
  }
  return result;
}

ViewerPose AnimationSession::reference_view() const {
  const size_t k = static_cast<size_t>(frame_);
  if (source_.is_scene()) return source_.viewer.frames[k].pose;
  return viewer_for_pose(source_.plane_script.frames.front().pose,
                         source_.plane_script.frames[k].pose);
}

Mat3 AnimationSession::displayed_warp() const {
  return plane_ && !source_.is_scene() ? plane_->displayed_warp() : Mat3(1.0);
}

Mat3 AnimationSession::exact_warp() const {
  if (source_.is_scene() || !plane_visibility_problem(plane_pose()).empty()) return Mat3(1.0);
  return exact_texture_warp(source_.camera(), plane_pose());
}

PlanePose AnimationSession::plane_pose() const {
  if (source_.is_scene()) return PlanePose{};
  PlanePose pose = source_.plane_script.frames[static_cast<size_t>(frame_)].pose;
  pose.texture_size = {source_.plane_texture.width(), source_.plane_texture.height()};
  return pose;
}

RigidMotion AnimationSession::plane_motion() const {
  if (source_.is_scene()) return RigidMotion{};
  return source_.plane_script.frames[static_cast<size_t>(frame_)].motion;
}

}  // namespace oflab
