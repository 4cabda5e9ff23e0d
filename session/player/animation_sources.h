// What the animation model can play, as one table of source kinds: the plane of the scene
// panel, a motion script for that plane, a multi-plane scene walked through by a viewer
// script, and scene shifting of such a scene. Each entry says what differs between kinds as
// data (its name in session files, its picker label, whether it follows the scene panel or
// needs a viewer script) and functions (its shipped names, how to make its animator and
// write its per-frame CSV). The animation controls, the animation model, session files and
// the exports read this table; adding a source kind is adding an entry.
//
// Animators and CSVs come from the analysis source-kind table (analysis/runs/), so the GUI
// plays and exports every source exactly as `oflab-cli animate` does.
#pragma once

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "display/panel_framing.h"
#include "engine/animator.h"
#include "scene/viewer_script.h"
#include "state/source_choice.h"

namespace oflab {

class PlanePanel;

struct AnimationSourceKind {
  std::string name;   // SourceChoice::kind and the session file's "kind": "scene"
  std::string label;  // picker entry, %1 the shipped name: "Scene: %1"
  // Title of the animation view's engine panel, %1 the engine mode's name.
  std::string panel_title;
  // The source is the scene panel's plane and motion: it is rebuilt when they change, and
  // the scene panel's own loop length is kept.
  bool follows_scene_panel = false;
  bool uses_viewer = false;    // a viewer script walks through it
  std::string default_viewer;  // the viewer script offered first (uses_viewer only)
  // The names the picker offers (shipped datasets; {""} for the scene panel's plane).
  std::function<std::vector<std::string>()> shipped_names;
  // The animator playing `choice` with `settings`, started at frame 0. Throws
  // std::runtime_error or std::invalid_argument with a one-line reason when a file cannot
  // be read or the source cannot be played (e.g. scene shifting of a scene whose planes are
  // not parallel to the image plane).
  std::function<std::unique_ptr<Animator>(const SourceChoice& choice, const PlanePanel& panel,
                                          const EngineSettings& settings)>
      make;
  // Runs the whole source headless and writes one CSV row per frame, header first (the
  // columns of `oflab-cli animate` for this kind). Throws like make.
  std::function<void(const SourceChoice& choice, const PlanePanel& panel,
                     const EngineSettings& settings, std::ostream& out)>
      write_csv;
  // The motion script of a single-plane kind (what zoom-to-fit frames); null for kinds
  // that play a scene. Throws like make.
  std::function<MotionScript(const SourceChoice& choice, const PlanePanel& panel)> plane_script;
  // The viewer script of a kind that plays a scene (what zoom-to-fit frames: the polygons
  // over the whole walk); null for single-plane kinds. Throws like make.
  std::function<ViewerScript(const SourceChoice& choice)> viewer_script;
  // The engine's reuse policy, thresholds and Delta policy drive it (scene shifting keeps
  // its own tolerance instead, so the controls for them do not apply).
  bool uses_reuse_policy = true;
};

// Every source kind, in picker order.
const std::vector<AnimationSourceKind>& animation_source_kinds();

// The kind with this name, or nullptr.
const AnimationSourceKind* find_animation_source_kind(const std::string& name);

// `pattern` (a label or panel title) with its "%1", if any, replaced by `value`.
std::string fill_pattern(const std::string& pattern, const std::string& value);

// What `choice` plays, in the picker's words: "Scene: street, viewer script walk",
// "Plane script: swing", "Plane of the scene panel"; the kind's name for an unknown kind.
std::string describe_source(const SourceChoice& choice);

// The names of the kinds, comma separated, for error messages.
std::string animation_source_kind_names();

// What `choice` shows at each frame, as the panels' framing takes it
// (display/panel_framing.h): a plane kind's image bounds along its script (`panel`: the
// scene panel's plane, for the kinds that play it), a scene kind's exact outlines of `scene`
// (the scene its engines play; null: none) along its viewer script, with the near plane
// `near`. Empty for an unknown kind, a kind with neither, or a source that cannot be read
// (the lab refuses it with a message).
FrameBounds source_frame_bounds(const SourceChoice& choice, const PlanePanel& panel,
                                const Scene* scene, double near);

}  // namespace oflab
