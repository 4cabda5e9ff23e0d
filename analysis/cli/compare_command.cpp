// `oflab-cli compare`: one motion script (or a scene's viewer script) played under several
// reuse policies, one row per policy (analysis/runs/policy_runs.h, manual/policies.md).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/animate_options.h"
#include "cli/animate_scene.h"
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "formats/image_io.h"
#include "formats/script_file.h"
#include "runs/policy_runs.h"

namespace oflab {
namespace {

// The source of the options: a scene and its viewer script with --scene, else a plane's
// motion script and texture. Sets *kind to the source's kind.
RunSource read_source(const CliArgs& a, const SourceKind** kind) {
  if (a.has("--scene")) {
    *kind = &source_kind("scene");
    return read_scene_source(a);  // as animate reads it: the same options, the same run
  }
  for (const char* option : {"--near", "--guard-band", "--no-skip-hidden", "--warp", "--hole-fill",
                             "--cache-angle", "--node-polygons", "--safety-radius", "--mesh-grid",
                             "--mesh-split", "--mesh-rebuild", "--mesh-jump", "--rubber-sheets"}) {
    if (a.has(option)) throw UsageError(std::string(option) + ": needs --scene NAME|FILE");
  }
  *kind = &source_kind("plane");
  return read_plane_source(a);
}

// Writes `text` as NAME in --out DIR (into its temporary directory, `out`), checked.
void write_output(const AtomicDir& out, const std::string& dir, const std::string& name,
                  const std::string& text) {
  write_file_inside(out.path() + "/" + name, text, dir + "/" + name);
}

// DIR/POLICY.csv per policy (the kind's per-frame CSV) and DIR/summary.csv, a row each, then
// DIR renamed into place.
void write_outputs(AtomicDir& out, const std::string& dir, const SourceKind& kind,
                   const std::vector<PolicyRun>& runs, const std::vector<PolicyRow>& rows) {
  for (const PolicyRun& r : runs) {
    std::ostringstream csv;
    kind.write_csv(csv, r.run);
    write_output(out, dir, std::string(r.policy->name) + ".csv", csv.str());
  }
  std::ostringstream summary;
  summary << "policy";
  for (int l = 0; l < kLevelCount; ++l) summary << ",pct_" << level_name(static_cast<Level>(l));
  summary << ",work_saved,time_saved,model_work_saved,max_measured_error_px,"
             "mean_measured_error_px,mean_psnr_db,layer_frames,frames,frames_over_budget,"
             "starved_layer_frames,mean_optimality_gap,hole_pixels,latency_frames,mean_ssim,"
             "inpainted_pixels,pixels_written,pixels_written_p95,pixels_written_max,pixels_warped,"
             "pixels_warped_p95\n";
  for (const PolicyRow& row : rows) {
    summary << row.name;
    for (double share : row.level_share) summary << ',' << 100.0 * share;
    summary << ',' << row.work_saved << ',' << row.time_saved << ',' << row.model_work_saved << ','
            << row.max_measured_error_px << ',' << row.mean_measured_error_px << ','
            << row.mean_psnr_db << ',' << row.layer_frames << ',' << row.frames;
    // The budget columns are empty for policies without a frame budget (and the gap when
    // no frame was checked by exhaustive search).
    if (row.budgeted) {
      summary << ',' << row.frames_over_budget << ',' << row.starved_layer_frames << ',';
      if (std::isfinite(row.mean_optimality_gap)) summary << row.mean_optimality_gap;
    } else {
      summary << ",,,";
    }
    summary << ',' << row.hole_pixels << ',' << row.latency_frames << ',';
    if (std::isfinite(row.mean_ssim)) summary << row.mean_ssim;
    summary << ',' << row.inpainted_pixels << ',' << row.pixels_written << ','
            << row.pixels_written_p95 << ',' << row.pixels_written_max << ',' << row.pixels_warped
            << ',' << row.pixels_warped_p95 << "\n";
  }
  write_output(out, dir, "summary.csv", summary.str());
  out.commit();
}

// The names of the registry's policies that `uses` holds for, joined: "timewarp, cadence".
template <class Uses>
std::string policy_names_where(Uses uses) {
  std::string names;
  for (const ReusePolicy& p : reuse_policies()) {
    if (uses(p)) names += (names.empty() ? "" : ", ") + std::string(p.name);
  }
  return names;
}

// An option that only a kind of policy reads, given while no compared policy reads it, would
// change nothing: refused, naming the option, the policies that read it and those compared.
bool uses_mesh(const ReusePolicy& p) { return p.pixel_motion == PixelMotion::kFarMesh; }

void refuse_options_without_their_policy(const CliArgs& a,
                                         const std::vector<const ReusePolicy*>& policies) {
  struct Rule {
    const char* option;
    bool (*uses)(const ReusePolicy&);
  };
  const Rule rules[] = {
      {"--cadence", [](const ReusePolicy& p) { return p.schedule == Schedule::kCadence; }},
      {"--stabilization-plane",
       [](const ReusePolicy& p) { return p.frame_plane == FramePlane::kStabilization; }},
      {"--hole-fill",
       [](const ReusePolicy& p) {
         return p.frame_warp == FrameWarp::kPerPixelDepth &&
                p.pixel_motion == PixelMotion::kViewerStep;
       }},
      {"--mesh-grid", uses_mesh},
      {"--mesh-split", uses_mesh},
      {"--mesh-rebuild", uses_mesh},
      {"--mesh-jump", uses_mesh},
      {"--rubber-sheets", uses_mesh},
  };
  for (const Rule& rule : rules) {
    if (!a.has(rule.option)) continue;
    if (std::any_of(policies.begin(), policies.end(),
                    [&](const ReusePolicy* p) { return rule.uses(*p); })) {
      continue;
    }
    std::string compared;
    for (const ReusePolicy* p : policies)
      compared += (compared.empty() ? "" : ",") + std::string(p->name);
    throw UsageError(std::string(rule.option) + ": needs one of " + policy_names_where(rule.uses) +
                     " in --policies, not '" + compared + "'");
  }
}

int compare(const CliArgs& a, std::ostream& out, std::ostream& err) {
  const CompareInputs inputs = read_compare_inputs(a);
  const SourceKind* kind = inputs.kind;
  const RunSource& source = inputs.source;
  const std::vector<const ReusePolicy*>& policies = inputs.policies;
  PlayOptions options;
  add_compare_measures(options);
  const RunOutput output = read_run_output(a, err);
  output.apply_timing_to(options);
  const std::vector<PolicyRun> runs = run_policies(*kind, source, policies, options);
  std::vector<PolicyRow> rows;
  for (const PolicyRun& r : runs) rows.push_back(policy_row(r));
  if (!output.dir.empty()) write_outputs(*output.out, output.dir, *kind, runs, rows);
  const std::string script = source.scene ? source.viewer.name : source.script.name;
  if (a.has("--json")) {
    out << compare_json(inputs, rows).dump(2) << "\n";
    return 0;
  }
  out << (source.scene ? "scene " + source.scene->name + ", viewer script " : "script ") << script
      << ", " << (rows.empty() ? 0 : rows.front().frames) << " frames, " << policies.size()
      << " policies (times measured in the same run as each policy's "
      << "exact re-render)\n";
  print_policy_table(rows, out);
  return 0;
}

}  // namespace

CompareInputs read_compare_inputs(const CliArgs& a) {
  if (!a.has("--policies")) throw UsageError("--policies: needs a list, e.g. perspective,talisman");
  CompareInputs inputs;
  std::vector<const ReusePolicy*>& policies = inputs.policies;
  try {
    policies = parse_policy_list(a.values("--policies").at(0));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--policies: ") + e.what());
  }
  for (const ReusePolicy* p : policies) {
    if (std::string why; needs_scene(*p, &why) && !a.has("--scene")) {
      throw UsageError(std::string("--policies: ") + p->name + " needs --scene NAME|FILE (" + why +
                       ")");
    }
  }
  refuse_options_without_their_policy(a, policies);
  inputs.source = read_source(a, &inputs.kind);
  const RunSource& source = inputs.source;
  const bool budgeted = std::any_of(policies.begin(), policies.end(),
                                    [](const ReusePolicy* p) { return p->shares_budget; });
  if (source.settings.engine.budget.unit != FrameBudget::Unit::kNone && !budgeted) {
    throw UsageError(std::string(a.has("--budget-ms") ? "--budget-ms" : "--budget-pixels") +
                     ": needs budget in --policies (the only policy with a frame budget)");
  }
  return inputs;
}

const std::map<std::string, int>& compare_options() {
  static const std::map<std::string, int> options = [] {
    std::map<std::string, int> all = run_options();
    all.insert({"--policies", 1});
    all.insert({"--warp", 1});  // scenes only (read_scene_settings)
    return all;
  }();
  return options;
}

nlohmann::json compare_json(const CompareInputs& inputs, const std::vector<PolicyRow>& rows) {
  const RunSource& source = inputs.source;
  const std::string script = source.scene ? source.viewer.name : source.script.name;
  nlohmann::json j = {{"script", script}, {"policies", nlohmann::json::array()}};
  if (source.scene) j["scene"] = source.scene->name;
  j["thresholds"] = source.settings.engine.thresholds;
  for (const PolicyRow& row : rows) j["policies"].push_back(policy_row_json(row));
  return j;
}

int run_compare_command(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  try {
    const CliArgs a(args, compare_options());
    if (!a.has("--script")) throw UsageError("--script: needs NAME|FILE");
    if (!a.has("--scene")) return compare(a, out, err);
    return report_scene_input_errors([&] { return compare(a, out, err); }, err, "compare");
  } catch (const ScriptError& e) {
    err << "oflab-cli compare: " << e.what() << "\n";
    return 2;
  } catch (const ImageFileError& e) {
    err << "oflab-cli compare: --texture: " << e.what() << "\n";
    return 2;
  }
}

void add_compare_measures(PlayOptions& options) { options.measure_ssim = true; }

}  // namespace oflab
