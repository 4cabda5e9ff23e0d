#include "shown_runs.h"

#include <algorithm>
#include <cmath>

#include "engine/reuse_policy.h"
#include "player/animation_sources.h"
#include "player/lab.h"
#include "player/policy_comparison.h"
#include "player/run_player.h"
#include "state/window_state.h"

namespace oflab {
namespace {

using json = nlohmann::json;

json point_json(const Vec2& p) { return json::array({p.x, p.y}); }

ShownRun shown_compared(const ComparedRun& run) {
  ShownRun shown{run.policy->name, run.animator(), &run.last, {}, 0.0};
  const int now = run.animator()->frame();
  shown.level_frames = run.level_totals(1, now);
  for (const ComparedFrame& f : run.history) {
    if (f.frame >= 1) shown.max_error_px = std::max(shown.max_error_px, f.max_measured_error_px);
  }
  return shown;
}

// The model's run as the views name it: its reuse policy, or the source's kind when the kind
// has none (scene shifting).
std::string model_name(RunPlayer& player) {
  return player.source_kind().uses_reuse_policy ? player.settings().policy->name
                                                : player.source().kind;
}

// The desktop's rule (gui/views/animation_view.cpp, analysis_view.cpp): the views show the
// compared runs while the animation view's layout is the comparison and there are compared
// runs (a kind without a reuse policy has none); otherwise the model's own engine.
bool shows_compared(Lab& lab) {
  return lab.state().display == PanelDisplay::kComparison && !lab.comparison().runs().empty();
}

ShownRun shown_model(RunPlayer& player) {
  ShownRun shown{model_name(player), player.animator(), &player.current(), {}, 0.0};
  const std::vector<AnimationFrame>& history = player.history();
  for (std::size_t k = 1; k < history.size(); ++k) {
    for (int l = 0; l < kLevelCount; ++l) shown.level_frames[l] += history[k].levels[l];
    shown.max_error_px = std::max(shown.max_error_px, history[k].max_measured_error_px);
  }
  return shown;
}

// The level of a frame: the shown layer's for one plane, the drawn layers per level for a
// scene.
std::string level_text(const AnimationFrame& record) {
  if (record.layer_reports.size() == 1) {
    return record.layer_reports[0].visible ? level_name(record.layer_reports[0].level)
                                           : "not visible";
  }
  std::string text;
  for (int l = 0; l < kLevelCount; ++l) {
    if (record.levels[l] == 0) continue;
    text += (text.empty() ? "" : ", ") + std::to_string(record.levels[l]) + " " +
            level_name(static_cast<Level>(l));
  }
  return text.empty() ? "nothing drawn" : text;
}

}  // namespace

std::vector<ShownRun> shown_runs(Lab& lab, std::string* problem) {
  std::vector<ShownRun> shown;
  if (!lab.run().animator()) {
    *problem = lab.run().take_problem();
    if (problem->empty()) *problem = "the source cannot be played";
    return shown;
  }
  if (!shows_compared(lab)) return {shown_model(lab.run())};
  for (const ComparedRun& run : lab.comparison().runs()) {
    if (!run.problem.empty()) {
      *problem = run.problem;
      return {};
    }
    shown.push_back(shown_compared(run));
  }
  return shown;
}

nlohmann::json shown_run_json(const ShownRun& run, double psnr_db, int heat_max) {
  json levels = json::object();
  std::int64_t drawn = 0;
  for (int l = 0; l < kLevelCount; ++l) drawn += run.level_frames[l];
  for (int l = 0; l < kLevelCount; ++l) {
    levels[level_name(static_cast<Level>(l))] =
        drawn > 0 ? static_cast<double>(run.level_frames[l]) / double(drawn) : 0.0;
  }
  json outlines = json::array();
  for (const LayerOutline& outline : run.animator->outlines()) {
    json points = json::array();
    for (const Vec2& p : outline.points) points.push_back(point_json(p));
    outlines.push_back({{"level", level_name(outline.level)}, {"points", points}});
  }
  const ReusePolicy* policy = find_reuse_policy(run.policy);
  return {{"policy", run.policy},
          {"summary", policy ? policy->summary : std::string()},
          {"level", level_text(*run.last)},
          {"measured_error_px", run.last->max_measured_error_px},
          {"max_error_px", run.max_error_px},
          {"pixels_written", run.last->pixels_written},
          {"pixels_warped", run.last->pixels_written - run.last->pixels_not_warped},
          {"level_shares", levels},
          {"psnr_db", psnr_db},
          {"heat_max", heat_max},
          {"outlines", outlines}};
}

std::string analysis_history_json(Lab& lab, int frames) {
  frames = std::clamp(frames, 1, 1000);
  std::string problem;
  if (!lab.run().animator()) {
    problem = lab.run().take_problem();
    return json{{"problem", problem.empty() ? "the source cannot be played" : problem}}.dump();
  }
  const int now = lab.run().animator()->frame();
  const int first = std::max(0, now - frames + 1);
  const auto frame_json = [](int frame, const auto& levels, int drawn, double error, double time_ms,
                             double work) {
    return json{{"frame", frame},
                {"levels", json(std::vector<int>(levels.begin(), levels.end()))},
                {"error_px", drawn > 0 ? json(error) : json()},
                {"time_ms", time_ms},
                {"model_work", work}};
  };
  const auto finite_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(); };
  const bool comparing = shows_compared(lab);
  json runs = json::array();
  json result = {{"first", first}, {"last", now}, {"comparing", comparing}};
  if (comparing) {
    for (const ComparedRun& run : lab.comparison().runs()) {
      if (!run.problem.empty()) return json{{"problem", run.problem}}.dump();
      json list = json::array();
      for (const ComparedFrame& f : run.history) {
        if (f.frame >= first && f.frame <= now) {
          list.push_back(frame_json(f.frame, f.levels, f.drawn(), f.max_measured_error_px,
                                    f.time_ms, f.model_work));
        }
      }
      runs.push_back({{"policy", run.policy->name}, {"frames", list}});
    }
  } else {
    const std::vector<AnimationFrame>& history = lab.run().history();
    json list = json::array();
    for (int k = first; k <= now && k < int(history.size()); ++k) {
      const AnimationFrame& f = history[std::size_t(k)];
      json item =
          frame_json(k, f.levels, f.drawn(), f.max_measured_error_px, f.time_ms, f.model_work);
      item["approximated_percent"] = f.drawn() > 0 ? json(approximated_percent(f)) : json();
      json budgets = json::array();
      for (int level = 0; level < kTermCount; ++level) {
        budgets.push_back(finite_or_null(level_budget_at(f, level)));
      }
      item["budgets"] = budgets;
      list.push_back(item);
    }
    runs.push_back({{"policy", model_name(lab.run())}, {"frames", list}});
    result["thresholds"] = lab.run().settings().thresholds;
  }
  result["runs"] = runs;
  return result.dump();
}

}  // namespace oflab
