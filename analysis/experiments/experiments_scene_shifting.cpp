#include "experiments/experiments_scene_shifting.h"

#include <iomanip>
#include <limits>
#include <sstream>

#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"

namespace oflab {
namespace {

ApproachFigures figures_of(const RunSummary& s) {
  ApproachFigures f;
  f.frames = s.frames;
  f.updates = s.drawn() - s.levels[static_cast<int>(Level::kNone)];
  f.rerendered = s.levels[static_cast<int>(Level::kRerender)];
  f.pixels = s.pixels;
  f.work_saved = s.work_saved;
  f.max_measured_error_px = s.max_measured_error_px;
  return f;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::vector<std::string> row(const std::string& script, const std::string& approach,
                             const ApproachFigures& f) {
  return {script,
          approach,
          std::to_string(f.updates),
          std::to_string(f.rerendered),
          std::to_string(f.pixels),
          fixed(100.0 * f.work_saved, 1) + "%",
          fixed(f.max_measured_error_px, 2)};
}

}  // namespace

SceneShiftingComparison compare_scene_shifting(const Scene& scene, const ViewerScript& script,
                                               double epsilon_px, int max_frames) {
  SceneShiftingComparison c;
  c.script = script.name;
  RunSource source;
  source.scene = std::make_shared<const Scene>(scene);
  source.viewer = script;
  source.shifting.epsilon_px = epsilon_px;
  source.settings.engine.thresholds.fill(epsilon_px);
  PlayOptions options;
  options.max_frames = max_frames;
  const AnimationRun shifting = source_kind("scene-shifting").play(source, options);
  const nlohmann::json& facts = shifting.facts.at("scene_shifting");
  for (const nlohmann::json& s : facts.at("slices")) {
    const nlohmann::json& far = s.at("far");
    c.slices.push_back({s.at("near").get<double>(), far.is_null()
                                                        ? std::numeric_limits<double>::infinity()
                                                        : far.get<double>()});
  }
  c.scene_shifting = figures_of(shifting.summary);
  c.turning_frames = facts.at("turning_frames");
  c.turning_frames_all_rebuilt = facts.at("turning_frames_all_rebuilt");
  c.optic_flow = figures_of(source_kind("scene").play(source, options).summary);
  return c;
}

ReportSection scene_shifting_section(ExperimentContext& context) {
  const double epsilon = 1.0;
  const int frames = context.quick() ? 30 : -1;
  const Scene scene = read_scene_file(resolve_scene_path("train-window"));
  ReportSection s;
  s.id = "scene-shifting";
  s.title = "Scene shifting (chapter 3): the view from a train window";
  s.paragraph(
      "Hofmann's scene shifting cuts the scene into slices parallel to the image plane and only "
      "shifts or scales each slice's layer; optic flow follows each plane's own flow. Both run "
      "here on the train-window scene (bushes at 2.5 to 3.3, fields at 8 and 12, hills at 40) "
      "with epsilon = 1 px, the engine's thresholds at the same 1 px.");
  std::vector<SceneShiftingComparison> results;
  for (const char* name : {"train-sideways", "train-turning"}) {
    context.progress("scene-shifting", std::string("running ") + name);
    const ViewerScript script = read_viewer_script_file(resolve_viewer_script_path(name));
    results.push_back(compare_scene_shifting(scene, script, epsilon, frames));
  }
  ReportTable slices;
  slices.caption = "Slices of train-sideways (|V| = 0.05 units/frame, k = 400 px, epsilon = 1 px)";
  slices.header = {"slice", "near", "far"};
  for (std::size_t i = 0; i < results[0].slices.size(); ++i) {
    const Slice& sl = results[0].slices[i];
    slices.rows.push_back({std::to_string(i + 1), fixed(sl.near, 3),
                           is_background(sl) ? "infinite (background)" : fixed(sl.far, 3)});
  }
  s.table(slices);
  ReportTable t;
  t.caption = "Scene shifting and optic flow on the same scene and scripts";
  t.header = {"script",         "approach",   "polygon updates", "re-rendered",
              "pixels written", "work saved", "max error (px)"};
  for (const SceneShiftingComparison& c : results) {
    t.rows.push_back(row(c.script, "scene shifting", c.scene_shifting));
    t.rows.push_back(row(c.script, "optic flow", c.optic_flow));
  }
  s.table(t);
  const SceneShiftingComparison& turning = results[1];
  s.paragraph(
      "On train-turning the viewing direction turned in " + std::to_string(turning.turning_frames) +
      " frames and scene shifting rebuilt every slice in " +
      std::to_string(turning.turning_frames_all_rebuilt) +
      " of them: its slices are no longer parallel to the image plane. Optic flow "
      "re-rendered " +
      std::to_string(turning.optic_flow.rerendered) + " polygon-frames there, scene shifting " +
      std::to_string(turning.scene_shifting.rerendered) + ".");
  return s;
}

}  // namespace oflab
