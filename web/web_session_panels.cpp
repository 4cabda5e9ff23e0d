// The animation view's panels of one browser page (web_session.h): their framing by the
// desktop's rule, their frames and heat maps sampled for the page, and the panel_fill claim the
// page measures on them.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "display/panel_framing.h"
#include "frame_pixels.h"
#include "image/image_compare.h"
#include "image/pixel_rows.h"      // warp_area_name
#include "scene/scene_animator.h"  // SceneSettings: the exact render's near plane
#include "shown_runs.h"
#include "web_session.h"

namespace oflab {
namespace {

using json = nlohmann::json;

// The page's background behind transparent frame pixels (the style sheet's panel colour).
constexpr std::uint8_t kBackground[3] = {24, 27, 31};
// Largest side of a comparison panel, display pixels.
constexpr int kMaxPanelSide = 4096;
// Grey levels of difference at the top of the heat map's ramp.
constexpr int kHeatFullScale = 64;
// The exact render's near plane, which frames and outlines what is seen.
const double kNear = SceneSettings{}.near;

}  // namespace

PanelView WebSession::panel_view(const Animator& exact, int cell_width, int cell_height) {
  const WindowState& s = lab_.values();
  if (bounds_epoch_ != epoch_) {  // what the source shows at each frame, once per state
    frame_bounds_ = source_frame_bounds(s.source, lab_.panel(), &exact.scene(), kNear);
    bounds_epoch_ = epoch_;
  }
  const std::optional<BoundingBox> content =
      framed_content(frame_bounds_, exact.frame(), frames_content(s.framing, s.presentation));
  const double aspect = hugging_aspect(double(cell_width) / cell_height, content, s.zoom);
  const Camera& camera = exact.camera();
  return fit_panel_view(panel_frame(content, camera.width, camera.height, aspect, s.zoom),
                        cell_width, cell_height);
}

void WebSession::sample_panels(const std::vector<const Animator*>& animators,
                               const PanelView& view) {
  const Image& exact = animators.back()->image();
  const DisplaySampling sampling = region_sampling(exact.width(), exact.height(), view.x0, view.y0,
                                                   view.pixel, view.width, view.height);
  panels_.resize(animators.size());
  for (std::size_t k = 0; k < animators.size(); ++k) {
    WebPanel& panel = panels_[k];
    const Image& image = animators[k]->image();
    flatten_into(image, sampling, kBackground, panel.pixels);
    if (k + 1 == animators.size()) {
      // The exact run against itself: no heat map is shown, and the figures are known.
      panel.heat.clear();
      panel.heat_max = 0;
      panel.psnr_db = kIdenticalPsnrDb;
      continue;
    }
    difference_heat_map_into(image, exact, kHeatFullScale, sampling, panel.heat);
    panel.heat_max = largest_difference(image, exact);
    panel.psnr_db = psnr_db(image, exact);
  }
  sampled_frame_ = animators.back()->frame();
  sampled_view_ = view;
  sampled_epoch_ = epoch_;
}

std::string WebSession::update_comparison(int cell_width, int cell_height) {
  cell_width = std::clamp(cell_width, 1, kMaxPanelSide);
  cell_height = std::clamp(cell_height, 1, kMaxPanelSide);
  const std::vector<const Animator*> animators = shown_animators();
  std::vector<ShownRun> shown = shown_runs(lab_, &comparison_problem_);
  if (!animators.empty() && (sampled_frame_ != animators.back()->frame() ||
                             sampled_cell_ != glm::ivec2(cell_width, cell_height) ||
                             sampled_epoch_ != epoch_ || panels_.size() != animators.size())) {
    sample_panels(animators, panel_view(*animators.back(), cell_width, cell_height));
    sampled_cell_ = {cell_width, cell_height};
  }
  const PanelView& view = sampled_view_;
  json out;
  out["problem"] = comparison_problem_;
  out["frame"] = frame();
  out["frames"] = frame_count();
  out["width"] = animators.empty() ? 0 : animators.back()->camera().width;
  out["height"] = animators.empty() ? 0 : animators.back()->camera().height;
  out["panel"] = {view.width, view.height};
  out["shown"] = {view.x0, view.y0, view.pixel};
  out["heat_full_scale"] = kHeatFullScale;
  out["warp"] = warp_area_name(lab_.values().settings.warp_area);
  json runs = json::array();
  if (!animators.empty()) {
    shown.push_back({kExactPolicy, exact_shown_, exact_record_, {}, 0.0});
    for (std::size_t k = 0; k < shown.size(); ++k) {
      runs.push_back(shown_run_json(shown[k], panels_[k].psnr_db, panels_[k].heat_max));
    }
  }
  out["runs"] = runs;
  return out.dump();
}

double WebSession::page_panel_fill() {
  const WindowState& s = lab_.values();
  if (s.view != "animation" || s.cause_and_effect || sampled_cell_.x < 1) return std::nan("");
  // The panels as the page draws them now: the part of the frame shown (the runs brought to
  // it) that update_comparison frames in the cell they were last drawn in.
  const std::vector<const Animator*> animators = shown_animators();
  if (animators.empty()) return std::nan("");
  const Animator& exact = *animators.back();
  const PanelView v = panel_view(exact, sampled_cell_.x, sampled_cell_.y);
  const BoundingBox shown{v.x0, v.y0, v.x0 + v.pixel * v.width, v.y0 + v.pixel * v.height};
  return 100.0 *
         outline_fill(exact_outlines(exact.scene(), exact.view(), exact.camera(), kNear), shown);
}

}  // namespace oflab
