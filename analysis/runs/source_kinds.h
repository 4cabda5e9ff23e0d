// The kinds of animation source, one table: the single plane (a motion script and a
// texture), the scene (a viewer script through polygons, the scene animator) and scene
// shifting (the same inputs, Hofmann's slices). Each entry has its factory, its play (the
// run driver of analysis/runs/run_driver.h with the kind's baseline and facts), its
// per-frame CSV and its JSON summary; the CLI, the experiments and the GUI's export go
// through it, so no caller asks which kind a source is. Columns and keys are documented in
// manual/animation.md (plane) and manual/scenes.md (scene and scene shifting).
#pragma once

#include <iosfwd>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/animator.h"
#include "engine/script.h"
#include "runs/run_driver.h"
#include "scene/scene.h"
#include "scene/scene_animator.h"
#include "scene/viewer_script.h"
#include "scene_shifting/scene_shifting_renderer.h"

namespace oflab {

// What to animate. A kind reads only its own fields: the plane script, texture and
// settings.engine; the scene, viewer and settings; the scene, viewer and shifting.
struct RunSource {
  MotionScript script;  // single plane
  int repeat = 1;       // single plane: the script played this many times back to back
  Image texture;        // single plane, premultiplied RGBA
  std::shared_ptr<const Scene> scene;
  ViewerScript viewer;
  SceneSettings settings;          // .engine for the plane and the scene animator
  SceneShiftingSettings shifting;  // design_speed 0: script_design_speed of the viewer
};

struct PlayOptions : RunOptions {
  bool baseline = true;       // run the exact re-render in the same loop (time, work, PSNR)
  bool conventional = false;  // scenes: the VTK renderer too (needs an X display)
  // The VTK renderer multisamples frames with shaded contents at their samples per pixel
  // (analysis/runs/vtk_scene_renderer.h); false: one sample per pixel.
  bool conventional_multisample = true;
};

struct SourceKind {
  const char* name;  // "plane", "scene", "scene-shifting"
  // The source's animator; with `baseline`, the same source re-rendered exactly every frame
  // (the rerender mode, or every slice rebuilt). Throws std::invalid_argument for a source
  // the animator rejects.
  std::unique_ptr<Animator> (*make)(const RunSource& source, bool baseline);
  // Plays the source; fills the run's facts. Throws as make, and std::runtime_error when
  // the conventional renderer cannot start.
  AnimationRun (*play)(const RunSource& source, const PlayOptions& options);
  // One CSV row per frame, header first (write_csv_header, then write_csv_row per frame;
  // a run without its frames, RunOptions::keep_frames false, writes the rows through
  // on_record as it plays).
  void (*write_csv)(std::ostream& out, const AnimationRun& run);
  void (*write_csv_header)(std::ostream& out);
  void (*write_csv_row)(std::ostream& out, const FrameRecord& record);
  // The run's JSON summary (from its summary and facts: also of a run without its frames).
  nlohmann::json (*summary_json)(const AnimationRun& run);
  // True when a mode named `name` selects the kind in place of a reuse policy (`oflab-cli
  // animate --mode scene-shifting`); false when the inputs choose it (a motion script: the
  // plane; a scene: the scene animator under the policy of the mode).
  bool selected_by_mode = false;
  // The columns the kind's rows add after hole_pixels (with a leading comma; "" for none):
  // the scene's causes of its re-renders (AnimationFrame::rerender_causes), which say per
  // frame why a policy on a fixed cadence did not keep it.
  const char* hole_extra_columns = "";
};

// Writes a kind's CSV header (`header`, one of SourceKind::write_csv_header); with `holes`
// (AnimationFrame::reports_holes) the line gets the column hole_pixels and then `extra`
// (SourceKind::hole_extra_columns), which the kinds' rows then fill. Without holes the
// header is the kind's own, byte for byte.
void write_csv_header_for(std::ostream& out, void (*header)(std::ostream&), bool holes,
                          const char* extra = "");

// The kinds, in the order above.
const std::vector<SourceKind>& source_kinds();
// The kind named `name`; throws std::invalid_argument for an unknown name.
const SourceKind& source_kind(const std::string& name);
// The kind that the mode `mode` selects (selected_by_mode); nullptr for any other word (a
// reuse policy, or nothing).
const SourceKind* source_kind_for_mode(const std::string& mode);
// The names of the kinds selected by a mode, joined by `separator`: "scene-shifting".
std::string source_kind_modes(const std::string& separator = ", ");

// Lines of the text summary shared by the scene kinds: "  polygons per level (N drawn
// polygon-frames):" and a line per level with its count and percent; leaves `out` in fixed
// notation with one decimal.
void print_polygon_levels(const RunSummary& summary, std::ostream& out);
// "  time saved ...% against the exact re-render, work saved ...% (pixels written ...)" and
// "  max measured error ... px, mean PSNR against the exact frame ... dB" and
// "  model work saved ...% (cost model ...); content render time ... ms; max photometric
// error ... grey levels", in the stream's current notation.
void print_savings_and_error(const RunSummary& summary, std::ostream& out);

// The "budget" block of a run's JSON summary, for a policy that shares a per-frame budget
// (summary.budget_frames > 0): {"frames" (with the budget active), "frames_over_budget",
// "starved_layer_frames", "gap_frames", "mean_optimality_gap" (a fraction; null when no
// frame was checked by exhaustive search)}; null for other policies, whose summaries then
// have no "budget" key.
nlohmann::json budget_json(const RunSummary& summary);
// "  budget: F frames over budget (of N), S starved layer-frames, mean optimality gap ..."
// (optimality_gap_text) for a block of budget_json; nothing for null.
void print_budget(const nlohmann::json& budget, std::ostream& out);
// A budgeted run's mean optimality gap (a fraction, NaN when no frame was checked) over its
// checked frames: "G% over K frames checked against the optimum", or "not checked (...)".
std::string optimality_gap_text(double mean_gap, long gap_frames);

}  // namespace oflab
