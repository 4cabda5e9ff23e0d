// The animation and analysis views: they render, re-render mode agrees with the exact VTK
// render, the session round-trips through its JSON file, and bad input changes nothing.
//
// Agreement in re-render mode. Both panels then show the exact projection: the engine's
// from core's perspective warp, the other, with the exact panel set to VTK
// (gui/adapters/exact_frames.h), from VTK's textured polygons, both with nearest texel
// sampling; they must agree as two rasterisers of one frame do (tests/gui/image_checks.h
// kExactAgreementIou and kExactAgreementPsnrDb, where the tolerance is explained).
#include "views/animation_view.h"

#include <QApplication>
#include <QComboBox>
#include <QFontMetrics>
#include <QLabel>
#include <QTemporaryDir>
#include <cmath>
#include <fstream>

#include "adapters/exact_frames.h"
#include "adapters/frame_images.h"
#include "adapters/view_theme.h"
#include "display/palette.h"
#include "image_checks.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "state/window_state_file.h"
#include "views/analysis_view.h"
#include "views/frame_inspector.h"
#include "views/image_canvas.h"
#include "views/panel_captions.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

constexpr double kRerenderIou = kExactAgreementIou;
constexpr double kRerenderPsnrDb = kExactAgreementPsnrDb;

class AnimationViewTest : public AnimationWindowTest {
 protected:
  void set_mode(const std::string& policy) {
    EngineSettings settings = model().settings();
    settings.policy = &reuse_policy(policy);
    ASSERT_TRUE(model().set_settings(settings));
  }

  // Compares the two panels, writing both on failure.
  void expect_panels_agree(const QString& name) {
    const Image& engine = animation().engine_image();
    const Image& exact = animation().exact_image();
    ASSERT_EQ(engine.width(), exact.width());
    const FrameAgreement a = agreement_writing_failures(engine, exact, kRerenderIou,
                                                        kRerenderPsnrDb, name, "engine", "exact");
    EXPECT_GE(a.mask_iou, kRerenderIou) << name.toStdString();
    EXPECT_GE(a.psnr_db, kRerenderPsnrDb) << name.toStdString();
  }
};

TEST_F(AnimationViewTest, AnimationViewRendersBothPanels) {
  window().show_view("animation");
  window().play_frames(5);
  const QImage image = animation().render_image();
  EXPECT_GT(image.width(), image.height());  // two panels side by side
  EXPECT_GT(distinct_colours(image), 100);
  EXPECT_GT(distinct_colours(image.copy(image.width() / 2, 0, image.width() / 2, image.height())),
            50);  // the exact panel is not empty
}

// Every source kind plays through the same model: frames advance one record each, the
// engine panel shows something, and the level legend under the panels names every level.
// WCAG relative luminance of an sRGB colour (components 0..1).
double relative_luminance(const QColor& c) {
  const auto linear = [](double v) {
    return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(c.redF()) + 0.7152 * linear(c.greenF()) + 0.0722 * linear(c.blueF());
}

// A black texel (the butterfly's body) stands apart from the camera image's background in
// both looks (contrast ratio at least 3 to 1), and the panels paint that background where
// the exact frame draws nothing.
TEST_F(AnimationViewTest, BlackTexelsStandApartFromTheImageBackgroundInBothLooks) {
  window().show_view("animation");
  for (bool presentation : {false, true}) {
    window().model()->set_presentation(presentation);
    const ViewTheme theme = view_theme(presentation);
    const QColor image = QColor::fromRgbF(theme.image_background[0], theme.image_background[1],
                                          theme.image_background[2]);
    EXPECT_GE((relative_luminance(image) + 0.05) / 0.05, 3.0) << presentation;
    const QImage canvas = animation().render_image();
    const QRectF panel = animation().panel_rects().back();  // the exact panel
    const QRectF frame = animation().shown_frame();
    const Image& exact = animation().exact_image();
    int checked = 0;
    for (int y = int(frame.top()) + 1; y < int(frame.bottom()) - 1 && checked < 20; y += 7) {
      for (int x = int(frame.left()) + 1; x < int(frame.right()) - 1 && checked < 20; x += 7) {
        if (x < 0 || y < 0 || x >= exact.width() || y >= exact.height()) continue;
        if (exact.row(y)[x].a != 0) continue;
        const QPoint at((panel.left() + (x + 0.5 - frame.left()) / frame.width() * panel.width()),
                        (panel.top() + (y + 0.5 - frame.top()) / frame.height() * panel.height()));
        EXPECT_LE(std::abs(QColor(canvas.pixel(at)).lightness() - image.lightness()), 3)
            << presentation << " at " << x << ", " << y;
        ++checked;
      }
    }
    EXPECT_GT(checked, 0) << presentation;
  }
}

TEST_F(AnimationViewTest, EachSourceKindPlaysInTheAnimationView) {
  window().show_view("animation");
  const SourceChoice sources[] = {{"plane", "", ""},
                                  {"scene", "four-cubes", "circle"},
                                  {"scene-shifting", "train-window", "train-sideways"}};
  for (const SourceChoice& source : sources) {
    ASSERT_TRUE(model().set_source(source)) << window().message().toStdString();
    window().play_frames(6);
    const Animator* animator = model().animator();
    ASSERT_NE(animator, nullptr) << source.kind;
    EXPECT_EQ(animator->frame(), 6) << source.kind;
    EXPECT_EQ(model().history().size(), 7u) << source.kind;
    EXPECT_GT(model().current().drawn(), 0) << source.kind;
    const QImage image = animation().render_image();
    ASSERT_FALSE(animation().panel_rects().empty());
    const QImage engine = image.copy(animation().panel_rects().front().toAlignedRect());
    EXPECT_GT(distinct_colours(engine), 50) << source.kind;
    // The legend under the panels shows a swatch of every level.
    const QImage legend =
        image.copy(0, int(animation().panel_rects().front().bottom()), image.width(),
                   image.height() - int(animation().panel_rects().front().bottom()));
    for (int k = 0; k < kLevelCount; ++k) {
      const Rgb8 c = level_colour(Level(k));
      bool found = false;
      for (int y = 0; y < legend.height() && !found; ++y) {
        for (int x = 0; x < legend.width() && !found; ++x)
          found = legend.pixel(x, y) == qRgb(c.r, c.g, c.b);
      }
      EXPECT_TRUE(found) << source.kind << " level " << k;
    }
  }
}

// Scene shifting needs planes parallel to the image plane: other scenes are refused with
// a message saying so, and the source playing before keeps playing.
TEST_F(AnimationViewTest, SceneShiftingOfATiltedSceneIsRefusedWithAMessage) {
  window().show_view("animation");
  ASSERT_TRUE(model().set_source({"scene", "two", "translate"}));
  EXPECT_FALSE(model().set_source({"scene-shifting", "four-cubes", "circle"}));
  EXPECT_TRUE(window().message().contains("parallel")) << window().message().toStdString();
  EXPECT_EQ(model().source().kind, "scene");
  EXPECT_GT(distinct_colours(animation().render_image()), 50);
}

// Scene shifting keeps its own tolerance: the policy controls are off while it plays and
// on again for the other kinds.
TEST_F(AnimationViewTest, PolicyControlsAreOffOnlyForSceneShifting) {
  window().show_view("animation");
  auto* mode = animation().findChild<QComboBox*>(QStringLiteral("animation_mode"));
  ASSERT_NE(mode, nullptr);
  ASSERT_TRUE(model().set_source({"scene-shifting", "train-window", "train-sideways"}));
  EXPECT_FALSE(mode->isEnabled());
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "circle"}));
  EXPECT_TRUE(mode->isEnabled());
}

// The analysis view reads the window model alone: no window, no animation view.
TEST(AnalysisViewAlone, ChartsTheAnimationModelsRun) {
  WindowModel window({"analysis"});
  SceneModel& scene = *window.scene();
  AnimationModel& model = *window.animation();
  AnalysisView analysis(&window);
  analysis.resize(900, 600);
  analysis.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&analysis, 10000));
  scene.set_frame(9);
  EXPECT_EQ(analysis.current_frame(), 9);
  EXPECT_GT(distinct_colours(analysis.render_image()), 10);
  ASSERT_TRUE(model.set_source({"scene", "two", "translate"}));
  scene.set_frame(4);
  EXPECT_EQ(analysis.current_frame(), 4);
  EXPECT_EQ(model.history().size(), 5u);
}

TEST_F(AnimationViewTest, DifferenceAndBlinkRender) {
  window().show_view("animation");
  window().model()->set_panel_display(PanelDisplay::kDifference);
  EXPECT_GT(distinct_colours(animation().render_image()), 5);
  window().model()->set_panel_display(PanelDisplay::kBlink);
  const QImage engine = animation().render_image();
  animation().set_blink_phase(true);
  EXPECT_GT(changed_fraction(engine, animation().render_image()), 0.001);
}

TEST_F(AnimationViewTest, AnalysisViewRendersCharts) {
  window().show_view("analysis");
  window().play_frames(12);
  EXPECT_GT(distinct_colours(view_page<AnalysisView>(window(), "analysis")->render_image()), 10);
  EXPECT_EQ(view_page<AnalysisView>(window(), "analysis")->current_frame(), 12);
}

TEST_F(AnimationViewTest, InRerenderModeThePlanePanelsAgree) {
  window().show_view("animation");
  window().model()->set_exact_renderer("vtk");
  set_mode("rerender");
  window().play_frames(8);
  expect_panels_agree("rerender-plane");
}

TEST_F(AnimationViewTest, InRerenderModeTheScenePanelsAgree) {
  window().show_view("animation");
  window().model()->set_exact_renderer("vtk");
  set_mode("rerender");
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "circle"}));
  window().play_frames(8);
  expect_panels_agree("rerender-scene");
}

TEST_F(AnimationViewTest, SteppingBackShowsTheSameFrameAsPlayingForward) {
  window().show_view("animation");
  window().play_frames(6);
  const Image forward = animation().engine_image();
  window().play_frames(3);
  window().model()->scene()->set_frame(6);
  const FrameAgreement a = frame_agreement(forward, animation().engine_image());
  EXPECT_TRUE(std::isinf(a.psnr_db));
}

TEST_F(AnimationViewTest, SessionSaveThenLoadRestoresTheState) {
  QTemporaryDir dir;
  const QString path = dir.filePath("session.json");
  EngineSettings settings = model().settings();
  settings.policy = &reuse_policy("affine");
  settings.thresholds = {0.5, 1.5, 2.0, 0.75};
  ASSERT_TRUE(model().set_settings(settings));
  ASSERT_TRUE(model().set_source({"scene", "two", "translate"}));
  window().model()->set_panel_display(PanelDisplay::kDifference);
  window().model()->scene()->set_frame(7);
  window().show_view("analysis");
  ASSERT_TRUE(window().save_session(path, false));
  EXPECT_FALSE(window().save_session(path, false));  // never overwrites unasked

  window().apply_lesson(*find_lesson("flow-of-a-plane"));
  ASSERT_TRUE(window().load_session(path)) << window().message().toStdString();
  EXPECT_STREQ(model().settings().policy->name, "affine");
  EXPECT_EQ(model().settings().thresholds, settings.thresholds);
  EXPECT_EQ(model().source().name, "two");
  EXPECT_EQ(model().source().viewer, "translate");
  EXPECT_EQ(animation().display(), PanelDisplay::kDifference);
  EXPECT_EQ(window().model()->scene()->frame(), 7);
  EXPECT_EQ(window().current_view_name(), "analysis");
}

TEST_F(AnimationViewTest, BrokenSessionAndSceneFilesChangeNothingAndShowAnError) {
  QTemporaryDir dir;
  const QString broken = dir.filePath("broken.json");
  std::ofstream(broken.toStdString()) << "{ \"format\": \"oflab-scene\", \"polygons\": [1, ";
  const SourceChoice before = model().source();
  EXPECT_FALSE(model().set_source({"scene", broken.toStdString(), "circle"}));
  EXPECT_FALSE(window().message().isEmpty());
  EXPECT_TRUE(model().source() == before);
  EXPECT_FALSE(window().load_session(broken));
  EXPECT_TRUE(window().message().contains("broken.json")) << window().message().toStdString();
  EXPECT_TRUE(model().source() == before);
}

TEST_F(AnimationViewTest, SessionWithAnUnknownSourceKindIsRefusedAndChangesNothing) {
  QTemporaryDir dir;
  const QString path = dir.filePath("movie.json");
  WindowState session;
  session.source = {"movie", "loop", ""};
  write_session_file(path.toStdString(), session, false);
  const SourceChoice before = model().source();
  EXPECT_FALSE(window().load_session(path));
  EXPECT_TRUE(window().message().contains("movie")) << window().message().toStdString();
  EXPECT_TRUE(model().source() == before);
}

TEST_F(AnimationViewTest, ImpossibleThresholdIsRefused) {
  EngineSettings settings = model().settings();
  const EngineSettings kept = settings;
  settings.thresholds[1] = -1.0;
  EXPECT_FALSE(model().set_settings(settings));
  EXPECT_EQ(model().settings().thresholds, kept.thresholds);
  EXPECT_FALSE(window().message().isEmpty());
}

TEST_F(AnimationViewTest, NewLessonsSetUpTheirViews) {
  window().apply_lesson(*find_lesson("affine-vs-perspective"));
  EXPECT_STREQ(model().settings().policy->name, "affine");
  EXPECT_EQ(window().current_view_name(), "animation");
  window().apply_lesson(*find_lesson("occlusion"));
  EXPECT_EQ(model().source().kind, "scene");
  EXPECT_GT(distinct_colours(animation().render_image()), 50);
  window().apply_lesson(*find_lesson("why-errors-accumulate"));
  EXPECT_EQ(window().current_view_name(), "analysis");
  EXPECT_EQ(model().source().kind, "plane");
}

TEST_F(AnimationViewTest, ModeBoxListsTheReusePoliciesAndFollowsTheSettings) {
  auto* box = animation().findChild<QComboBox*>(QStringLiteral("animation_mode"));
  ASSERT_NE(box, nullptr);
  ASSERT_EQ(box->count(), int(reuse_policies().size()));
  for (int i = 0; i < box->count(); ++i) {
    EXPECT_EQ(box->itemText(i).toStdString(), reuse_policies()[size_t(i)].name);
  }
  set_mode("exact");
  EXPECT_EQ(box->currentText().toStdString(), "exact");
  EXPECT_STREQ(model().settings().policy->name, "exact");
}

TEST(FrameInspector, MarksTheLevelsThePolicyDoesNotAllow) {
  AnimationFrame record;
  record.frame = 3;
  record.layers = 1;
  record.levels[static_cast<int>(Level::kRerender)] = 1;
  FrameReport plane;
  plane.frame = 3;
  plane.level = Level::kRerender;
  record.layer_reports.push_back(plane);
  EngineSettings settings;
  settings.policy = &reuse_policy("affine");
  const std::string affine = explain_frame(record, settings).toStdString();
  EXPECT_NE(affine.find("perspective: leaves 0.00 px &le; 1.00 px (not allowed by the affine "
                        "policy)"),
            std::string::npos)
      << affine;
  EXPECT_EQ(affine.find("affine: leaves 0.00 px &le; 1.00 px (not allowed"), std::string::npos);
  settings.policy = &reuse_policy("perspective");
  EXPECT_EQ(explain_frame(record, settings).toStdString().find("not allowed"), std::string::npos);
}

TEST(FrameInspector, SaysWhyAnAffineViewsMeasuredErrorExceedsItsEstimate) {
  AnimationFrame record;
  record.frame = 20;
  record.layers = 1;
  record.levels[static_cast<int>(Level::kRerender)] = 1;
  FrameReport plane;
  plane.frame = 20;
  plane.level = Level::kRerender;
  plane.estimated_error_px = 0.0;
  plane.measured_error_px = 83.46;
  plane.affine_view_error_px = 83.46;
  plane.reuse_error_px = 0.0;
  record.layer_reports.push_back(plane);
  EngineSettings settings;
  settings.policy = &reuse_policy("affine");
  const std::string affine = explain_frame(record, settings).toStdString();
  EXPECT_NE(affine.find("Estimated error 0.00 px; measured"), std::string::npos) << affine;
  EXPECT_NE(affine.find("that view alone is 83.46 px off the exact projection"), std::string::npos)
      << affine;
  EXPECT_NE(affine.find("reuse adds 0.00 px"), std::string::npos) << affine;
  // A policy whose initial view is the exact projection has no such part to explain.
  settings.policy = &reuse_policy("perspective");
  EXPECT_EQ(explain_frame(record, settings).toStdString().find("Why they differ"),
            std::string::npos);
}

TEST(PanelCaptions, ReprojectionPoliciesSayWhatTheyDidInTheirOwnWords) {
  AnimationFrame frame;
  frame.frame = 5;
  frame.layers = 10;
  frame.levels[static_cast<int>(Level::kPerspective)] = 10;
  EngineSettings settings;
  const QString warped =
      run_caption(frame, reuse_policy("depth-reprojection"), settings, 0, 0).join('\n');
  EXPECT_TRUE(warped.startsWith(QStringLiteral("reprojected 10"))) << warped.toStdString();
  EXPECT_FALSE(warped.contains(QStringLiteral("perspective"))) << warped.toStdString();
  EXPECT_FALSE(warped.contains(QStringLiteral("render frame"))) << warped.toStdString();

  frame.levels = {};
  frame.levels[static_cast<int>(Level::kRerender)] = 8;
  frame.layers = 8;
  const QString rendered = run_caption(frame, reuse_policy("timewarp"), settings, 0, 0).join('\n');
  EXPECT_TRUE(rendered.startsWith(QStringLiteral("rendered 8"))) << rendered.toStdString();
  EXPECT_TRUE(rendered.contains(QStringLiteral("a render frame"))) << rendered.toStdString();
  // A policy of the threshold rule keeps Algorithm 1's names and has no render frames.
  const QString perspective =
      run_caption(frame, reuse_policy("perspective"), settings, 0, 0).join('\n');
  EXPECT_TRUE(perspective.startsWith(QStringLiteral("rerender 8"))) << perspective.toStdString();
  EXPECT_FALSE(perspective.contains(QStringLiteral("render frame"))) << perspective.toStdString();
}

// Under a visible-only warp the caption says how many of the pixels written the warps
// computed, this frame and over the run; under the whole warp (all of them) it says nothing.
TEST(PanelCaptions, AVisibleOnlyWarpShowsThePixelsWarpedBesideThePixelsWritten) {
  AnimationFrame frame;
  frame.layers = 4;
  frame.levels[static_cast<int>(Level::kAffine)] = 4;
  frame.pixels_written = 48000;
  frame.pixels_not_warped = 6000;
  EngineSettings settings;
  settings.warp_area = WarpArea::kVisible;
  const QString visible =
      run_caption(frame, reuse_policy("perspective"), settings, 900000, 20, 700000).join('\n');
  EXPECT_TRUE(visible.contains(QStringLiteral("48 k px")) &&
              visible.contains(QStringLiteral("warped, what shows only: 42 k px (run 700 k px)")))
      << visible.toStdString();
  settings.warp_area = WarpArea::kWhole;
  const QString whole =
      run_caption(frame, reuse_policy("perspective"), settings, 900000, 20, 900000).join('\n');
  EXPECT_FALSE(whole.contains(QStringLiteral("warped"))) << whole.toStdString();
}

TEST(SessionFile, PolicyAndSamplingRoundTripByNameAndUnknownNamesAreRefused) {
  WindowState session;
  session.settings.policy = &reuse_policy("exact");
  session.settings.sampling = Sampling::kBilinear;
  const std::string text = window_state_to_json(session);
  const WindowState back = parse_session(text, "test");
  EXPECT_EQ(back.settings.policy, &reuse_policy("exact"));
  EXPECT_EQ(back.settings.sampling, Sampling::kBilinear);
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace(at, from.size(), to);
  };
  try {
    parse_session(replaced("\"mode\": \"exact\"", "\"mode\": \"bogus\""), "test");
    ADD_FAILURE() << "an unknown policy was accepted";
  } catch (const SessionError& e) {
    EXPECT_NE(std::string(e.what()).find("'mode'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(reuse_policy_names()), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      parse_session(replaced("\"sampling\": \"bilinear\"", "\"sampling\": \"cubic\""), "test"),
      SessionError);
}

// The cursor readout speaks centred pixels, as the flow view and the coefficients do: the
// pixel whose top-left corner is the principal point (cx, cy) has its centre at (0.5, 0.5),
// the image's top-left pixel at (0.5 - cx, 0.5 - cy); the readout under the mouse says so.
TEST_F(AnimationViewTest, CursorReadoutUsesCentredPixels) {
  window().show_view("animation");
  window().play_frames(3);
  const Animator* animator = model().animator();
  ASSERT_NE(animator, nullptr);
  const Camera& camera = animator->camera();
  const Image& exact = animation().exact_image();
  const QString at_centre =
      pixel_readout(*animator, Vec2(camera.cx + 0.25, camera.cy + 0.25), exact);
  EXPECT_TRUE(at_centre.startsWith("pixel (0.5, 0.5) px from the principal point"))
      << at_centre.toStdString();
  const QString corner = pixel_readout(*animator, Vec2(0.2, 0.7), exact);
  const QString expected = QStringLiteral("pixel (%1, %2)")
                               .arg(0.5 - camera.cx, 0, 'f', 1)
                               .arg(0.5 - camera.cy, 0, 'f', 1);
  EXPECT_TRUE(corner.startsWith(expected)) << corner.toStdString();
  EXPECT_TRUE(pixel_readout(*animator, Vec2(-1.0, 5.0), exact).isEmpty());
  // Through the view: the mouse over the first panel where it shows the principal point.
  animation().render_image();
  const QRectF panel = animation().panel_rects().front();
  const QRectF frame = animation().shown_frame();
  const QPointF mouse(
      panel.left() + (camera.cx + 0.25 - frame.left()) / frame.width() * panel.width(),
      panel.top() + (camera.cy + 0.25 - frame.top()) / frame.height() * panel.height());
  auto* canvas = animation().findChild<ImageCanvas*>("animation_canvas");
  ASSERT_NE(canvas, nullptr);
  emit canvas->hovered(mouse);
  const QString shown = animation().findChild<QLabel*>("pixel_readout")->text();
  EXPECT_TRUE(shown.startsWith("pixel (0.5, 0.5) px from the principal point"))
      << shown.toStdString();
  // The whole readout shows at 1920 x 1080, in presentation mode too: no control beside it
  // covers it, and it is as wide as its text (or wraps).
  window().resize(1920, 1080);
  window().model()->set_presentation(true);
  QApplication::processEvents();
  auto* readout = animation().findChild<QLabel*>("pixel_readout");
  readout->setText(shown);
  QApplication::processEvents();
  const QRect label = readout->geometry();
  for (const char* name : {"exact_renderer", "animation_zoom"}) {
    const QWidget* control = animation().findChild<QWidget*>(name);
    ASSERT_NE(control, nullptr) << name;
    const QRect other(control->mapTo(readout->parentWidget(), QPoint(0, 0)), control->size());
    EXPECT_FALSE(label.intersects(other)) << name;
  }
  const QFontMetrics metrics(readout->font());
  const QRect needed =
      metrics.boundingRect(QRect(0, 0, label.width(), 10000), Qt::TextWordWrap, shown);
  EXPECT_LE(needed.height(), label.height() + 1) << label.width() << " x " << label.height();
}

}  // namespace
}  // namespace oflab::test
