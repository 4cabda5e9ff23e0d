// The analysis view's charts: a click on any chart (the four budget charts included)
// lands on the frame under the pointer, computed here from the chart's own rectangle; the
// axis stays still after a jump; every chart has a frame axis and the levels chart a
// legend. And the inspector's words for each policy's frames.
#include "views/analysis_view.h"

#include <QApplication>
#include <QPainter>
#include <cmath>

#include "display/palette.h"
#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "flow/geometry.h"
#include "flow/plane_scene.h"
#include "lessons/lessons.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "player/policy_comparison.h"
#include "views/analysis_charts.h"
#include "views/animation_view.h"
#include "views/frame_inspector.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class AnalysisViewTest : public WindowTest {
 protected:
  AnalysisView& analysis() { return *view_page<AnalysisView>(window(), "analysis"); }
  QWidget* charts() { return analysis().findChild<QWidget*>(QStringLiteral("analysis_charts")); }

  // The centre of frame `frame`'s column in chart `index`: its rectangle split into one
  // equal column per frame of the axis.
  QPoint column_centre(int index, int frame) {
    const QRect area = analysis().chart_area(index);
    const int n = analysis().last_frame() - analysis().first_frame() + 1;
    const double x = area.left() + (frame - analysis().first_frame() + 0.5) * area.width() / n;
    return QPoint(int(std::lround(x)), area.center().y());
  }
};

TEST_F(AnalysisViewTest, ClickOnEveryChartLandsOnTheFrameUnderThePointer) {
  window().resize(1920, 1080);
  window().show_view("analysis");
  window().play_frames(40);
  ASSERT_NE(charts(), nullptr);
  ASSERT_EQ(analysis().current_frame(), 40);
  for (int chart = 0; chart < AnalysisView::kChartCount; ++chart) {
    const QRect area = analysis().chart_area(chart);
    ASSERT_TRUE(charts()->rect().contains(area)) << chart;
    for (int frame : {3, 17, 29, 38}) {
      QTest::mouseClick(charts(), Qt::LeftButton, Qt::NoModifier, column_centre(chart, frame));
      EXPECT_EQ(window().model()->scene()->frame(), frame) << "chart " << chart;
    }
  }
}

TEST_F(AnalysisViewTest, ClickBetweenChartsDoesNothing) {
  window().show_view("analysis");
  window().play_frames(12);
  const QRect first = analysis().chart_area(0), second = analysis().chart_area(1);
  const QPoint gap(first.center().x(), (first.bottom() + second.top()) / 2);
  QTest::mouseClick(charts(), Qt::LeftButton, Qt::NoModifier, gap);
  EXPECT_EQ(window().model()->scene()->frame(), 12);
  QTest::mouseClick(charts(), Qt::LeftButton, Qt::NoModifier, QPoint(2, first.center().y()));
  EXPECT_EQ(window().model()->scene()->frame(), 12);
}

TEST_F(AnalysisViewTest, TheAxisStaysStillUnderThePointerAfterAJump) {
  window().show_view("analysis");
  window().play_frames(100);  // past the 80 recent frames: the axis has scrolled
  const int first = analysis().first_frame(), last = analysis().last_frame();
  ASSERT_EQ(last, 100);
  ASSERT_EQ(first, 100 - AnalysisView::kRecentFrames + 1);
  const QPoint target = column_centre(0, 50);
  QTest::mouseClick(charts(), Qt::LeftButton, Qt::NoModifier, target);
  ASSERT_EQ(window().model()->scene()->frame(), 50);
  EXPECT_EQ(analysis().first_frame(), first);
  EXPECT_EQ(analysis().last_frame(), last);
  EXPECT_EQ(analysis().frame_at(target), 50) << "the same place still means the same frame";
  // Playing on within the axis keeps it; past its end it scrolls again.
  window().play_frames(10);
  EXPECT_EQ(analysis().first_frame(), first);
  window().play_frames(45);
  EXPECT_EQ(analysis().last_frame(), 105);
}

TEST_F(AnalysisViewTest, WholeLoopAxisSpansTheLoop) {
  window().show_view("analysis");
  analysis().set_whole_run(true);
  window().play_frames(5);
  EXPECT_EQ(analysis().first_frame(), 0);
  EXPECT_EQ(analysis().last_frame(), window().model()->animation()->animator()->frame_count() - 1);
  EXPECT_EQ(analysis().current_frame(), 5);
}

// The why-errors-accumulate lesson on a 1366 x 768 projector in presentation mode, with the
// scene panel shown and hidden: no chart text is elided, off the charts or over another (a
// linear chart too short for its top and bottom values keeps the top one). The control: a
// window held at 900 x 480 with the scene panel, its charts drawn at the 1920 x 1080 sizes
// (not scaled to the window), cuts some.
TEST_F(AnalysisViewTest, TheLessonsChartsAreLegibleAt1366x768) {
  window().apply_lesson(*find_lesson("why-errors-accumulate"));
  window().model()->set_playing(false);
  window().model()->set_presentation(true);
  window().set_external_clock(true);
  const auto problems = [this] {
    QApplication::processEvents();
    analysis().render_image();
    QString all;
    for (const QString& p : analysis().text_problems()) all += p + QStringLiteral("; ");
    return all.toStdString();
  };
  for (bool scene_panel : {true, false}) {
    window().model()->set_scene_panel(scene_panel);
    window().resize(1366, 768);
    EXPECT_EQ(problems(), "") << (scene_panel ? "with" : "without") << " the scene panel";
  }
  window().model()->set_scene_panel(true);
  window().setFixedSize(900, 480);
  QApplication::processEvents();
  analysis().set_theme(view_theme(true));  // the 1920 x 1080 sizes, unscaled
  EXPECT_NE(problems(), "") << "the control: 900 x 480 at the 1920 x 1080 sizes";
}

TEST(AnalysisFrameTicks, AreRoundFramesFarEnoughApartForTheirLabels) {
  for (int width : {300, 900, 1800}) {
    for (int label : {12, 20}) {
      const std::vector<int> ticks = AnalysisView::frame_ticks(21, 100, width, label);
      ASSERT_GE(ticks.size(), 2u) << width;
      const int step = ticks[1] - ticks[0];
      int base = step;
      while (base % 10 == 0) base /= 10;
      EXPECT_TRUE(base == 1 || base == 2 || base == 5) << step;
      EXPECT_GE(step * double(width) / 80, 3.0 * label);
      for (size_t i = 0; i < ticks.size(); ++i) {
        EXPECT_EQ(ticks[i] % step, 0);
        EXPECT_GE(ticks[i], 21);
        EXPECT_LE(ticks[i], 100);
        if (i > 0) {
          EXPECT_EQ(ticks[i] - ticks[i - 1], step);
        }
      }
      EXPECT_LT(ticks.front() - step, 21) << "the first round frame is not skipped";
    }
  }
}

// Pixels of exactly `colour` in `area` of `image`.
int count_colour(const QImage& image, const QRect& area, const QColor& colour) {
  int n = 0;
  for (int y = std::max(0, area.top()); y <= std::min(image.height() - 1, area.bottom()); ++y) {
    for (int x = std::max(0, area.left()); x <= std::min(image.width() - 1, area.right()); ++x) {
      n += image.pixelColor(x, y).rgb() == colour.rgb();
    }
  }
  return n;
}

TEST_F(AnalysisViewTest, LevelsChartHasALegendAndEveryChartAFrameAxis) {
  window().resize(1600, 1000);
  window().show_view("analysis");
  window().play_frames(3);  // few frames: the levels' bars cover little of the chart
  QApplication::processEvents();
  const QImage image = analysis().render_image();
  ASSERT_EQ(image.size(), charts()->size());
  const QRect levels = analysis().chart_area(1);
  const int line = QFontMetrics(QFont()).height() + 40;
  const QRect title_strip(levels.left(), levels.top() - line, levels.width(), line);
  for (int level = 0; level < kLevelCount; ++level) {
    const Rgb8 c = level_colour(Level(level));
    EXPECT_GT(count_colour(image, title_strip, QColor(c.r, c.g, c.b)), 20)
        << "no legend swatch for " << level_name(Level(level));
  }
  const QColor background = image.pixelColor(2, image.height() - 2);
  for (int chart = 0; chart < AnalysisView::kChartCount; ++chart) {
    const QRect area = analysis().chart_area(chart);
    const QRect axis(area.left(), area.bottom() + 2, area.width(), 20);
    const int marks = axis.width() * axis.height() - count_colour(image, axis, background);
    EXPECT_GT(marks, 30) << "no ticks or labels under chart " << chart;
  }
}

TEST_F(AnalysisViewTest, BudgetChartsAreTheLargestAndTheFrameTimeChartSmaller) {
  window().resize(1920, 1080);
  window().show_view("analysis");
  window().play_frames(5);
  const auto area = [&](int chart) {
    const QRect r = analysis().chart_area(chart);
    return r.width() * r.height();
  };
  for (int budget = 3; budget < AnalysisView::kChartCount; ++budget) {
    for (int other = 0; other < 3; ++other) {
      EXPECT_GT(area(budget), area(other)) << "budget chart " << budget << ", chart " << other;
    }
    EXPECT_GT(analysis().chart_area(budget).height(), 2 * analysis().chart_area(0).height());
  }
  // No two charts overlap.
  for (int a = 0; a < AnalysisView::kChartCount; ++a) {
    for (int b = 0; b < a; ++b) {
      EXPECT_FALSE(analysis().chart_area(a).intersects(analysis().chart_area(b))) << a << b;
    }
  }
}

// The engine's choice (core/engine/decision.h choose_level): a level whose neglected error
// exceeds its threshold is never chosen, so every frame a budget chart shows above its
// dashed line chose a higher level: there are never more crossings than such frames.
TEST_F(AnalysisViewTest, ThresholdCrossingsAreFramesWhereTheEngineHadToGoHigher) {
  PlaneScene slow = default_demo_scene();
  slow.motion.velocity *= 0.04;
  slow.motion.omega *= 0.04;
  window().model()->scene()->set_scene(slow);
  window().show_view("analysis");
  window().play_frames(79);
  analysis().render_image();
  const std::vector<AnimationFrame>& history = window().model()->animation()->history();
  const EngineSettings& settings = window().model()->animation()->settings();
  for (int level = 0; level < kTermCount; ++level) {
    int went_higher = 0;
    for (size_t k = 1; k < history.size(); ++k) {
      if (history[k].layer_reports.size() != 1) continue;
      const FrameReport& now = history[k].layer_reports.front();
      went_higher += k > 1 && int(now.level) > level;
      if (neglected_error(now.carried, now.flow, Level(level)) >
          settings.thresholds[size_t(level)]) {
        EXPECT_GT(int(now.level), level) << "frame " << k;
      }
    }
    EXPECT_LE(analysis().threshold_crossings(level), went_higher) << level;
  }
  // At this speed none and translate take turns with dearer levels: saw-teeth.
  EXPECT_GE(analysis().threshold_crossings(int(Level::kNone)), 3);
  EXPECT_GE(analysis().threshold_crossings(int(Level::kTranslate)), 3);
  EXPECT_EQ(analysis().threshold_crossings(kTermCount), -1);  // no such chart
}

// ---- The comparison overlaid ----

class AnalysisComparisonTest : public AnalysisViewTest {
 protected:
  // The animation view compares `names` (its comparison layout), the analysis view in front.
  void compare(const std::vector<std::string>& names) {
    window().model()->set_compared(names);
    window().model()->set_panel_display(PanelDisplay::kComparison);
    window().show_view("analysis");
  }
  static QColor policy_qcolor(int index) {
    const Rgb8 c = policy_colour(index);
    return QColor(c.r, c.g, c.b);
  }
};

TEST(PolicyColours, FourDistinctColoursRepeatingAfterTheFourth) {
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < i; ++j) {
      const Rgb8 a = policy_colour(i), b = policy_colour(j);
      EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 100) << i << j;
    }
    EXPECT_EQ(policy_colour(i + 4).r, policy_colour(i).r);
  }
}

// The hue of an 8-bit colour in degrees, and the angle between two hues.
double hue_of(const Rgb8& c) { return QColor(c.r, c.g, c.b).hsvHueF() * 360.0; }
double hue_apart(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

TEST(PolicyColours, KeepClearOfEveryLevelColour) {
  for (int i = 0; i < 4; ++i) {
    const Rgb8 p = policy_colour(i);
    EXPECT_GT(QColor(p.r, p.g, p.b).hsvSaturationF(), 0.5) << "policy " << i << " is greyish";
    for (int level = int(Level::kTranslate); level < kLevelCount; ++level) {
      EXPECT_GE(hue_apart(hue_of(p), hue_of(level_colour(Level(level)))), 40.0)
          << "policy " << i << " near level " << level_name(Level(level));
    }
    for (int j = 0; j < i; ++j) EXPECT_GE(hue_apart(hue_of(p), hue_of(policy_colour(j))), 40.0);
  }
  // Negative control: the red the comparison used before is within 40 degrees of the
  // re-render level's vermillion.
  EXPECT_LT(hue_apart(hue_of(Rgb8{238, 102, 119}), hue_of(level_colour(Level::kRerender))), 40.0);
}

TEST_F(AnalysisComparisonTest, EachComparedPolicyHasItsLineKeyAndLevelBand) {
  window().resize(1600, 1000);
  compare({"perspective", "affine", "rerender"});
  window().play_frames(30);
  QApplication::processEvents();
  ASSERT_TRUE(analysis().comparing());
  ASSERT_EQ(analysis().chart_count(), AnalysisView::kComparisonChartCount);
  const QImage image = analysis().render_image();
  const int line = QFontMetrics(QFont()).height() + 40;
  for (int i = 0; i < 3; ++i) {
    int on_lines = 0;
    for (int chart = 0; chart < 3; ++chart) {
      const QRect area = analysis().chart_area(chart);
      on_lines += count_colour(image, area, policy_qcolor(i));
      const QRect key(area.left(), area.top() - line, area.width(), line);
      EXPECT_GT(count_colour(image, key, policy_qcolor(i)), 20) << "no key of policy " << i;
    }
    EXPECT_GT(on_lines, 100) << "no line of policy " << i;
  }
  for (int chart = 0; chart < 3; ++chart) {  // no fourth series
    EXPECT_EQ(count_colour(image, analysis().chart_area(chart), policy_qcolor(3)), 0) << chart;
  }
  // The bands, top to bottom in panel order, marked in the margin by the policy's colour;
  // the re-render policy's band (the third) is all re-render up to the current frame.
  const QRect bands = analysis().chart_area(3);
  const int band = bands.height() / 3;
  for (int i = 0; i < 3; ++i) {
    const QRect mark(bands.left() - 10, bands.top() + i * band + 2, 6, band - 4);
    EXPECT_GT(count_colour(image, mark, policy_qcolor(i)), mark.width() * mark.height() / 2) << i;
  }
  const Rgb8 r = level_colour(Level::kRerender);
  const double played = (analysis().current_frame() - analysis().first_frame() + 1.0) /
                        (analysis().last_frame() - analysis().first_frame() + 1.0);
  const QRect third(bands.left() + 1, bands.top() + 2 * band + 2, bands.width() - 2, band - 4);
  EXPECT_GT(count_colour(image, third, QColor(r.r, r.g, r.b)),
            0.8 * played * third.width() * third.height());
}

// Four policies, affine among them, on a projector with the scene panel shown and hidden, at
// 1920 x 1080 and 1366 x 768 (presentation mode scaled to the window): no chart text is
// elided, off the charts or overlapping another (a title over its key among them), and the
// error chart takes a log scale, so the perspective policy's line within a pixel is not
// flattened under affine's many pixels.
TEST_F(AnalysisComparisonTest, FourPoliciesWithAffineAreLegibleAndNotFlattened) {
  window().model()->set_presentation(true);
  window().model()->set_playing(false);
  window().set_external_clock(true);
  compare({"affine", "perspective", "talisman", "rerender"});
  window().model()->animation()->set_source({"script", "swing", ""});
  // Delta sqrt, as the affine-vs-perspective lesson plays swing: with the default Delta the
  // perspective policy re-renders every frame and its error line lies flat at zero.
  EngineSettings settings = window().model()->animation()->settings();
  settings.delta = DeltaPolicy::kSqrtAbsDet;
  ASSERT_TRUE(window().model()->animation()->set_settings(settings));
  window().play_frames(60);
  for (const QSize size : {QSize(1920, 1080), QSize(1366, 768)}) {
    for (bool scene_panel : {true, false}) {
      window().resize(size);
      window().model()->set_scene_panel(scene_panel);
      QApplication::processEvents();
      const std::string where = std::to_string(size.width()) + (scene_panel ? " panel" : "");
      ASSERT_TRUE(analysis().comparing()) << where;
      for (const QString& p : analysis().text_problems())
        ADD_FAILURE() << where << ": " << p.toStdString();
      const QImage image = analysis().render_image();
      const QRect error = analysis().chart_area(0);
      int top = error.bottom(), bottom = error.top();
      for (int y = error.top(); y <= error.bottom(); ++y) {
        if (count_colour(image, QRect(error.left(), y, error.width(), 1), policy_qcolor(1)) > 0) {
          top = std::min(top, y);
          bottom = std::max(bottom, y);
        }
      }
      EXPECT_GT(bottom - top, error.height() / 5) << where << ": perspective's line flattened";
    }
  }
}

// The error chart's scale: linear while the policies' largest errors are within a factor of
// ten, logarithmic from kLogScaleBottom beyond; the control, a linear scale to affine's 47 px,
// puts a 0.8 px error under 2 % of the chart's height.
TEST(SeriesScale, TakesALogScaleWhenOneSeriesFlattensTheOthers) {
  const ValueScale close = series_scale({1.0, 0.8, std::nan("")}, 0.1);
  EXPECT_FALSE(close.log);
  EXPECT_NEAR(close.top, 1.1, 1e-12);
  EXPECT_NEAR(close.fraction(0.8), 0.8 / 1.1, 1e-12);
  const ValueScale apart = series_scale({47.0, 0.8, 0.0}, 0.1);
  ASSERT_TRUE(apart.log);
  EXPECT_NEAR(apart.bottom, kLogScaleBottom, 1e-12);
  const double expected = std::log(0.8 / kLogScaleBottom) / std::log(51.7 / kLogScaleBottom);
  EXPECT_NEAR(apart.fraction(0.8), expected, 1e-9);
  EXPECT_GT(apart.fraction(0.8), 0.5);
  EXPECT_EQ(apart.fraction(0.0), 0.0);
  EXPECT_EQ(apart.fraction(1000.0), 1.0);
  EXPECT_LT(ValueScale{51.7}.fraction(0.8), 0.02);
}

TEST_F(AnalysisComparisonTest, TheLevelBandsShareTheFrameAxisOfTheLineCharts) {
  window().resize(1920, 1080);
  compare({"perspective", "affine", "rerender"});
  window().play_frames(40);
  ASSERT_TRUE(analysis().comparing());
  const QRect bands = analysis().chart_area(3);
  for (int chart = 0; chart < 3; ++chart) {
    const QRect area = analysis().chart_area(chart);
    EXPECT_EQ(area.left(), bands.left()) << chart;
    EXPECT_EQ(area.right(), bands.right()) << chart;
    // The same x is the same frame in the chart and in the bands.
    for (int x = bands.left(); x <= bands.right(); x += 37) {
      EXPECT_EQ(analysis().frame_at(QPoint(x, area.center().y())),
                analysis().frame_at(QPoint(x, bands.center().y())))
          << "chart " << chart << ", x " << x;
    }
  }
  EXPECT_EQ(analysis().threshold_crossings(0), -1);  // no budget charts while comparing
}

TEST_F(AnalysisComparisonTest, WithoutTheComparisonLayoutTheModelsEngineIsCharted) {
  compare({"perspective", "talisman"});
  window().play_frames(10);
  ASSERT_TRUE(analysis().comparing());
  window().model()->set_panel_display(PanelDisplay::kSideBySide);
  window().play_frames(1);
  EXPECT_FALSE(analysis().comparing());
  EXPECT_EQ(analysis().chart_count(), AnalysisView::kChartCount);
  const QImage image = analysis().render_image();
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(count_colour(image, analysis().chart_area(0), policy_qcolor(i)), 0) << i;
  }
  EXPECT_TRUE(analysis().status_text().contains(QStringLiteral("layers drawn")));
}

TEST_F(AnalysisComparisonTest, ClickOnEveryChartLandsOnTheFrameUnderThePointer) {
  window().resize(1920, 1080);
  compare({"perspective", "affine", "talisman", "rerender"});
  window().play_frames(40);
  ASSERT_TRUE(analysis().comparing());
  EXPECT_TRUE(analysis().chart_area(AnalysisView::kComparisonChartCount).isEmpty());
  for (int chart = 0; chart < AnalysisView::kComparisonChartCount; ++chart) {
    const QRect area = analysis().chart_area(chart);
    ASSERT_TRUE(charts()->rect().contains(area)) << chart;
    for (int frame : {3, 17, 38}) {
      QTest::mouseClick(charts(), Qt::LeftButton, Qt::NoModifier, column_centre(chart, frame));
      EXPECT_EQ(window().model()->scene()->frame(), frame) << "chart " << chart;
      EXPECT_TRUE(analysis().status_text().startsWith(QStringLiteral("Frame %1,").arg(frame)))
          << analysis().status_text().toStdString();
    }
  }
  // The runs followed the jumps: their histories end at the frame shown.
  for (const ComparedRun& run : window().model()->comparison().runs()) {
    EXPECT_EQ(run.history.back().frame, 38);
  }
}

// What the inspector says about frame 0 and a later frame of every policy on the demo.
TEST(FrameInspector, SaysWhatEachPolicysFramesAreAndHowFarFromExact) {
  SceneModel scene;
  AnimationModel model(&scene);
  for (const ReusePolicy& policy : reuse_policies()) {
    // The demo is a single plane; the node-image cache and frame generation play scenes only.
    if (needs_scene(policy)) continue;
    EngineSettings settings = model.settings();
    settings.policy = &policy;
    ASSERT_TRUE(model.set_settings(settings)) << policy.name;
    scene.set_frame(12);
    for (const AnimationFrame& record : {model.history().front(), model.history().back()}) {
      ASSERT_EQ(record.layer_reports.size(), 1u);
      const FrameReport& r = record.layer_reports.front();
      const std::string text = explain_frame(record, settings).toStdString();
      const std::string shown = describe_shown_view(r, policy).toStdString();
      EXPECT_NE(text.find(QString::fromStdString(shown).toHtmlEscaped().toStdString()),
                std::string::npos);
      const std::string error = QString::number(r.measured_error_px, 'f', 2).toStdString();
      EXPECT_NE(shown.find(error + " px"), std::string::npos) << shown;
      const bool exact = r.measured_error_px < kExactTolerancePx;
      EXPECT_EQ(shown.find("exact:") != std::string::npos, exact) << policy.name << ": " << shown;
      if (r.level == Level::kRerender && policy.initial_view == InitialView::kAffinePart) {
        EXPECT_NE(shown.find("affine initial view of section 6.5"), std::string::npos) << shown;
      }
      if (r.level == Level::kRerender && policy.initial_view == InitialView::kExact) {
        EXPECT_NE(shown.find("with the exact projection"), std::string::npos) << shown;
      }
    }
  }
}

// The affine policy's frame 0 is the affine part of the exact warp about the texture
// centre: its measured error is the corner distance between that affine view and the exact
// projection, computed here with the affine part taken by central differences.
TEST(FrameInspector, AffineInitialViewIsReportedOffByItsMeasuredDistance) {
  SceneModel scene;
  AnimationModel model(&scene);
  EngineSettings settings = model.settings();
  settings.policy = &reuse_policy("affine");
  ASSERT_TRUE(model.set_settings(settings));
  const FrameReport& r = model.history().front().layer_reports.front();
  const PlanePose pose = scene.current_pose();
  const Mat3 exact = exact_texture_warp(scene.scene().camera, pose);
  const Vec2 size(pose.texture_size.x, pose.texture_size.y), centre = 0.5 * size;
  const double h = 1e-3;  // texels
  const auto at = [&](const Vec2& t) { return apply_homography(exact, t); };
  const Vec2 dx = (at(centre + Vec2(h, 0)) - at(centre - Vec2(h, 0))) / (2 * h);
  const Vec2 dy = (at(centre + Vec2(0, h)) - at(centre - Vec2(0, h))) / (2 * h);
  double worst = 0.0;
  for (const Vec2& t : {Vec2(0, 0), Vec2(size.x, 0), size, Vec2(0, size.y)}) {
    const Vec2 affine = at(centre) + (t.x - centre.x) * dx + (t.y - centre.y) * dy;
    worst = std::max(worst, glm::length(affine - at(t)));
  }
  ASSERT_GT(worst, 1.0) << "the demo's first pose should show perspective";
  EXPECT_NEAR(r.measured_error_px, worst, 0.05);
  const std::string shown = describe_shown_view(r, *settings.policy).toStdString();
  EXPECT_NE(
      shown.find(QString::number(r.measured_error_px, 'f', 2).toStdString() + " px off the exact"),
      std::string::npos)
      << shown;
  EXPECT_EQ(shown.find("exact:"), std::string::npos);
}

TEST(FrameInspector, NotVisibleFramesSayWhyInsteadOfShowingNumbers) {
  AnimationFrame record;
  record.frame = 7;
  record.layers = 1;
  FrameReport plane;
  plane.frame = 7;
  plane.visible = false;
  plane.note = "not visible: a corner is at or behind the eye";
  record.layer_reports.push_back(plane);
  EXPECT_EQ(not_drawn_reason(record), QString::fromStdString(plane.note));
  const QString text = explain_frame(record, EngineSettings{});
  EXPECT_TRUE(text.contains(QString::fromStdString(plane.note))) << text.toStdString();
  EXPECT_FALSE(text.contains(QStringLiteral("leaves"))) << text.toStdString();

  AnimationFrame scene;
  scene.layers = 3;
  scene.outside_frustum = 3;
  EXPECT_EQ(not_drawn_reason(scene), QStringLiteral("outside the image"));
  EXPECT_TRUE(explain_frame(scene, EngineSettings{}).contains(QStringLiteral("outside the image")));
  scene.levels[size_t(Level::kAffine)] = 1;
  EXPECT_TRUE(not_drawn_reason(scene).isEmpty());
}

}  // namespace
}  // namespace oflab::test
