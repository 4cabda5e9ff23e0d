#include "app/lesson_check.h"

#include <QApplication>
#include <QLabel>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "adapters/flow_parts.h"
#include "app/main_window.h"
#include "models/animation_model.h"
#include "models/basis_explorer.h"
#include "models/policy_comparison.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "views/analysis_view.h"
#include "views/animation_view.h"
#include "views/basis_view.h"

namespace oflab {
namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

double coefficient(const SceneModel& scene, const std::string& term) {
  const PlanarFlowCoefficients c =
      planar_flow_coefficients(scene.scene().camera, scene.current_pose(), scene.current_motion());
  const std::pair<const char*, double> terms[] = {{"tx", c.tx},   {"ty", c.ty},   {"j11", c.j11},
                                                  {"j12", c.j12}, {"j21", c.j21}, {"j22", c.j22},
                                                  {"px", c.px},   {"py", c.py}};
  for (const auto& [name, value] : terms) {
    if (term == name) return std::abs(value);
  }
  return kUnknown;
}

// The largest |flow| of a part over the plane's image (8-pixel grid), px/s.
double largest_flow(const SceneModel& scene, const std::string& key) {
  FlowPart part;
  if (!parse_flow_part(key, &part)) return kUnknown;
  const FlowContext context =
      make_flow_context(scene.scene().camera, scene.current_pose(), scene.current_motion());
  double largest = 0.0;
  for (const FlowSample& s : sample_flow_grid(context, part, 8.0)) {
    largest = std::max(largest, double(glm::length(s.flow)));
  }
  return largest;
}

// The compared run of the policy named `name`, at the model's frame; nullptr when no
// compared policy has that name.
const ComparedRun* compared_run(WindowModel& model, const std::string& name) {
  for (const ComparedRun& run : model.comparison().runs()) {
    if (run.policy->name == name) return &run;
  }
  return nullptr;
}

// Levels and errors of frames 1 .. now of the engine or of a compared policy: calls
// `each(levels, error)` per frame; false when `of` names no such run.
template <class Each>
bool for_each_played(WindowModel& model, const std::string& of, Each each) {
  if (of == "engine") {
    for (const AnimationFrame& f : model.animation()->history()) {
      if (f.frame > 0) each(f.levels, f.max_measured_error_px);
    }
    return true;
  }
  const ComparedRun* run = compared_run(model, of);
  if (!run) return false;
  for (const ComparedFrame& f : run->history) {
    if (f.frame > 0) each(f.levels, f.max_measured_error_px);
  }
  return true;
}

double level_share(WindowModel& model, const LessonClaim& claim) {
  Level level;
  if (!parse_level(claim.level, &level)) return kUnknown;
  double at_level = 0.0, drawn = 0.0;
  const bool found = for_each_played(model, claim.of, [&](const auto& levels, double) {
    for (int k = 0; k < kLevelCount; ++k) drawn += levels[size_t(k)];
    at_level += levels[size_t(level)];
  });
  return found && drawn > 0 ? at_level / drawn : kUnknown;
}

double max_error(WindowModel& model, const std::string& of) {
  double largest = 0.0;
  const bool found = for_each_played(
      model, of, [&](const auto&, double error) { largest = std::max(largest, error); });
  return found ? largest : kUnknown;
}

// The frame shown now and its animator, of the engine (`of` "engine") or of a compared
// policy (`of` its name); false when `of` names no such run or it cannot play.
bool shown_run(WindowModel& model, const std::string& of, const AnimationFrame** frame,
               const Animator** animator) {
  if (of == "engine") {
    *frame = &model.animation()->current();
    *animator = model.animation()->animator();
    return *animator != nullptr;
  }
  const ComparedRun* run = compared_run(model, of);
  if (!run || !run->animator) return false;
  *frame = &run->last;
  *animator = run->animator.get();
  return true;
}

double hole_pixels(WindowModel& model, const std::string& of) {
  const AnimationFrame* frame = nullptr;
  const Animator* animator = nullptr;
  return shown_run(model, of, &frame, &animator) ? double(frame->hole_pixels) : kUnknown;
}

// The mean measured error of the nearer half of the layers drawn now (by the depth of each
// polygon's centre in the viewer frame) over that of the farther half: above 1 when the
// error grows with inverse depth, below 1 when it falls. Infinite when only the nearer half
// has an error; NaN with fewer than two layers with an error, or none at all.
double near_far_error(WindowModel& model, const std::string& of) {
  const AnimationFrame* frame = nullptr;
  const Animator* animator = nullptr;
  if (!shown_run(model, of, &frame, &animator)) return kUnknown;
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

// The share of the exact frame's pixels that something covers (alpha > 0).
double exact_drawn(AnimationView* view) {
  view->render_image();
  const Image& exact = view->exact_image();
  if (exact.empty()) return 0.0;
  std::size_t covered = 0;
  for (const Pixel& p : exact.pixels()) covered += p.a > 0;
  return double(covered) / double(exact.pixel_count());
}

double heat_map_width(MainWindow* window, AnimationView* view) {
  view->render_image();
  const int policies = int(window->model()->comparison().policies().size());
  const std::vector<QRectF>& rects = view->panel_rects();
  if (window->model()->panel_display() != PanelDisplay::kComparison ||
      int(rects.size()) < 2 * policies + 1) {
    return 0.0;
  }
  double narrowest = 1e300;
  for (size_t k = rects.size() - size_t(policies); k < rects.size(); ++k) {
    narrowest = std::min(narrowest, rects[k].width());
  }
  return narrowest;
}

// Texts of the animation view that are elided, leave its canvas or overlap another.
double cut_texts(AnimationView* view) {
  view->render_image();
  return double(view->text_problems().size());
}

// How often the analysis view's budget chart of `claim.level` crosses its threshold upwards
// over the frames it charts (AnalysisView::threshold_crossings).
double threshold_crossings(MainWindow* window, const LessonClaim& claim) {
  auto* analysis = qobject_cast<AnalysisView*>(window->view(QStringLiteral("analysis")));
  Level level;
  if (!analysis || !parse_level(claim.level, &level)) return kUnknown;
  analysis->render_image();
  const int crossings = analysis->threshold_crossings(int(level));
  return crossings < 0 ? kUnknown : crossings;
}

// The pixels compared policy `of` has written over frames 0 .. now (its caption's "run N px")
// over those of policy `over`.
double run_pixels_ratio(WindowModel& model, const LessonClaim& claim) {
  const ComparedRun* of = compared_run(model, claim.of);
  const ComparedRun* over = compared_run(model, claim.over);
  if (!of || !over || over->pixels_written <= 0) return kUnknown;
  return double(of->pixels_written) / double(over->pixels_written);
}

// 1 when the lesson caption's banner is shorter than its wrapped text needs (its last lines
// cut off), else 0.
double caption_cut(MainWindow* window) {
  const auto* banner = window->findChild<QLabel*>(QStringLiteral("caption_banner"));
  if (!banner || !banner->isVisible()) return 0.0;
  return banner->height() < banner->heightForWidth(banner->width()) ? 1.0 : 0.0;
}

// The claims of the basis explorer, measured on what the basis view shows; NaN for another
// kind, or when the view is not there.
double explorer_claim(MainWindow* window, const LessonClaim& claim) {
  auto* basis = qobject_cast<BasisView*>(window->view(QStringLiteral("basis")));
  if (!basis) return kUnknown;
  basis->render_image();
  const std::string& kind = claim.claim;
  if (kind == "tile_active") return basis->tile_active(claim.of);
  WindowModel& model = *window->model();
  const Camera& camera = model.scene()->scene().camera;
  const ExplorerResult result = explore(model.explorer_terms(), camera);
  if (kind == "solution_count") return double(result.inverse.solutions.size());
  if (kind == "futures_apart_frame") {
    return result.futures_played ? result.futures.first_frame_apart : -1.0;
  }
  if (kind == "futures_first_px") {
    return result.futures_played && result.futures.frames_played >= 1
               ? result.futures.corner_distance_px[1]
               : kUnknown;
  }
  double value = kUnknown;
  if (kind == "grid_change") {
    grid_change_field(explorer_grid_change(model.explorer_terms(), camera), claim.of, &value);
  }
  return value;
}

std::string number_text(double v) {
  std::ostringstream out;
  out.precision(4);
  out << v;
  return out.str();
}

}  // namespace

double measure_claim(MainWindow* window, const LessonClaim& claim) {
  if (ViewPage* page = window->current_view()) page->render_image();
  QApplication::processEvents();
  WindowModel& model = *window->model();
  auto* animation = qobject_cast<AnimationView*>(window->view(QStringLiteral("animation")));
  const std::string& kind = claim.claim;
  if (kind == "coefficient") return coefficient(*model.scene(), claim.of);
  if (kind == "flow_ratio") {
    const double over = largest_flow(*model.scene(), claim.over);
    return over > 0 ? largest_flow(*model.scene(), claim.of) / over : kUnknown;
  }
  if (kind == "level_share") return level_share(model, claim);
  if (kind == "max_error") return max_error(model, claim.of);
  if (kind == "exact_drawn") return animation ? exact_drawn(animation) : kUnknown;
  if (kind == "heat_map_width") return animation ? heat_map_width(window, animation) : kUnknown;
  if (kind == "hole_pixels") return hole_pixels(model, claim.of);
  if (kind == "hole_map_pixels") {
    if (!animation) return kUnknown;
    animation->render_image();
    return double(animation->hole_map_pixels());
  }
  if (kind == "near_far_error") return near_far_error(model, claim.of);
  if (kind == "cut_texts") return animation ? cut_texts(animation) : kUnknown;
  if (kind == "active_tiles") {
    auto* basis = qobject_cast<BasisView*>(window->view(QStringLiteral("basis")));
    if (!basis) return kUnknown;
    basis->render_image();
    return basis->active_tile_count();
  }
  if (kind == "threshold_crossings") return threshold_crossings(window, claim);
  if (kind == "run_pixels_ratio") return run_pixels_ratio(model, claim);
  if (kind == "caption_cut") return caption_cut(window);
  if (kind == "view") return window->current_view_name().toStdString() == claim.of ? 1.0 : 0.0;
  return explorer_claim(window, claim);
}

std::vector<ClaimCheck> check_lesson(MainWindow* window, const Lesson& lesson,
                                     const std::function<void(int)>& after_part) {
  std::vector<ClaimCheck> checks;
  // Every part's caption must be readable whole, whatever the part claims besides.
  LessonClaim whole_caption;
  whole_caption.says = "the caption shows its whole text";
  whole_caption.claim = "caption_cut";
  whole_caption.at_most = 0;
  const auto check_all = [&](int step, std::vector<LessonClaim> claims) {
    claims.push_back(whole_caption);
    for (const LessonClaim& claim : claims) {
      const double measured = measure_claim(window, claim);
      const bool holds = measured >= claim.at_least && measured <= claim.at_most;
      checks.push_back({step, claim, measured, holds});
    }
  };
  window->go_to_lesson_step(lesson, 0);
  check_all(0, lesson.claims);
  if (after_part) after_part(0);
  for (size_t k = 0; k < lesson.steps.size(); ++k) {
    window->perform_lesson_step(lesson, int(k) + 1);
    check_all(int(k) + 1, lesson.steps[k].claims);
    if (after_part) after_part(int(k) + 1);
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

}  // namespace oflab
