#include "player/engine_claims.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "basis/basis_explorer.h"
#include "display/flow_parts.h"
#include "experiments/sampling_comparison.h"
#include "flow/flow_field.h"
#include "lessons/claim_kinds.h"
#include "player/animation_sources.h"
#include "player/lab.h"
#include "runs/statistics.h"
#include "study/engine_display.h"
#include "study/study_analysis.h"

namespace oflab {
namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

double coefficient(Lab& lab, const LessonClaim& claim) {
  const PlanarFlowCoefficients c = planar_flow_coefficients(
      lab.panel().scene().camera, lab.panel().current_pose(), lab.panel().current_motion());
  const std::pair<const char*, double> terms[] = {{"tx", c.tx},   {"ty", c.ty},   {"j11", c.j11},
                                                  {"j12", c.j12}, {"j21", c.j21}, {"j22", c.j22},
                                                  {"px", c.px},   {"py", c.py}};
  for (const auto& [name, value] : terms) {
    if (claim.of == name) return std::abs(value);
  }
  return kUnknown;
}

// The largest |flow| of a part over the plane's image (8-pixel grid), px/s.
double largest_flow(Lab& lab, const std::string& key) {
  FlowPart part;
  if (!parse_flow_part(key, &part)) return kUnknown;
  const FlowContext context = make_flow_context(
      lab.panel().scene().camera, lab.panel().current_pose(), lab.panel().current_motion());
  double largest = 0.0;
  for (const FlowSample& s : sample_flow_grid(context, part, 8.0)) {
    largest = std::max(largest, double(glm::length(s.flow)));
  }
  return largest;
}

double flow_ratio(Lab& lab, const LessonClaim& claim) {
  const double over = largest_flow(lab, claim.over);
  return over > 0 ? largest_flow(lab, claim.of) / over : kUnknown;
}

// The compared run of the policy named `name` at the lab's frame; nullptr when no compared
// policy has that name.
const ComparedRun* compared_run(Lab& lab, const std::string& name) {
  for (const ComparedRun& run : lab.comparison().runs()) {
    if (run.policy->name == name) return &run;
  }
  return nullptr;
}

// Levels and errors of frames 1 .. now of the engine or of a compared policy: calls
// `each(levels, error)` per frame; false when `of` names no such run.
template <class Each>
bool for_each_played(Lab& lab, const std::string& of, Each each) {
  if (of == "engine") {
    for (const AnimationFrame& f : lab.run().history()) {
      if (f.frame > 0) each(f.levels, f.max_measured_error_px);
    }
    return true;
  }
  const ComparedRun* run = compared_run(lab, of);
  if (!run) return false;
  for (const ComparedFrame& f : run->history) {
    if (f.frame > 0) each(f.levels, f.max_measured_error_px);
  }
  return true;
}

double level_share(Lab& lab, const LessonClaim& claim) {
  Level level;
  if (!parse_level(claim.level, &level)) return kUnknown;
  double at_level = 0.0, drawn = 0.0;
  const bool found = for_each_played(lab, claim.of, [&](const auto& levels, double) {
    for (int k = 0; k < kLevelCount; ++k) drawn += levels[size_t(k)];
    at_level += levels[size_t(level)];
  });
  return found && drawn > 0 ? at_level / drawn : kUnknown;
}

double max_error(Lab& lab, const LessonClaim& claim) {
  double largest = 0.0;
  const bool found = for_each_played(
      lab, claim.of, [&](const auto&, double error) { largest = std::max(largest, error); });
  return found ? largest : kUnknown;
}

// The frame shown now and its animator, of the engine (`of` "engine") or of a compared
// policy (`of` its name); false when `of` names no such run or it cannot play.
bool shown_run(Lab& lab, const std::string& of, const AnimationFrame** frame,
               const Animator** animator) {
  if (of == "engine") {
    *animator = lab.run().animator();
    if (!*animator) return false;
    *frame = &lab.run().current();
    return true;
  }
  const ComparedRun* run = compared_run(lab, of);
  if (!run || !run->animator()) return false;
  *frame = &run->last;
  *animator = run->animator();
  return true;
}

// The largest measured error (corners against the exact projection, px) of the layers of
// the frame shown now; 0 at frame 0 or with nothing drawn.
double frame_error(Lab& lab, const LessonClaim& claim) {
  const AnimationFrame* frame = nullptr;
  const Animator* animator = nullptr;
  return shown_run(lab, claim.of, &frame, &animator) ? frame->max_measured_error_px : kUnknown;
}

// The largest photometric error (grey levels) of a layer of the frame shown now.
double photometric_error(Lab& lab, const LessonClaim& claim) {
  const AnimationFrame* frame = nullptr;
  const Animator* animator = nullptr;
  return shown_run(lab, claim.of, &frame, &animator) ? frame->max_photometric_error : kUnknown;
}

double hole_pixels(Lab& lab, const LessonClaim& claim) {
  const AnimationFrame* frame = nullptr;
  const Animator* animator = nullptr;
  return shown_run(lab, claim.of, &frame, &animator) ? double(frame->hole_pixels) : kUnknown;
}

// The mean measured error of the nearer half of the layers drawn now (by the depth of each
// polygon's centre in the viewer frame) over that of the farther half: above 1 when the
// error grows with inverse depth. Infinite when only the nearer half has an error; NaN with
// fewer than two layers with an error, or none at all.
double near_far_error(Lab& lab, const LessonClaim& claim) {
  const AnimationFrame* frame = nullptr;
  const Animator* animator = nullptr;
  if (!shown_run(lab, claim.of, &frame, &animator)) return kUnknown;
  std::vector<std::pair<double, double>> by_depth;  // (depth Z, error px)
  const ViewerPose view = animator->view();
  for (const LayerOutline& layer : animator->outlines()) {
    if (!std::isfinite(layer.error_px)) continue;
    const ScenePolygon& polygon = animator->scene().polygons.at(size_t(layer.polygon));
    by_depth.emplace_back(to_view(view, polygon.centre).z, layer.error_px);
  }
  const size_t half = by_depth.size() / 2;
  if (half == 0) return kUnknown;
  std::sort(by_depth.begin(), by_depth.end());
  double near = 0.0, far = 0.0;
  for (size_t k = 0; k < half; ++k) {
    near += by_depth[k].second;
    far += by_depth[by_depth.size() - 1 - k].second;
  }
  if (far <= 0.0) return near > 0.0 ? std::numeric_limits<double>::infinity() : kUnknown;
  return near / far;
}

// The pixels compared policy `of` has written over frames 0 .. now over those of `over`.
double run_pixels_ratio(Lab& lab, const LessonClaim& claim) {
  const ComparedRun* of = compared_run(lab, claim.of);
  const ComparedRun* over = compared_run(lab, claim.over);
  if (!of || !over || over->pixels_written <= 0) return kUnknown;
  return double(of->pixels_written) / double(over->pixels_written);
}

// The pixels `of` (engine or a compared policy) wrote in each of frames 1 .. now; false when
// `of` names no such run.
bool frame_pixels(Lab& lab, const std::string& of, std::vector<std::int64_t>* pixels) {
  if (of == "engine") {
    for (const AnimationFrame& f : lab.run().history()) {
      if (f.frame > 0) pixels->push_back(f.pixels_written);
    }
    return true;
  }
  const ComparedRun* run = compared_run(lab, of);
  if (!run) return false;
  for (const ComparedFrame& f : run->history) {
    if (f.frame > 0) pixels->push_back(f.pixels_written);
  }
  return true;
}

// The 95th percentile of the pixels `of` wrote per frame over that of `over`.
double frame_pixels_p95_ratio(Lab& lab, const LessonClaim& claim) {
  std::vector<std::int64_t> of, over;
  if (!frame_pixels(lab, claim.of, &of) || !frame_pixels(lab, claim.over, &over)) return kUnknown;
  const std::int64_t below = nearest_rank_percentile(over, 95.0);
  return below > 0 ? double(nearest_rank_percentile(of, 95.0)) / double(below) : kUnknown;
}

double max_error_gap(Lab& lab, const LessonClaim& claim) {
  LessonClaim over = claim;
  over.of = claim.over;
  return std::abs(max_error(lab, claim) - max_error(lab, over));
}

// The pixels `of` has warped and written over frames 0 .. now; false when `of` names no run.
bool pixels_warped_and_written(Lab& lab, const std::string& of, std::int64_t* warped,
                               std::int64_t* written) {
  *warped = *written = 0;
  if (of == "engine") {
    for (const AnimationFrame& f : lab.run().history()) {
      *written += f.pixels_written;
      *warped += f.pixels_written - f.pixels_not_warped;
    }
    return true;
  }
  const ComparedRun* run = compared_run(lab, of);
  if (!run || !run->animator()) return false;
  *warped = run->pixels_warped;
  *written = run->pixels_written;
  return true;
}

double pixels_warped_share(Lab& lab, const LessonClaim& claim) {
  std::int64_t warped = 0, written = 0;
  if (!pixels_warped_and_written(lab, claim.of, &warped, &written) || written <= 0) return kUnknown;
  return double(warped) / double(written);
}

// The run of `of` played afresh from frame 0 to now twice, with the lab's warp and with every
// layer warped whole; the pixels in which their frames differ, summed over the frames.
double whole_warp_difference(Lab& lab, const LessonClaim& claim) {
  const AnimationFrame* shown = nullptr;
  const Animator* animator = nullptr;
  if (!shown_run(lab, claim.of, &shown, &animator)) return kUnknown;
  EngineSettings settings = lab.run().settings();
  if (claim.of != "engine") settings.policy = &reuse_policy(claim.of);
  EngineSettings whole_settings = settings;
  whole_settings.warp_area = WarpArea::kWhole;
  const AnimationSourceKind& kind = lab.run().source_kind();
  const auto as_played = kind.make(lab.run().source(), lab.panel(), settings);
  const auto whole = kind.make(lab.run().source(), lab.panel(), whole_settings);
  const std::int64_t differing = differing_pixels(*as_played, *whole, animator->frame());
  return differing >= 0 ? double(differing) : kUnknown;
}

ExplorerResult explored(Lab& lab) {
  return explore(lab.values().explorer_terms, lab.panel().scene().camera);
}

double grid_change(Lab& lab, const LessonClaim& claim) {
  double value = kUnknown;
  grid_change_field(explorer_grid_change(lab.values().explorer_terms, lab.panel().scene().camera),
                    claim.of, &value);
  return value;
}

// max_error over the largest of the four thresholds of the lab's settings (the engine's and
// the compared runs' alike).
double error_over_threshold(Lab& lab, const LessonClaim& claim) {
  const TermArray& t = lab.run().settings().thresholds;
  const double largest = *std::max_element(t.begin(), t.end());
  return largest > 0.0 ? max_error(lab, claim) / largest : kUnknown;
}

// The smallest or largest error (`of` min or max) the engine shows in the study the lab's
// state opens, over its conditions' ladders, px; NaN without a study.
double study_errors(Lab& lab, const LessonClaim& claim) {
  if (lab.values().study_open.empty()) return kUnknown;
  double low = 1e300, high = 0.0;
  for (const ErrorLadder& ladder : study_ladders(find_or_read_study(lab.values().study_open))) {
    for (double px : ladder.measured_px) {
      low = std::min(low, px);
      high = std::max(high, px);
    }
  }
  return claim.of == "min" ? low : claim.of == "max" ? high : kUnknown;
}

// The median fitted threshold of 100 simulated observers of threshold `of` px run through the
// study the lab's state opens, over `of`: the condition farthest from 1 on a log scale.
double study_recovery(Lab& lab, const LessonClaim& claim) {
  if (lab.values().study_open.empty()) return kUnknown;
  const Study study = find_or_read_study(lab.values().study_open);
  SimulationSettings settings;
  settings.sessions = 100;
  settings.seed = study.seed;
  settings.observer =
      PsychometricFunction{std::stod(claim.of), study.assumed_slope, study.assumed_lapse};
  settings.methods = {study.method};
  settings.replicates = 20;  // the intervals are not claimed: the fewest refits
  settings.display = engine_error_display(study);
  double farthest = kUnknown;
  for (const SimulationSummary& s : simulate_study(study, settings)) {
    const double ratio = s.median_threshold_px / settings.observer.threshold_px;
    if (std::isnan(farthest) || std::abs(std::log(ratio)) > std::abs(std::log(farthest)))
      farthest = ratio;
  }
  return farthest;
}

// Mipmap's mean PSNR over bilinear's (dB) on the minified reused frames of the lab's plane
// script, with the texture it shows and its engine settings, as the sampling experiment
// measures it (experiments/sampling_comparison.h; the times are not claimed: one pass), to
// 0.01 dB as the experiment prints it (the page's SIMD kernels round a few pixels differently:
// 4.898 there, 4.897 here); NaN for a source that plays no plane script.
double sampling_psnr_gain(Lab& lab, const LessonClaim&) {
  const SourceChoice& source = lab.run().source();
  const AnimationSourceKind* kind = find_animation_source_kind(source.kind);
  if (!kind || !kind->plane_script) return kUnknown;
  SamplingSpec spec;
  spec.script = source.name;
  spec.timing_passes = 1;
  const double gain =
      compare_samplings(make_layer(lab.panel().texture()), kind->plane_script(source, lab.panel()),
                        lab.run().settings(), spec)
          .mipmap_gain_db();
  return std::round(gain * 100.0) / 100.0;
}

std::map<std::string, EngineMeasure> make_measures() {
  return {
      {"coefficient", coefficient},
      {"flow_ratio", flow_ratio},
      {"level_share", level_share},
      {"max_error", max_error},
      {"frame_error", frame_error},
      {"photometric_error", photometric_error},
      {"hole_pixels", hole_pixels},
      {"near_far_error", near_far_error},
      {"view",
       [](Lab& lab, const LessonClaim& c) { return lab.values().view == c.of ? 1.0 : 0.0; }},
      {"run_pixels_ratio", run_pixels_ratio},
      {"frame_pixels_p95_ratio", frame_pixels_p95_ratio},
      {"max_error_gap", max_error_gap},
      {"pixels_warped_share", pixels_warped_share},
      {"whole_warp_difference", whole_warp_difference},
      {"solution_count",
       [](Lab& lab, const LessonClaim&) { return double(explored(lab).inverse.solutions.size()); }},
      {"futures_apart_frame",
       [](Lab& lab, const LessonClaim&) {
         const ExplorerResult r = explored(lab);
         return r.futures_played ? double(r.futures.first_frame_apart) : -1.0;
       }},
      {"futures_first_px",
       [](Lab& lab, const LessonClaim&) {
         const ExplorerResult r = explored(lab);
         return r.futures_played && r.futures.frames_played >= 1 ? r.futures.corner_distance_px[1]
                                                                 : kUnknown;
       }},
      {"grid_change", grid_change},
      {"error_over_threshold", error_over_threshold},
      {"study_errors", study_errors},
      {"study_recovery", study_recovery},
      {"sampling_psnr_gain", sampling_psnr_gain},
  };
}

std::string number_text(double v) {
  std::ostringstream out;
  out.precision(4);
  out << v;
  return out.str();
}

}  // namespace

const std::map<std::string, EngineMeasure>& engine_claim_measures() {
  static const std::map<std::string, EngineMeasure> measures = make_measures();
  return measures;
}

double measure_engine_claim(Lab& lab, const LessonClaim& claim) {
  const auto it = engine_claim_measures().find(claim.claim);
  return it == engine_claim_measures().end() ? kUnknown : it->second(lab, claim);
}

std::int64_t differing_pixels(Animator& a, Animator& b, int last_frame) {
  std::int64_t differing = 0;
  for (int k = 0; k <= last_frame; ++k) {
    if (k == 0) a.start(), b.start();
    if (k > 0) a.advance(), b.advance();
    const std::vector<Pixel>& p = a.image().pixels();
    const std::vector<Pixel>& q = b.image().pixels();
    if (p.size() != q.size()) return -1;
    for (size_t i = 0; i < p.size(); ++i) differing += p[i] != q[i];
  }
  return differing;
}

WindowState LabStage::stage_state() const { return lab_->state(); }
std::string LabStage::stage_apply(const WindowState& state) { return lab_->apply(state); }
void LabStage::stage_stop() { lab_->values().playing = false; }
void LabStage::stage_seek(int frame) { lab_->panel().set_frame(frame); }

int LabStage::stage_loop_frames() const { return lab_->panel().loop_frames(); }
void LabStage::stage_play(int frames) {
  for (int k = 0; k < frames; ++k) lab_->panel().set_frame(lab_->panel().frame() + 1);
}
void LabStage::stage_set_step(int step) { lab_->values().lesson_step = step; }

std::vector<ClaimCheck> check_lesson_claims(
    LessonStage& stage, const Lesson& lesson,
    const std::function<std::optional<double>(const LessonClaim&)>& measure,
    const std::vector<LessonClaim>& every_part, const std::function<void(int)>& after_part) {
  std::vector<ClaimCheck> checks;
  const auto check_all = [&](int step, std::vector<LessonClaim> claims) {
    claims.insert(claims.end(), every_part.begin(), every_part.end());
    for (const LessonClaim& claim : claims) {
      const std::optional<double> measured = measure(claim);
      if (!measured) continue;
      checks.push_back(
          {step, claim, *measured, *measured >= claim.at_least && *measured <= claim.at_most});
    }
    if (after_part) after_part(step);
  };
  std::string problem = go_to_lesson_step(stage, lesson, 0);
  if (!problem.empty()) throw std::runtime_error(problem);
  check_all(0, lesson.claims);
  for (size_t k = 0; k < lesson.steps.size(); ++k) {
    problem = perform_lesson_step(stage, lesson, int(k) + 1);
    if (!problem.empty()) throw std::runtime_error(problem);
    check_all(int(k) + 1, lesson.steps[k].claims);
  }
  return checks;
}

std::string describe(const Lesson& lesson, const ClaimCheck& check) {
  const LessonClaim& c = check.claim;
  std::string what = c.claim;
  if (!c.of.empty()) what += " " + c.of + (c.over.empty() ? "" : "/" + c.over);
  if (!c.level.empty()) what += " at " + c.level;
  std::string claimed;
  if (c.at_least > -1e300) claimed += "at least " + number_text(c.at_least);
  if (c.at_most < 1e300) {
    claimed += std::string(claimed.empty() ? "" : " and ") + "at most " + number_text(c.at_most);
  }
  return lesson.name + ", " +
         (check.step == 0 ? std::string("narrative") : "step " + std::to_string(check.step)) +
         ": \"" + c.says + "\" (" + what + ") measured " + number_text(check.measured) +
         ", claimed " + claimed + ": " + (check.holds ? "holds" : "FALSE");
}

std::vector<ClaimCheck> check_engine_claims(const Lesson& lesson, int* screen_claims) {
  Lab lab(shipped_default_texture());
  LabStage stage(&lab);
  const auto measure = [&](const LessonClaim& claim) -> std::optional<double> {
    const ClaimKind* kind = find_claim_kind(claim.claim);
    if (!kind || kind->source != ClaimSource::kEngine) {
      if (screen_claims) ++*screen_claims;
      return std::nullopt;
    }
    return measure_engine_claim(lab, claim);
  };
  return check_lesson_claims(stage, lesson, measure);
}

}  // namespace oflab
