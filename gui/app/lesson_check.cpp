#include "app/lesson_check.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "app/main_window.h"
#include "lessons/claim_kinds.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "views/analysis_view.h"
#include "views/animation_view.h"
#include "views/basis_view.h"
#include "views/flow_view.h"
#include "views/study_window.h"
#include "views/world_view.h"

namespace oflab {
namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

// The share of the exact frame's pixels that something covers (alpha > 0).
double exact_drawn(AnimationView* view) {
  view->render_image();
  const Image& exact = view->exact_image();
  if (exact.empty()) return 0.0;
  std::size_t covered = 0;
  for (const Pixel& p : exact.pixels()) covered += p.a > 0;
  return double(covered) / double(exact.pixel_count());
}

// The narrowest width of the frame's content as drawn on the comparison's heat maps (the
// last `policies` panels), in pixels of the 1920 x 1080 look: canvas pixels over the
// presentation scale (ViewTheme::scale, 1 in the normal look); 0 outside the comparison.
double heat_map_width(MainWindow* window, AnimationView* view) {
  view->render_image();
  const int policies = int(window->model()->comparison().policies().size());
  const std::vector<QRectF> drawn = view->drawn_content_rects();
  if (window->model()->panel_display() != PanelDisplay::kComparison ||
      int(drawn.size()) < 2 * policies + 1) {
    return 0.0;
  }
  double narrowest = 1e300;
  for (size_t k = drawn.size() - size_t(policies); k < drawn.size(); ++k) {
    narrowest = std::min(narrowest, drawn[k].width());
  }
  return narrowest / window->theme().scale;
}

// The views in front: those of the cause-and-effect layout, else the current one.
std::vector<ViewPage*> shown_views(MainWindow* window) {
  return window->model()->cause_and_effect() ? window->layout_views()
                                             : std::vector<ViewPage*>{window->current_view()};
}

// The percent of its panel what a view in front draws covers, the smallest over them: the
// animation view's exact panel (the exact frame's content as drawn), the flow view's scene
// region (the plane's image), the world view's picture between its legend and caption (the hull of
// the plane or the scene, the eye and its image plane), the basis view's tiles (the smallest
// share of a tile inside its deformed square) or, with the explorer, its deformation picture
// (inside the deformed texture rectangle); NaN when none of them is in front.
double panel_fill(MainWindow* window) {
  double smallest = kUnknown;
  for (ViewPage* page : shown_views(window)) {
    double fill = kUnknown;
    if (auto* animation = qobject_cast<AnimationView*>(page)) {
      animation->render_image();
      fill = animation->content_fill();
    } else if (auto* flow = qobject_cast<FlowView*>(page)) {
      fill = flow->plane_share();
    } else if (auto* world = qobject_cast<WorldView*>(page)) {
      fill = world->drawn_share();
    } else if (auto* basis = qobject_cast<BasisView*>(page)) {
      fill = basis->drawn_share();
    }
    if (!std::isnan(fill))
      smallest = std::isnan(smallest) ? 100.0 * fill : std::min(smallest, 100.0 * fill);
  }
  return smallest;
}

// Texts that are elided, leave their canvas or overlap another: of the world view, the basis
// view (its explorer) or the analysis view when one of them shows (in front, or in the
// cause-and-effect layout), else of the animation view.
double cut_texts(MainWindow* window) {
  const std::vector<ViewPage*> shown = shown_views(window);
  bool measured = false;
  double problems = 0.0;
  for (ViewPage* page : shown) {
    if (auto* world = qobject_cast<WorldView*>(page)) {
      world->render_image();
      problems += double(world->text_problems().size());
      measured = true;
    } else if (auto* basis = qobject_cast<BasisView*>(page)) {
      basis->render_image();
      problems += double(basis->text_problems().size());
      measured = true;
    } else if (auto* analysis = qobject_cast<AnalysisView*>(page)) {
      analysis->render_image();
      problems += double(analysis->text_problems().size());
      measured = true;
    }
  }
  if (measured) return problems;
  auto* animation = qobject_cast<AnimationView*>(window->view(QStringLiteral("animation")));
  if (!animation) return kUnknown;
  animation->render_image();
  return double(animation->text_problems().size());
}

// The world view's labels over its drawn pictures (WorldView::labels_over_content), summed
// over the world views shown; NaN when none is.
double labels_over_content(MainWindow* window) {
  double over = kUnknown;
  for (ViewPage* page : shown_views(window)) {
    if (auto* world = qobject_cast<WorldView*>(page))
      over = (std::isnan(over) ? 0.0 : over) + double(world->labels_over_content().size());
  }
  return over;
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

// 1 when the lesson caption's banner is shorter than its wrapped text needs (its last lines
// cut off), else 0.
double caption_cut(MainWindow* window) {
  const auto* banner = window->findChild<QLabel*>(QStringLiteral("caption_banner"));
  if (!banner || !banner->isVisible()) return 0.0;
  return banner->height() < banner->heightForWidth(banner->width()) ? 1.0 : 0.0;
}

// Frames per second of the window playing on from the part's frame: the engine advanced and
// the view in front drawn frame by frame, as `oflab --benchmark` (gui/app/app_runner.h),
// after a warm-up; the part's frame is shown again afterwards (a replay from its start).
double frame_rate(MainWindow* window) {
  constexpr int kWarmUp = 3, kFrames = 60;
  SceneModel* model = window->model()->scene();
  const int frame = model->frame();
  for (int i = 0; i < kWarmUp; ++i) window->play_frames(1);
  QElapsedTimer timer;
  timer.start();
  for (int i = 0; i < kFrames; ++i) {
    model->advance(1);
    QApplication::processEvents();
  }
  const double seconds = timer.nsecsElapsed() * 1e-9;
  model->set_frame(frame);
  QApplication::processEvents();
  return seconds > 0 ? kFrames / seconds : kUnknown;
}

BasisView* basis_view(MainWindow* window) {
  auto* basis = qobject_cast<BasisView*>(window->view(QStringLiteral("basis")));
  if (basis) basis->render_image();
  return basis;
}

AnimationView* animation_view(MainWindow* window) {
  auto* animation = qobject_cast<AnimationView*>(window->view(QStringLiteral("animation")));
  if (animation) animation->render_image();
  return animation;
}

// 1 when the study window shows its set-up page with study `claim.of` chosen, else 0.
double study_setup(MainWindow* window, const LessonClaim& claim) {
  const StudyWindow* study = window->study_window();
  return study && study->isVisible() && study->setup_study() == claim.of ? 1.0 : 0.0;
}

// The largest difference (px) between the window's four threshold fields as shown and the
// number the study window's "Use X px" button shows; NaN without that button's number.
double study_threshold_gap(MainWindow* window) {
  const StudyWindow* study = window->study_window();
  const auto* use = study ? study->findChild<QPushButton*>("study_use_threshold") : nullptr;
  const QRegularExpressionMatch number =
      QRegularExpression(QStringLiteral("([0-9]+(\\.[0-9]+)?) px")).match(use ? use->text() : "");
  if (!number.hasMatch()) return kUnknown;
  const double offered = number.captured(1).toDouble();
  double gap = kUnknown;
  for (int k = 0; k < kTermCount; ++k) {
    const auto* field =
        window->findChild<QDoubleSpinBox*>(QStringLiteral("animation_threshold_%1").arg(k));
    if (!field) return kUnknown;
    const double shown = QLocale().toDouble(field->text());
    gap = std::isnan(gap) ? std::abs(shown - offered) : std::max(gap, std::abs(shown - offered));
  }
  return gap;
}

using ScreenMeasure = std::function<double(MainWindow*, const LessonClaim&)>;

// A screen measure of the animation view, NaN without one.
ScreenMeasure on_animation(double (*measure)(MainWindow*, AnimationView*)) {
  return [measure](MainWindow* window, const LessonClaim&) {
    AnimationView* view = animation_view(window);
    return view ? measure(window, view) : kUnknown;
  };
}

std::map<std::string, ScreenMeasure> make_screen_measures() {
  return {
      {"exact_drawn", on_animation([](MainWindow*, AnimationView* v) { return exact_drawn(v); })},
      {"heat_map_width", on_animation(heat_map_width)},
      {"hole_map_pixels",
       on_animation([](MainWindow*, AnimationView* v) { return double(v->hole_map_pixels()); })},
      {"panel_fill", [](MainWindow* window, const LessonClaim&) { return panel_fill(window); }},
      {"cut_texts", [](MainWindow* window, const LessonClaim&) { return cut_texts(window); }},
      {"labels_over_content",
       [](MainWindow* window, const LessonClaim&) { return labels_over_content(window); }},
      {"active_tiles",
       [](MainWindow* window, const LessonClaim&) {
         BasisView* basis = basis_view(window);
         return basis ? double(basis->active_tile_count()) : kUnknown;
       }},
      {"threshold_crossings", threshold_crossings},
      {"caption_cut", [](MainWindow* window, const LessonClaim&) { return caption_cut(window); }},
      {"frame_rate", [](MainWindow* window, const LessonClaim&) { return frame_rate(window); }},
      {"tile_active",
       [](MainWindow* window, const LessonClaim& claim) {
         BasisView* basis = basis_view(window);
         return basis ? double(basis->tile_active(claim.of)) : kUnknown;
       }},
      {"study_setup", study_setup},
      {"study_results",
       [](MainWindow* window, const LessonClaim&) {
         const StudyWindow* study = window->study_window();
         return study && study->isVisible() ? double(study->results_shown()) : 0.0;
       }},
      {"study_threshold_gap",
       [](MainWindow* window, const LessonClaim&) { return study_threshold_gap(window); }},
  };
}

// The threshold of the simulated observer who answers a lesson's study in a check, pixels.
constexpr double kCheckObserverPx = 1.0;

// A part that leaves the study window on its set-up page is answered as the class would
// answer it: a simulated observer of kCheckObserverPx (the study's slope and lapse, seeded by
// the study's seed) runs the study to its end in the window (its trials and results, without
// making the clips' pictures: TrialRunner::answer_unseen), then "Use X px" is pressed.
void answer_shown_study(MainWindow* window) {
  StudyWindow* study = window->study_window();
  if (!study || !study->isVisible() || study->setup_study().empty()) return;
  const Study chosen = find_or_read_study(study->setup_study());
  study->set_fields(chosen.method, "simulated", 96.0, chosen.seed);
  SimulatedObserver observer(
      chosen.seed,
      PsychometricFunction{kCheckObserverPx, chosen.assumed_slope, chosen.assumed_lapse});
  if (!study->run_simulated_unseen(observer).empty()) return;
  if (auto* use = study->findChild<QPushButton*>("study_use_threshold")) use->click();
  QApplication::processEvents();
}

}  // namespace

const std::map<std::string, std::function<double(MainWindow*, const LessonClaim&)>>&
screen_claim_measures() {
  static const std::map<std::string, ScreenMeasure> measures = make_screen_measures();
  return measures;
}

double measure_claim(MainWindow* window, const LessonClaim& claim) {
  if (ViewPage* page = window->current_view()) page->render_image();
  // The layouts settled first: a new caption or look (a re-sized font) asks for layouts that
  // ask for more.
  for (int pass = 0; pass < 3; ++pass) {
    QApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QApplication::processEvents();
  }
  const auto screen = screen_claim_measures().find(claim.claim);
  if (screen != screen_claim_measures().end()) return screen->second(window, claim);
  return measure_engine_claim(window->model()->lab(), claim);
}

std::vector<ClaimCheck> check_lesson(MainWindow* window, const Lesson& lesson,
                                     const std::function<void(int)>& after_part, bool time_claims,
                                     const std::vector<std::string>& kinds) {
  // Every part's caption must be readable whole, whatever the part claims besides.
  LessonClaim whole_caption;
  whole_caption.says = "the caption shows its whole text";
  whole_caption.claim = "caption_cut";
  whole_caption.at_most = 0;
  return check_lesson_claims(
      *window, lesson,
      [window, time_claims, &kinds](const LessonClaim& claim) -> std::optional<double> {
        const ClaimKind* kind = find_claim_kind(claim.claim);
        if (kind && kind->timed && !time_claims) return std::nullopt;
        if (!kinds.empty() && std::find(kinds.begin(), kinds.end(), claim.claim) == kinds.end())
          return std::nullopt;
        return measure_claim(window, claim);
      },
      {whole_caption},
      [window, &after_part](int part) {
        if (after_part) after_part(part);
        answer_shown_study(window);
      });
}

}  // namespace oflab
