// One source under several reuse policies (see analysis/runs/policy_runs.h).
#include "runs/policy_runs.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace oflab {
namespace {

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// The per-frame peaks of the pixels written, frame 0 left out (it renders every layer).
void set_pixel_peaks(const AnimationRun& run, PolicyRow* row) {
  row->pixels_written = run.summary.pixels;
  std::vector<std::int64_t> per_frame;
  for (std::size_t i = 1; i < run.frames.size(); ++i) {
    per_frame.push_back(run.frames[i].pixels_written);
  }
  row->pixels_written_p95 = nearest_rank_percentile(per_frame, 95.0);
  row->pixels_written_max = nearest_rank_percentile(per_frame, 100.0);
  std::vector<std::int64_t> warped;
  row->pixels_warped = 0;
  for (std::size_t i = 0; i < run.frames.size(); ++i) {
    const AnimationFrame& f = run.frames[i];
    row->pixels_warped += f.pixels_written - f.pixels_not_warped;
    if (i > 0) warped.push_back(f.pixels_written - f.pixels_not_warped);
  }
  row->pixels_warped_p95 = nearest_rank_percentile(warped, 95.0);
}

nlohmann::json expiry_json(const ExpiryTable& t) {
  nlohmann::json layers = nlohmann::json::array();
  std::map<int, std::size_t> at;
  for (const ExpiryPair& p : t.pairs) {
    if (!at.count(p.layer)) {
      at[p.layer] = layers.size();
      layers.push_back({{"layer", p.layer},
                        {"predicted", nlohmann::json::array()},
                        {"actual", nlohmann::json::array()}});
    }
    nlohmann::json& l = layers[at[p.layer]];
    l["predicted"].push_back(p.predicted);
    l["actual"].push_back(p.actual);
  }
  return {{"by_rule", t.by_rule},
          {"early", t.early},
          {"other", t.other},
          {"unpredicted", t.unpredicted},
          {"exact", t.exact},
          {"median_error_frames", finite_or_null(t.median_error_frames)},
          {"max_error_frames", finite_or_null(t.max_error_frames)},
          {"layers", layers}};
}

}  // namespace

ExpiryTable expiry_table(const AnimationRun& run) {
  ExpiryTable t;
  std::vector<double> errors;
  for (const AnimationFrame& f : run.frames) {
    for (const FrameReport& r : f.layer_reports) {
      const ExpiryOutcome& o = r.expiry;
      if (!o.ended) continue;
      if (o.early) ++t.early;
      if (!o.by_rule && !o.early) ++t.other;
      if (!o.by_rule) continue;
      ++t.by_rule;
      if (o.predicted < 0) {
        ++t.unpredicted;
        continue;
      }
      t.pairs.push_back({r.layer, o.predicted, o.actual});
      errors.push_back(std::abs(o.predicted - o.actual));
      t.exact += o.predicted == o.actual ? 1 : 0;
    }
  }
  if (!errors.empty()) {
    std::sort(errors.begin(), errors.end());
    const std::size_t n = errors.size();
    t.median_error_frames = n % 2 ? errors[n / 2] : 0.5 * (errors[n / 2 - 1] + errors[n / 2]);
    t.max_error_frames = errors.back();
  }
  return t;
}

std::vector<PolicyRun> run_policies(const SourceKind& kind, const RunSource& source,
                                    const std::vector<const ReusePolicy*>& policies,
                                    const PlayOptions& options) {
  std::vector<PolicyRun> runs;
  for (const ReusePolicy* policy : policies) {
    RunSource one = source;
    one.settings.engine.policy = policy;
    PolicyRun r;
    r.policy = policy;
    r.cadence = one.settings.engine.cadence;
    PlayOptions o = options;
    o.on_view = [&r](int, const ViewerPose& view) { r.views.push_back(view); };
    r.run = kind.play(one, o);
    runs.push_back(std::move(r));
  }
  return runs;
}

std::vector<const ReusePolicy*> parse_policy_list(const std::string& text) {
  std::vector<const ReusePolicy*> out;
  std::set<std::string> seen;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) {
    const ReusePolicy* p = find_reuse_policy(name);
    if (!p) {
      throw std::invalid_argument("unknown policy '" + name + "' (one of " + reuse_policy_names() +
                                  ")");
    }
    if (!seen.insert(name).second) throw std::invalid_argument("policy '" + name + "' twice");
    out.push_back(p);
  }
  if (out.empty())
    throw std::invalid_argument("no policy given (one of " + reuse_policy_names() + ")");
  return out;
}

PolicyRow policy_row(const PolicyRun& r) {
  PolicyRow row;
  row.name = r.policy->name;
  const RunSummary& s = r.run.summary;
  row.frames = s.frames;
  row.layer_frames = s.drawn();
  for (int l = 0; l < kLevelCount; ++l) {
    row.level_share[l] = row.layer_frames > 0 ? double(s.levels[l]) / row.layer_frames : 0.0;
  }
  row.work_saved = s.work_saved;
  row.time_saved = s.time_saved;
  row.model_work_saved = s.model_work_saved;
  row.mean_psnr_db = s.mean_psnr_db;
  row.mean_ssim = s.mean_ssim;
  row.inpainted_pixels = s.inpainted_pixels;
  row.budgeted = r.policy->shares_budget;
  row.frames_over_budget = s.frames_over_budget;
  row.starved_layer_frames = s.starved_layer_frames;
  row.gap_frames = s.gap_frames;
  row.mean_optimality_gap = s.mean_optimality_gap;
  row.hole_pixels = s.hole_pixels;
  row.latency_frames = latency_frames(*r.policy, r.cadence);
  row.cache = s.cache;
  set_pixel_peaks(r.run, &row);
  row.predicts = r.policy->spreads_updates;
  if (row.predicts) row.expiry = expiry_table(r.run);
  double sum = 0.0;
  long count = 0;
  for (const AnimationFrame& f : r.run.frames) {
    // A frame warped as a whole (depth reprojection, frame generation) has no layer reports:
    // its largest per-pixel error is its one sample.
    if (f.layer_reports.empty() && f.drawn() > 0) {
      row.max_measured_error_px = std::max(row.max_measured_error_px, f.max_measured_error_px);
      sum += f.max_measured_error_px;
      ++count;
    }
    for (const FrameReport& report : f.layer_reports) {
      if (!report.visible || !std::isfinite(report.measured_error_px)) continue;
      row.max_measured_error_px = std::max(row.max_measured_error_px, report.measured_error_px);
      sum += report.measured_error_px;
      ++count;
    }
  }
  row.mean_measured_error_px = count > 0 ? sum / count : 0.0;
  return row;
}

nlohmann::json policy_row_json(const PolicyRow& row) {
  nlohmann::json levels;
  for (int l = 0; l < kLevelCount; ++l) {
    levels[level_name(static_cast<Level>(l))] = 100.0 * row.level_share[l];
  }
  nlohmann::json j = {{"name", row.name},
                      {"levels", levels},
                      {"rerender_share", row.level_share[static_cast<int>(Level::kRerender)]},
                      {"work_saved", row.work_saved},
                      {"time_saved", finite_or_null(row.time_saved)},
                      {"model_work_saved", row.model_work_saved},
                      {"max_measured_error_px", row.max_measured_error_px},
                      {"mean_measured_error_px", row.mean_measured_error_px},
                      {"mean_psnr_db", finite_or_null(row.mean_psnr_db)},
                      {"mean_ssim", finite_or_null(row.mean_ssim)},
                      {"layer_frames", row.layer_frames},
                      {"frames", row.frames},
                      {"hole_pixels", row.hole_pixels},
                      {"inpainted_pixels", row.inpainted_pixels},
                      {"latency_frames", row.latency_frames},
                      {"pixels_written", row.pixels_written},
                      {"pixels_written_p95", row.pixels_written_p95},
                      {"pixels_written_max", row.pixels_written_max},
                      {"pixels_warped", row.pixels_warped},
                      {"pixels_warped_p95", row.pixels_warped_p95}};
  if (row.cache.active) j["cache"] = node_cache_json(row.cache);
  if (row.predicts) j["expiry"] = expiry_json(row.expiry);
  if (row.budgeted) {
    j["budget"] = {{"frames_over_budget", row.frames_over_budget},
                   {"starved_layer_frames", row.starved_layer_frames},
                   {"gap_frames", row.gap_frames},
                   {"mean_optimality_gap", finite_or_null(row.mean_optimality_gap)}};
  }
  return j;
}

void print_policy_table(const std::vector<PolicyRow>& rows, std::ostream& out) {
  int name_width = 13;
  for (const PolicyRow& r : rows) name_width = std::max(name_width, int(r.name.size()) + 1);
  out << std::left << std::setw(name_width) << "policy" << std::right;
  for (int l = 0; l < kLevelCount; ++l) out << std::setw(12) << level_title(static_cast<Level>(l));
  out << std::setw(8) << "work" << std::setw(8) << "time" << std::setw(8) << "model"
      << std::setw(10) << "max err" << std::setw(10) << "mean err" << std::setw(8) << "PSNR"
      << std::setw(8) << "SSIM"
      << "\n";
  out << std::left << std::setw(name_width) << "" << std::right;
  for (int l = 0; l < kLevelCount; ++l) out << std::setw(12) << "% layer-fr.";
  out << std::setw(8) << "saved %" << std::setw(8) << "saved %" << std::setw(8) << "saved %"
      << std::setw(10) << "px" << std::setw(10) << "px" << std::setw(8) << "dB" << std::setw(8)
      << ""
      << "\n";
  out << std::fixed;
  for (const PolicyRow& r : rows) {
    out << std::left << std::setw(name_width) << r.name << std::right << std::setprecision(1);
    for (double share : r.level_share) out << std::setw(12) << 100.0 * share;
    out << std::setw(8) << 100.0 * r.work_saved << std::setw(8) << 100.0 * r.time_saved
        << std::setw(8) << 100.0 * r.model_work_saved << std::setprecision(3) << std::setw(10)
        << r.max_measured_error_px << std::setw(10) << r.mean_measured_error_px
        << std::setprecision(1) << std::setw(8) << r.mean_psnr_db << std::setprecision(3)
        << std::setw(8) << r.mean_ssim << "\n";
  }
  out << "pixels written (warped):";
  for (const PolicyRow& r : rows) {
    out << (&r == &rows.front() ? " " : ", ") << r.name << " " << r.pixels_written << " ("
        << r.pixels_warped << ")";
  }
  out << "\n";
  for (const PolicyRow& r : rows) {
    if (!r.budgeted) continue;
    out << r.name << ": " << r.frames_over_budget << " frames over budget, "
        << r.starved_layer_frames << " starved layer-frames, mean optimality gap "
        << optimality_gap_text(r.mean_optimality_gap, r.gap_frames) << "\n";
  }
  for (const PolicyRow& r : rows) {
    if (!r.predicts) continue;
    const ExpiryTable& e = r.expiry;
    out << std::setprecision(1) << r.name << ": " << e.by_rule << " expiries by the rule ("
        << e.exact << " predicted exactly, median error " << e.median_error_frames
        << " frames, largest " << e.max_error_frames << "), " << e.early
        << " re-renders brought forward, " << e.other << " lives ended otherwise; pixels per "
        << "frame p95 " << r.pixels_written_p95 << ", max " << r.pixels_written_max << "\n";
  }
  for (const PolicyRow& r : rows) {
    if (!r.cache.active) continue;
    const NodeCacheTotals& c = r.cache;
    out << std::setprecision(3) << r.name << ": " << c.nodes << " nodes, " << c.node_frames
        << " node-frames drawn, " << c.renders << " node renders (" << c.fresh << " fresh, "
        << c.by_angle << " by the angle, " << c.by_sphere << " by the safety sphere, "
        << c.uncacheable << " uncacheable); threshold " << c.threshold_px
        << " px at the focal length, largest corner angle reused " << c.max_angle_deg
        << " deg; holes " << r.hole_pixels << " px, overlaps " << c.overlap_pixels
        << " px; per-pixel error max " << c.max_pixel_error_px << " px, mean "
        << c.mean_pixel_error_px << " px\n";
  }
}

}  // namespace oflab
