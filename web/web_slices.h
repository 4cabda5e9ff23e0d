// The scene-shifting view on the page (manual/web.md, manual/scene-shifting.md): the
// teaching layer's walk (session/player/slice_walk.h) and diagram
// (session/display/slice_diagram.h), the numbers and pictures the desktop's view shows,
// handed to web/slices_view.js as JSON and canvas pixels. Made when the page first shows
// the view (reading the train-window scene and cutting its slices costs some milliseconds).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "player/slice_walk.h"

namespace oflab {

class WebSlices {
 public:
  // Cuts the slices for `epsilon_px` (pixels per frame) and `speed` (world units per frame)
  // when they changed (and restarts the walk), brings the walk to the window's frame
  // `window_frame` (modulo the walk's length) and returns it as JSON:
  // {"problem", "slicing_problem", "exact_problem", "exact_title", "frame", "frame_count",
  //  "caption", "width", "height" (the camera's pixels), "diagram": {"slices": [{"near",
  //  "far" (null for the background)}], "asymptote" (null when not drawn), "asymptote_label",
  //  "title", "max_depth", "ticks", "half_width", "planes": [{"depth", "left", "right"}],
  //  "focal_px", "epsilon_px", "speed"}} (world units, pixels).
  std::string update(double epsilon_px, double speed, int window_frame);

  // The frame shown as scene shifting draws it (`exact` false) or as core's exact render
  // projects it (true), flattened over dark grey (17, 19, 21) and sampled at width x height
  // display pixels (clamped to 1 .. 4096): RGBA8 rows, valid until the next call. Empty when
  // there is no such frame.
  const std::vector<std::uint8_t>& pixels(bool exact, int width, int height);

 private:
  SliceWalk walk_;
  bool cut_ = false;  // the slicing was set from the page's sliders at least once
  std::vector<std::uint8_t> pixels_;
};

}  // namespace oflab
