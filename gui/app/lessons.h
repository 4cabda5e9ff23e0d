// Lesson presets for the classroom: each sets up a view, a scene and motion, the view's
// options and a narrative caption shown above the views. manual/lessons.md has one
// section per preset (what to show, what to ask, what to point at). Plain C++.
#pragma once

#include <string>
#include <vector>

#include "adapters/flow_display.h"
#include "engine/engine.h"
#include "flow/plane_scene.h"
#include "views/animation_controls.h"
#include "views/basis_catalog.h"

namespace oflab {

struct Lesson {
  std::string name;     // command-line name, e.g. "flow-of-a-plane"
  std::string title;    // menu entry
  std::string caption;  // the narrative, a few sentences
  std::string view;     // the view it shows: "flow", "basis", "animation" or "analysis"
  PlaneScene scene;
  FlowDisplay flow;
  BasisKind basis = BasisKind::kPlanar;
  bool play_basis = false;   // animate the gallery's deformation amount
  bool play_motion = false;  // play the scene's motion
  // What the animation and analysis views play (gui/models/animation_sources.h: a kind of
  // its table, a name and a viewer script) and with which reuse policy
  // (core/engine/reuse_policy.h).
  std::string animation_kind = "plane";
  std::string animation_name;
  std::string animation_viewer;
  const ReusePolicy* mode = &default_reuse_policy();
  // How the animation view shows its panels (the comparison plays several policies at once).
  PanelDisplay display = PanelDisplay::kSideBySide;
  // The policies the comparison layout plays (2 .. kMaxComparedPolicies of the registry).
  std::vector<const ReusePolicy*> compared = {&reuse_policy("affine"),
                                              &reuse_policy("perspective")};
};

// Every preset, in teaching order.
const std::vector<Lesson>& lessons();

// The preset with this name, or nullptr.
const Lesson* find_lesson(const std::string& name);

// The names, comma separated, for error messages and --help.
std::string lesson_names();

}  // namespace oflab
