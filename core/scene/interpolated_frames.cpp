// The scene engine's frames between two renders under view interpolation
// (core/scene/scene_animator.h; the interpolation itself is core/scene/view_interpolation.h):
// the next render made ahead of its time, and each frame between made from both renders. The
// rest of the frame loop is scene_animator.cpp.
#include <algorithm>

#include "engine/wall_clock.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

using Clock = WallClock;

}  // namespace

bool SceneEngine::look_ahead(double& excluded_ms) {
  if (!future_views_) return false;
  // The next render: the next frame on the cadence, or the last frame there is before it.
  const int cadence = std::max(1, settings_.engine.cadence);
  int next = (frame_index_ / cadence + 1) * cadence;
  ViewerPose view;
  while (next > frame_index_ && !future_views_(next, view)) --next;
  if (next <= frame_index_) return false;
  if (next == next_index_) return true;
  // Rendered as the frame `next` will render it (every polygon afresh), its time counted there.
  const auto t0 = Clock::now();
  AnimationFrame ahead;
  ahead.frame = next;
  ahead.layers = static_cast<int>(scene_.polygons.size());
  render_frame(nullptr, nullptr, view, ahead);
  next_frame_ = frame_;
  next_depth_ = render_depth(scene_, camera_, view, settings_.near);
  next_view_ = view;
  next_index_ = next;
  excluded_ms += ms_since(t0);
  return true;
}

double SceneEngine::interpolate_frame(const ViewerPose& current, AnimationFrame& report) {
  const double t = static_cast<double>(frame_index_ - rendered_index_) /
                   static_cast<double>(next_index_ - rendered_index_);
  InterpolatedFrame f = interpolate_views(
      RenderedView{rendered_frame_, rendered_depth_, viewer_step(rendered_view_, current)},
      RenderedView{next_frame_, next_depth_, viewer_step(next_view_, current)}, t, camera_,
      settings_.near);
  return show_splats(std::move(f.image), std::move(f.source), f.unreached, f.pixels_written,
                     f.source_pixels, f.max_error_px, current, report);
}

}  // namespace oflab
