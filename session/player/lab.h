// The lab: one window state played, without a window. It holds the plane panel (the frame
// clock), the run of the state's source and the compared runs (player/run_player.h,
// player/policy_comparison.h), and the rest of the state as one WindowState value. The
// desktop's window model (gui/models/window_model.h) holds one and adds Qt signals; the
// command line (`oflab-cli lesson`) and the lesson checks play lessons on one headlessly.
// Plain C++.
#pragma once

#include <functional>
#include <string>

#include "image/image.h"
#include "player/plane_panel.h"
#include "player/policy_comparison.h"
#include "player/run_player.h"
#include "state/window_state.h"

namespace oflab {

class Lab {
 public:
  // Reads a texture file: the image, or an empty one with *error set to one line naming it.
  using TextureReader = std::function<Image(const std::string& path, std::string* error)>;
  // "" when a front-end can show `state`, else "field: problem" (the view, the exact
  // renderer: what the front-end has). Empty: every view and renderer is accepted.
  using FrontEndCheck = std::function<std::string(const WindowState& state)>;

  // The default state with `default_texture` (never empty) as the plane's texture; texture
  // files named by a state are read with `read_texture` (default: read_texture_file).
  explicit Lab(Image default_texture, TextureReader read_texture = {});

  PlanePanel& panel() { return panel_; }
  const PlanePanel& panel() const { return panel_; }
  RunPlayer& run() { return run_; }
  PolicyComparison& comparison() { return comparison_; }

  // The state's fields that the panel and the runs do not hold (the view, each view's
  // options, presentation, play, the lesson); `values().frame` etc. are not kept here.
  const WindowState& values() const { return values_; }
  WindowState& values() { return values_; }

  // The whole state as shown now.
  WindowState state() const;
  // "" when `state` can be applied: window_state_problem, the front-end's check, the
  // lesson and its step, the source kind and its files, the texture and the script;
  // else "field: problem".
  std::string problem(const WindowState& state) const;
  // Applies `state` whole, or changes nothing and returns problem(state).
  std::string apply(const WindowState& state);

  void set_front_end_check(FrontEndCheck check) { front_end_check_ = std::move(check); }

  // The default texture a state without "texture" shows.
  const Image& default_texture() const { return default_texture_; }

 private:
  std::string read_inputs(const WindowState& state, Image* texture,
                          std::optional<MotionScript>* script) const;

  Image default_texture_;
  TextureReader read_texture_;
  FrontEndCheck front_end_check_;
  PlanePanel panel_;
  RunPlayer run_;
  PolicyComparison comparison_;
  WindowState values_;
};

// The shipped butterfly (analysis/formats/datasets.h default_texture_path) decoded by
// analysis/formats/image_io.h. Throws std::runtime_error when it cannot be read.
Image shipped_default_texture();

// Reads a PNG or JPEG with analysis/formats/image_io.h; an empty image and *error on failure.
Image read_texture_file(const std::string& path, std::string* error);

// The policies named `names` (registry names; precondition: each is known).
std::vector<const ReusePolicy*> policies_named(const std::vector<std::string>& names);

}  // namespace oflab
