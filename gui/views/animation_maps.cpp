// The animation view's heat maps (gui/views/animation_view.h): each compared run's difference
// map against the exact frame with its agreement figures and, under per-pixel depth
// reprojection, its holes marked; kept while the frame on screen is the one they were
// computed of.
#include <algorithm>

#include "adapters/frame_images.h"
#include "adapters/hole_map.h"
#include "models/animation_model.h"
#include "player/policy_comparison.h"
#include "player/stage_times.h"
#include "runs/frame_maps.h"
#include "views/animation_view.h"
#include "views/panel_captions.h"

namespace oflab {

const AnimationView::HeatMap& AnimationView::comparison_heat_map(std::size_t index,
                                                                 const ComparedRun& run,
                                                                 const Image& exact) {
  if (heat_maps_.size() <= index) heat_maps_.resize(index + 1);
  HeatMap& map = heat_maps_[index];
  const Animator* animator = run.animator();
  const int exact_frame = model_->animator() ? model_->animator()->frame() : -1;
  const Pixel* exact_pixels = exact.empty() ? nullptr : exact.row(0);
  if (map.animator == animator && map.frame == animator->frame() && map.time_ms == run.time_ms &&
      map.pixels_written == run.pixels_written && map.exact == exact_pixels &&
      map.exact_frame == exact_frame) {
    return map;
  }
  const StageTimer timer(FrameStage::kMaps);
  ++map_passes_;
  const Image& image = animator->image();
  if (&image == &exact) {
    // The exact panel's own frame: no pixel differs, and the map is its first colour throughout
    // (difference_map_into), painted only when the image held another map or size.
    const QSize size(std::max(1, image.width()), std::max(1, image.height()));
    if (!map.blank || map.image.size() != size)
      difference_map_into(image, exact, kDifferenceScale, map.image);
    map.agreement = agreement_caption(frame_agreement(image, exact));
    map.blank = true;
  } else {
    map.agreement =
        agreement_caption(difference_map_and_agreement(image, exact, kDifferenceScale, map.image));
    map.blank = false;
  }
  map.holes = -1;
  if (run.policy->frame_warp == FrameWarp::kPerPixelDepth) {
    // Per-pixel depth reprojection: its holes are marked, never shown as a colour error.
    const std::vector<int>* sources = reprojection_sources(*animator, exact);
    map.holes = sources ? mark_reprojection_holes(map.image, *sources, exact) : 0;
    map.blank = map.blank && map.holes == 0;
  }
  map.animator = animator;
  map.frame = animator->frame();
  map.time_ms = run.time_ms;
  map.pixels_written = run.pixels_written;
  map.exact = exact_pixels;
  map.exact_frame = exact_frame;
  return map;
}

QImage AnimationView::heat_map(std::size_t index) const {
  return index < heat_maps_.size() ? heat_maps_[index].image : QImage();
}

}  // namespace oflab
