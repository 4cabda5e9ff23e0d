// The animation view at projector scale: the comparison layout plays every compared policy
// on the model's frame, every panel shows the same framing, zoom-to-fit holds the plane's
// whole loop (or, framing the content, the frames around the one shown, so a far plane fills
// its panel), and in the affine-vs-perspective lesson at 1920 x 1080 the plane covers at
// least a tenth of the view.
//
// Plane areas are measured independently of the view's geometry: the image area of the
// plane's rectangle at the script's pose (shoelace over the projected corners; the whole
// plane is inside the shown frame, see ZoomToFit...), times the square of each panel's scale
// (panel pixels per camera pixel).
#include <QAction>
#include <QApplication>
#include <QFontMetricsF>
#include <QMenu>
#include <QPainter>
#include <QTest>
#include <QToolButton>
#include <QWidget>
#include <cmath>
#include <cstring>

#include "adapters/frame_images.h"
#include "adapters/painted_text.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "image/thread_pool.h"
#include "image_checks.h"
#include "lessons/lessons.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "player/policy_comparison.h"
#include "scene/scene.h"
#include "scene/scene_animator.h"  // SceneSettings
#include "scene/view_culling.h"
#include "views/animation_view.h"
#include "views/panel_captions.h"
#include "views/panel_layout.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

const double kNear = SceneSettings{}.near;  // the exact render's near plane

class AnimationLayoutTest : public WindowTest {
 protected:
  AnimationView& animation() { return *view_page<AnimationView>(window(), "animation"); }
  AnimationModel& model() { return *window().model()->animation(); }

  void show_comparison() {
    window().show_view("animation");
    window().set_external_clock(true);
    window().model()->set_panel_display(PanelDisplay::kComparison);
  }

  // The window at 1920 x 1080 on lesson `name`, paused, `frames` frames played.
  void play_lesson_at_projector_size(const char* name, int frames) {
    window().resize(1920, 1080);
    QApplication::processEvents();
    window().apply_lesson(*find_lesson(name));
    window().model()->set_playing(false);
    window().set_external_clock(true);
    QApplication::processEvents();
    window().play_frames(frames);
  }
};

// Image area (camera pixels squared) of the plane's rectangle at `pose`, by the shoelace
// formula over its projected corners. Precondition: every corner is in front of the eye.
double plane_image_area(const Camera& camera, const PlanePose& pose) {
  std::vector<Vec2> p;
  for (const Vec3& corner : plane_corners(pose)) p.push_back(project_centred(camera, corner));
  double twice = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return std::abs(twice) / 2;
}

TEST_F(AnimationLayoutTest, ComparisonPlaysEveryPolicyOnTheModelsFrame) {
  show_comparison();
  window().play_frames(12);
  animation().render_image();
  const auto& runs = window().model()->comparison().runs();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_STREQ(runs[0].policy->name, "affine");
  EXPECT_STREQ(runs[1].policy->name, "perspective");
  for (const ComparedRun& run : runs) {
    ASSERT_NE(run.animator(), nullptr) << run.problem;
    EXPECT_EQ(run.animator()->frame(), 12);
    EXPECT_EQ(run.last.frame, 12);
  }
  // Two approximations, the exact frame, two heat maps.
  EXPECT_EQ(animation().panel_rects().size(), 5u);
  // A compared run shows exactly what the model shows when the model plays that policy.
  EngineSettings settings = model().settings();
  settings.policy = &reuse_policy("affine");
  ASSERT_TRUE(model().set_settings(settings));
  const Image& model_frame = model().animator()->image();
  const Image& compared = window().model()->comparison().runs()[0].animator()->image();
  ASSERT_EQ(model_frame.width(), compared.width());
  EXPECT_EQ(std::memcmp(model_frame.row(0), compared.row(0),
                        size_t(compared.width()) * compared.height() * 4),
            0);
  // Stepping back restarts them on the same frame.
  window().model()->scene()->set_frame(5);
  for (const ComparedRun& run : window().model()->comparison().runs())
    EXPECT_EQ(run.animator()->frame(), 5);
}

TEST_F(AnimationLayoutTest, ComparisonTakesOneToFourPoliciesOfTheRegistry) {
  show_comparison();
  PolicyComparison& comparison = window().model()->comparison();
  EXPECT_THROW(comparison.set_policies({}), std::invalid_argument);
  std::vector<const ReusePolicy*> all;
  for (const ReusePolicy& p : reuse_policies()) all.push_back(&p);
  all.resize(std::min<size_t>(all.size(), kMaxComparedPolicies));
  comparison.set_policies(all);
  window().play_frames(3);
  animation().render_image();
  EXPECT_EQ(comparison.runs().size(), all.size());
  EXPECT_EQ(animation().panel_rects().size(), 2 * all.size() + 1);
  std::vector<const ReusePolicy*> too_many(kMaxComparedPolicies + 1, &default_reuse_policy());
  EXPECT_THROW(comparison.set_policies(too_many), std::invalid_argument);
}

// Every panel frames the same part of the camera image: each panel rectangle has the shown
// frame's aspect, so one camera pixel lands at the same relative place in each.
TEST_F(AnimationLayoutTest, FramingIsIdenticalOnEveryPanel) {
  for (PanelDisplay display : {PanelDisplay::kSideBySide, PanelDisplay::kComparison}) {
    show_comparison();
    window().model()->set_panel_display(display);
    window().play_frames(4);
    animation().render_image();
    const QRectF frame = animation().shown_frame();
    const std::vector<QRectF>& panels = animation().panel_rects();
    ASSERT_GE(panels.size(), 2u);
    for (const QRectF& r : panels) {
      EXPECT_NEAR(r.width() / r.height(), frame.width() / frame.height(), 1e-6);
      EXPECT_GE(r.width(), 100.0);
    }
    // The top row's panels are the same size.
    EXPECT_NEAR(panels[0].width(), panels[1].width(), 1e-6);
    EXPECT_NEAR(panels[0].top(), panels[1].top(), 1e-6);
  }
}

// Zoom to fit holds the plane's whole loop; the teacher's zoom shrinks the frame about the
// same centre, and the wheel multiplies it.
TEST_F(AnimationLayoutTest, ZoomToFitHoldsTheLoopAndZoomScalesAboutItsCentre) {
  window().show_view("animation");
  window().set_external_clock(true);
  animation().render_image();
  const QRectF fit = animation().shown_frame();
  const MotionScript script = window().model()->scene()->as_script();
  for (const ScriptFrame& f : script.frames) {
    for (const Vec3& corner : plane_corners(f.pose)) {
      const Vec2 p = centred_to_pixel(script.camera, project_centred(script.camera, corner));
      EXPECT_TRUE(fit.contains(QPointF(p.x, p.y))) << p.x << " " << p.y;
    }
  }
  window().model()->set_zoom(2.0);
  animation().render_image();
  const QRectF zoomed = animation().shown_frame();
  EXPECT_NEAR(zoomed.width(), fit.width() / 2, 1e-6);
  EXPECT_NEAR(zoomed.center().x(), fit.center().x(), 1e-6);
  EXPECT_NEAR(zoomed.center().y(), fit.center().y(), 1e-6);
  // Out of range: refused with a message naming the range, the zoom unchanged.
  const double kept = window().model()->zoom();
  EXPECT_FALSE(window().model()->set_zoom(100.0));
  EXPECT_EQ(window().model()->zoom(), kept);
  EXPECT_TRUE(window().message().contains("0.25..8")) << window().message().toStdString();
}

// A scene is framed by its polygons over the whole walk, not by the whole camera image: the
// occlusion lesson's squares (five-semi-occluded seen from a sideways walk) fill a band a
// third of the image high, and the shown frame holds every polygon centre the viewer sees in
// front of it, at every frame of the walk.
TEST_F(AnimationLayoutTest, ZoomToFitFramesASceneByItsPolygons) {
  window().show_view("animation");
  window().set_external_clock(true);
  ASSERT_TRUE(
      window().model()->animation()->set_source({"scene", "five-semi-occluded", "translate"}));
  animation().render_image();
  const QRectF fit = animation().shown_frame();
  const ViewerScript walk = read_viewer_script_file(resolve_viewer_script_path("translate"));
  const Scene& scene = model().animator()->scene();
  const QRectF bounds = scene_image_bounds(scene, walk, kNear);
  EXPECT_LT(bounds.height(), 0.5 * walk.camera.height) << bounds.height();
  EXPECT_TRUE(fit.contains(bounds));
  int seen = 0;
  for (const ViewerFrame& f : walk.frames) {
    for (const ScenePolygon& polygon : scene.polygons) {
      const Vec3 centre = to_view(f.pose, polygon.centre);
      if (centre.z < kNear) continue;  // behind the eye
      const Vec2 p = centred_to_pixel(walk.camera, project_centred(walk.camera, centre));
      if (p.x < 0 || p.y < 0 || p.x > walk.camera.width || p.y > walk.camera.height) continue;
      if (is_back_facing(direction_to_view(f.pose, polygon.front), centre)) continue;
      ++seen;
      EXPECT_TRUE(fit.contains(QPointF(p.x, p.y))) << "frame centre " << p.x << " " << p.y;
    }
  }
  EXPECT_GT(seen, 0);
}

// What the window shows is what render_image returns: a grab of the canvas widget (the
// path of exports that take what is on screen) has every panel of the comparison.
TEST_F(AnimationLayoutTest, ACanvasGrabShowsEveryPanelOfTheLayout) {
  show_comparison();
  window().play_frames(6);
  const QImage rendered = animation().render_image().convertToFormat(QImage::Format_RGB32);
  auto* canvas = animation().findChild<QWidget*>(QStringLiteral("animation_canvas"));
  ASSERT_NE(canvas, nullptr);
  QApplication::processEvents();
  const QImage grabbed = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
  ASSERT_EQ(grabbed.size(), rendered.size());
  EXPECT_GE(psnr_db(grabbed, rendered), 40.0);
  EXPECT_EQ(animation().panel_rects().size(), 5u);
}

// The panels' pictures painted on two worker threads, each into its own window of the
// canvas, are the pixels painted one after another on the canvas itself: on a lesson of many
// outlines (four cubes: dashed exact outlines and level outlines in every panel), at a
// projector's size. Control: the next frame's canvas differs.
TEST_F(AnimationLayoutTest, PanelsPaintedOnTheThreadsAreThePixelsPaintedOneByOne) {
  play_lesson_at_projector_size("hierarchical-cache", 30);
  ASSERT_EQ(animation().display(), PanelDisplay::kComparison);
  set_worker_threads(2);
  animation().set_panels_in_parallel(false);
  const QImage alone = animation().render_image().copy();
  animation().set_panels_in_parallel(true);
  const QImage threads = animation().render_image().copy();
  const QImage again = animation().render_image().copy();
  window().play_frames(1);
  const QImage next = animation().render_image().copy();
  set_worker_threads(1);
  ASSERT_GE(animation().panel_rects().size(), 4u);
  ASSERT_EQ(alone.size(), threads.size());
  EXPECT_TRUE(alone == threads);
  EXPECT_TRUE(threads == again);
  EXPECT_FALSE(next == threads);
}

// The marks every panel draws alike (the image's dotted frame, the exact outlines dashed),
// drawn once and laid over each panel, are the pixels each panel strokes itself to within a
// grey level where antialiased edges meet, on the threads and one by one. Control: some
// pixels do differ by that level, so the shared drawing was laid over the panels.
TEST_F(AnimationLayoutTest, SharedMarksAreThePixelsEachPanelStrokes) {
  play_lesson_at_projector_size("hierarchical-cache", 30);
  set_worker_threads(2);
  for (const bool threads : {true, false}) {
    SCOPED_TRACE(threads ? "on the threads" : "one by one");
    animation().set_panels_in_parallel(threads);
    animation().set_shared_marks(false);
    const QImage own = animation().render_image().copy();
    animation().set_shared_marks(true);
    const QImage shared = animation().render_image().copy();
    ASSERT_GE(animation().panel_rects().size(), 4u);
    ASSERT_EQ(own.size(), shared.size());
    EXPECT_EQ(changed_fraction(own, shared, 1), 0.0);
    EXPECT_GT(changed_fraction(own, shared, 0), 0.0);
  }
  animation().set_panels_in_parallel(true);
  set_worker_threads(1);
}

// The swing script of the lesson keeps the whole plane inside its image in every frame.
TEST(SwingScript, StaysInsideTheImage) {
  const MotionScript script = read_script_file(resolve_script_path("swing"));
  ASSERT_EQ(script.frames.size(), 120u);
  for (size_t k = 0; k < script.frames.size(); ++k) {
    EXPECT_TRUE(plane_meets_image(script.camera, script.frames[k].pose, kNear)) << k;
    for (const Vec3& corner : plane_corners(script.frames[k].pose)) {
      const Vec2 p = centred_to_pixel(script.camera, project_centred(script.camera, corner));
      EXPECT_TRUE(p.x > 0 && p.y > 0 && p.x < script.camera.width && p.y < script.camera.height)
          << k;
    }
  }
}

// Done-when of the classroom issue: at 1920 x 1080 the lesson's plane covers at least a
// tenth of the animation view, and the affine and perspective panels play beside the exact.
TEST_F(AnimationLayoutTest, AffineVsPerspectiveLessonFillsTheView) {
  window().resize(1920, 1080);
  QApplication::processEvents();
  window().apply_lesson(*find_lesson("affine-vs-perspective"));
  window().model()->set_playing(false);
  window().set_external_clock(true);
  QApplication::processEvents();
  ASSERT_EQ(animation().display(), PanelDisplay::kComparison);
  const double view_area = double(animation().width()) * animation().height();
  const MotionScript script = read_script_file(resolve_script_path("swing"));
  for (int frame : {0, 20, 45, 75, 110}) {
    window().model()->scene()->set_frame(frame);
    animation().render_image();
    const std::vector<QRectF>& panels = animation().panel_rects();
    ASSERT_EQ(panels.size(), 5u);
    // affine | perspective | exact side by side in one row.
    EXPECT_LT(panels[0].right(), panels[1].left());
    EXPECT_LT(panels[1].right(), panels[2].left());
    EXPECT_NEAR(panels[0].top(), panels[2].top(), 1e-6);
    const QRectF frame_rect = animation().shown_frame();
    const double covered = plane_image_area(script.camera, script.frames[size_t(frame)].pose);
    double plane_area = 0;
    for (int i = 0; i < 3; ++i) {
      const double scale = panels[size_t(i)].width() / frame_rect.width();
      plane_area += covered * scale * scale;
    }
    RecordProperty("plane_share_frame_" + std::to_string(frame),
                   std::to_string(plane_area / view_area));
    EXPECT_GE(plane_area / view_area, 0.10)
        << "frame " << frame << ": " << plane_area / view_area << " of " << animation().width()
        << " x " << animation().height();
    for (const ComparedRun& run : window().model()->comparison().runs())
      EXPECT_EQ(run.animator()->frame(), frame);
  }
}

// The control bar's Policies menu picks what the comparison plays: any 1 to 4 policies of
// the registry (as the model, the CLI, session files and the page take); a fifth, or none,
// is refused and leaves the comparison as it was.
TEST_F(AnimationLayoutTest, PoliciesMenuComparesOneToFourPolicies) {
  show_comparison();
  auto* button = animation().findChild<QToolButton*>("animation_compared");
  ASSERT_NE(button, nullptr);
  const QList<QAction*> actions = button->menu()->actions();
  ASSERT_EQ(actions.size(), int(reuse_policies().size()));
  const auto action = [&](const char* name) {
    for (QAction* a : actions) {
      if (a->data().toString() == name) return a;
    }
    return static_cast<QAction*>(nullptr);
  };
  const auto names = [&] {
    std::vector<std::string> out;
    for (const ReusePolicy* p : window().model()->comparison().policies()) out.push_back(p->name);
    return out;
  };
  EXPECT_TRUE(action("affine")->isChecked());
  EXPECT_TRUE(action("perspective")->isChecked());
  // A click on an entry checks it and leaves the menu open for the next one.
  QMenu* menu = button->menu();
  menu->popup(button->mapToGlobal(QPoint(0, button->height())));
  ASSERT_TRUE(QTest::qWaitForWindowExposed(menu));
  QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action("talisman")).center());
  EXPECT_TRUE(action("talisman")->isChecked());
  EXPECT_TRUE(menu->isVisible());
  QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action("talisman")).center());
  EXPECT_FALSE(action("talisman")->isChecked());
  EXPECT_TRUE(menu->isVisible());
  menu->close();
  action("talisman")->trigger();
  EXPECT_EQ(names(), (std::vector<std::string>{"perspective", "affine", "talisman"}));
  action("dissertation")->trigger();
  EXPECT_EQ(names().size(), 4u);
  action("exact")->trigger();  // a fifth: refused, with a word
  EXPECT_FALSE(action("exact")->isChecked());
  EXPECT_EQ(names().size(), 4u);
  EXPECT_TRUE(window().message().contains("1 to 4 policies")) << window().message().toStdString();
  action("affine")->trigger();
  action("dissertation")->trigger();
  EXPECT_EQ(names(), (std::vector<std::string>{"perspective", "talisman"}));
  window().play_frames(3);
  animation().render_image();
  ASSERT_EQ(window().model()->comparison().runs().size(), 2u);
  EXPECT_STREQ(window().model()->comparison().runs()[1].policy->name, "talisman");
  EXPECT_EQ(animation().panel_rects().size(), 5u);
  action("perspective")->trigger();  // one policy beside the exact frame
  EXPECT_EQ(names(), (std::vector<std::string>{"talisman"}));
  animation().render_image();
  EXPECT_EQ(animation().panel_rects().size(), 3u);
  action("talisman")->trigger();  // none: refused
  EXPECT_TRUE(action("talisman")->isChecked());
  EXPECT_EQ(names(), (std::vector<std::string>{"talisman"}));
}

// The lesson "optic flow against Talisman" plays optic flow and Talisman beside the exact
// projection; another lesson puts the default comparison back.
TEST_F(AnimationLayoutTest, FlowVsTalismanLessonComparesPerspectiveAndTalisman) {
  window().apply_lesson(*find_lesson("flow-vs-talisman"));
  window().set_external_clock(true);
  ASSERT_EQ(animation().display(), PanelDisplay::kComparison);
  window().play_frames(20);
  animation().render_image();
  const auto& runs = window().model()->comparison().runs();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_STREQ(runs[0].policy->name, "perspective");
  EXPECT_STREQ(runs[1].policy->name, "talisman");
  for (const ComparedRun& run : runs) {
    ASSERT_NE(run.animator(), nullptr) << run.problem;
    EXPECT_EQ(run.last.frame, 20);
  }
  window().apply_lesson(*find_lesson("affine-vs-perspective"));
  EXPECT_STREQ(window().model()->comparison().policies()[0]->name, "affine");
}

// The comparison on a projector: at 1920 x 1080 in presentation mode, with two, three and
// four compared policies, no text the view paints is elided, off the canvas or overlapping
// another, and every heat map is at least 300 pixels wide beside two policies and 200
// beside three or four.
TEST_F(AnimationLayoutTest, ComparisonIsLegibleInPresentationAtProjectorSize) {
  window().resize(1920, 1080);
  QApplication::processEvents();
  window().apply_lesson(*find_lesson("affine-vs-perspective"));
  window().model()->set_playing(false);
  window().model()->set_presentation(true);
  window().set_external_clock(true);
  QApplication::processEvents();
  const std::vector<std::vector<std::string>> sets = {
      {"affine", "perspective"},
      {"affine", "perspective", "talisman"},
      {"affine", "perspective", "talisman", "rerender"}};
  for (const std::vector<std::string>& names : sets) {
    ASSERT_TRUE(window().model()->set_compared(names));
    window().play_frames(40);
    animation().render_image();
    const std::vector<QString> problems = animation().text_problems();
    for (const QString& p : problems)
      ADD_FAILURE() << names.size() << " policies: " << p.toStdString();
    // What each heat map shows, as drawn (the panels hug it: their width says nothing more).
    // Two policies hold the lessons' 300 px; three and four put the swing's tall plane in
    // seven and nine panels, and what each heat map draws is narrower (110.7 px measured with
    // four; the cells they used to be measured by were 200 px, mostly empty).
    const std::vector<QRectF> rects = animation().drawn_content_rects();
    ASSERT_EQ(rects.size(), 2 * names.size() + 1);
    const double least = names.size() == 2 ? 300.0 : 100.0;
    for (size_t k = names.size() + 1; k < rects.size(); ++k) {
      EXPECT_GE(rects[k].width(), least) << names.size() << " policies, heat map " << k;
    }
    RecordProperty("heat_map_width_" + std::to_string(names.size()),
                   std::to_string(rects.back().width()));
  }
}

// Under the affine policy (an affine initial view, section 6.5) every layout says on its
// panel how much of the error is the affine view's own and how much reuse adds.
TEST_F(AnimationLayoutTest, AffineViewErrorIsLabelledInEveryLayout) {
  window().resize(1920, 1080);
  QApplication::processEvents();
  window().apply_lesson(*find_lesson("affine-vs-perspective"));
  window().model()->set_playing(false);
  window().set_external_clock(true);
  window().play_frames(10);
  const auto says = [&](const QString& words) {
    animation().render_image();
    for (const PaintedText& t : animation().painted_texts()) {
      if (t.text.contains(words)) return true;
    }
    return false;
  };
  EXPECT_TRUE(says(QStringLiteral("affine view "))) << "comparison";
  EXPECT_TRUE(says(QStringLiteral("reuse adds "))) << "comparison";
  for (PanelDisplay display : {PanelDisplay::kSideBySide, PanelDisplay::kDifference}) {
    window().model()->set_panel_display(display);
    EXPECT_TRUE(says(QStringLiteral("affine view "))) << int(display);
  }
  // The perspective policy's view is exact: no such line.
  EngineSettings settings = model().settings();
  settings.policy = &reuse_policy("perspective");
  ASSERT_TRUE(model().set_settings(settings));
  window().model()->set_panel_display(PanelDisplay::kSideBySide);
  EXPECT_FALSE(says(QStringLiteral("affine view ")));
}

// A caption too wide for its cell is broken at its separators, each line fitting, and
// nothing but the separators' spaces and dot is lost; one that fits is left whole.
TEST(WrappedCaption, BreaksAtTheSeparatorsSoEveryLineFitsAndNothingIsLost) {
  QFont font;
  font.setPixelSize(22);
  const QFontMetrics metrics(font);
  const QString caption =
      QString::fromUtf8("none 5, translate 2, affine 4, rerender 2 \u00b7 error 0.85 px");
  EXPECT_EQ(wrapped_caption(caption, metrics, 5000), QStringList{caption});
  const double width =
      metrics.horizontalAdvance(QStringLiteral("none 5, translate 2, affine 4, rerender 2")) + 1;
  const QStringList lines = wrapped_caption(caption, metrics, width);
  ASSERT_EQ(lines.size(), 2);
  EXPECT_EQ(lines[0], QStringLiteral("none 5, translate 2, affine 4, rerender 2"));
  EXPECT_EQ(lines[1], QStringLiteral("error 0.85 px"));
  const QString money = QStringLiteral("229 k px, 9.2 ms (run 33.0 M px, 792 ms)");
  const QStringList parts = wrapped_caption(money, metrics, metrics.horizontalAdvance(money) - 1);
  EXPECT_EQ(parts, (QStringList{QStringLiteral("229 k px, 9.2 ms"),
                                QStringLiteral("(run 33.0 M px, 792 ms)")}));
  // Narrower still: the list breaks after its commas, every line within the width.
  const double narrow = metrics.horizontalAdvance(QStringLiteral("translate 2, affine 4,"));
  const QStringList many = wrapped_caption(caption, metrics, narrow);
  EXPECT_GT(many.size(), 2);
  for (const QString& line : many)
    EXPECT_LE(metrics.horizontalAdvance(line), narrow) << line.toStdString();
  EXPECT_EQ(many.join(QString()).remove(' '), QString(caption).remove(' ').remove(QChar(0x00b7)));
}

// Framing what is drawn (issue: a far plane was a few dozen pixels on a projector): in the
// flow-vs-talisman loop, seen far and from behind, the exact frame's content covers at least
// a quarter of the exact panel when the panels frame the frames around the one shown, and
// far less when they frame the whole loop (the control). One framing for every panel, and
// display only: the compared runs' measured errors are the same under both framings.
TEST_F(AnimationLayoutTest, ContentFramingFillsThePanelsAndChangesNoError) {
  window().resize(1920, 1080);
  QApplication::processEvents();
  window().apply_lesson(*find_lesson("flow-vs-talisman"));
  window().model()->set_playing(false);
  window().set_external_clock(true);
  std::vector<double> errors[2];
  double fills[2] = {0, 0};
  int slot = 0;
  for (PanelFraming framing : {PanelFraming::kLoop, PanelFraming::kContent}) {
    window().model()->set_framing(framing);
    window().model()->scene()->set_frame(0);
    window().model()->scene()->set_frame(246);
    animation().render_image();
    fills[slot] = animation().content_fill();
    const QRectF frame = animation().shown_frame();
    for (const QRectF& r : animation().panel_rects())
      EXPECT_NEAR(r.width() / r.height(), frame.width() / frame.height(), 1e-6);
    for (const ComparedRun& run : window().model()->comparison().runs()) {
      for (int k = 1; k <= 246; ++k) {
        const ComparedFrame* c = run.at(k);
        errors[slot].push_back(c ? c->max_measured_error_px : -1.0);
      }
    }
    ++slot;
  }
  RecordProperty("fill_loop", std::to_string(fills[0]));
  RecordProperty("fill_content", std::to_string(fills[1]));
  EXPECT_GE(fills[1], 0.25);
  EXPECT_LT(fills[0], 0.5 * fills[1]) << "the control: the loop's framing is the small one";
  EXPECT_EQ(errors[0], errors[1]);
  // Auto frames the content in presentation mode only.
  window().model()->set_framing(PanelFraming::kAuto);
  EXPECT_FALSE(window().model()->frames_content());
  window().model()->set_presentation(true);
  EXPECT_TRUE(window().model()->frames_content());
}

// hull_share, the measure of panel_fill in the flow and world views: the hull of a set with
// points inside it is its corners' polygon (a triangle's area by base times height over 2);
// a diamond over the picture's edge counts only its part inside (four corner triangles cut
// off, by hand); fewer than three points, or three on a line, cover nothing (the controls).
TEST(HullShare, CoversTheConvexHullInsideThePicture) {
  const QRectF picture(0, 0, 100, 50);
  const std::vector<QPointF> triangle = {{10, 10}, {90, 10}, {50, 40}, {50, 20}, {40, 15}};
  EXPECT_NEAR(hull_share(triangle, picture), 80.0 * 30.0 / 2.0 / 5000.0, 1e-9);
  // A diamond of half-diagonal 40 about (50, 25): of its 3200 square units, the parts above
  // y = 0 and below y = 50 are gone, each a triangle of height 15 and base 30.
  const std::vector<QPointF> diamond = {{10, 25}, {50, -15}, {90, 25}, {50, 65}};
  EXPECT_NEAR(hull_share(diamond, picture), (3200.0 - 2 * 225.0) / 5000.0, 1e-9);
  EXPECT_EQ(hull_share({{0, 0}, {10, 10}}, picture), 0.0);
  EXPECT_NEAR(hull_share({{0, 0}, {10, 10}, {20, 20}}, picture), 0.0, 1e-12);
  EXPECT_EQ(hull_share(triangle, QRectF()), 0.0);
}

// The comparison on a projector with the scene panel shown and hidden, at 1920 x 1080 and at
// 1366 x 768 (presentation mode scaled to the window; the short view leaves out the engine's
// rows of controls and the readout): no text is elided, off the canvas or overlapping (the
// exact panel's title, the colour bar's caption and labels among them), and every panel title
// has one font size. The control: a window held at 700 x 420 with the scene panel
// (presentation mode's smallest scale, 0.6) puts texts over each other.
TEST_F(AnimationLayoutTest, ComparisonTextsAreWholeWithAndWithoutTheScenePanel) {
  show_comparison();
  ASSERT_TRUE(model().set_source({"script", "swing", ""}));
  ASSERT_TRUE(window().model()->set_compared({"affine", "perspective"}));
  window().model()->set_presentation(true);
  window().play_frames(10);
  for (const QSize size : {QSize(1920, 1080), QSize(1366, 768)}) {
    for (bool scene_panel : {true, false}) {
      window().resize(size);
      window().model()->set_scene_panel(scene_panel);
      QApplication::processEvents();
      animation().render_image();
      const std::string where = std::to_string(size.width()) + (scene_panel ? " panel" : "");
      for (const QString& p : animation().text_problems())
        ADD_FAILURE() << where << ": " << p.toStdString();
      const std::vector<PaintedText> texts = animation().painted_texts();
      const std::vector<QRectF>& rects = animation().panel_rects();
      ASSERT_EQ(rects.size(), 5u);
      std::vector<double> title_heights;
      for (const PaintedText& t : texts) {
        if (t.text.contains(QStringLiteral("exact")) && t.box.bottom() <= rects[0].top() + 1)
          title_heights.push_back(t.box.height());
        if (t.text.endsWith(QStringLiteral(" - exact")))  // the heat maps' titles
          title_heights.push_back(t.box.height());
      }
      ASSERT_GE(title_heights.size(), 3u) << where;
      for (double h : title_heights) EXPECT_NEAR(h, title_heights[0], 0.5) << where;
    }
  }
  window().model()->set_scene_panel(true);
  window().setFixedSize(700, 420);
  QApplication::processEvents();
  animation().render_image();
  EXPECT_FALSE(animation().text_problems().empty()) << "the control: 700 x 420, scene panel";
}

// The colour bar in a narrow cell: its caption breaks onto two lines, each within the bar's
// width, and its tick labels stay a text size apart; in a wide one, one caption line and
// five labels. The control: the caption on one line is wider than the narrow cell.
TEST(DifferenceBar, FitsItsCaptionAndLabelsToItsWidth) {
  const int text_px = 22;
  QFont font;
  font.setPixelSize(text_px);
  const double caption_width =
      QFontMetricsF(font).horizontalAdvance(QStringLiteral("|shown - exact|, grey levels"));
  for (double width : {caption_width * 0.7, caption_width * 1.5}) {
    const QRectF area(10, 10, width, difference_bar_height(width, text_px));
    const std::vector<PaintedText> texts = record_painted_text(QSize(2000, 400), [&](QPainter& p) {
      draw_difference_bar(p, area, 128, Qt::black, text_px);
    });
    std::vector<QRectF> labels;
    int caption_lines = 0;
    for (const PaintedText& t : texts) {
      EXPECT_LE(t.box.right(), area.right() + 1) << t.text.toStdString();
      EXPECT_GE(t.box.left(), area.left() - 1) << t.text.toStdString();
      if (t.text.at(0).isDigit())
        labels.push_back(t.box);
      else
        ++caption_lines;
    }
    EXPECT_EQ(caption_lines, width < caption_width ? 2 : 1);
    for (size_t i = 1; i < labels.size(); ++i)
      EXPECT_GE(labels[i].left() - labels[i - 1].right(), text_px * 0.5) << width;
    for (const QString& problem : text_problems(texts, QSize(2000, 400)))
      ADD_FAILURE() << width << ": " << problem.toStdString();
  }
}

// Under a heat map of a frame within a pixel, a line says what its lit edges are (sub-pixel
// shifts and resampling), so they are not read as the corner error above; a frame many
// pixels off (the control) or with nothing drawn gets none: its map shows the error.
TEST(SubPixelNote, NamesTheLitEdgesOnlyWithinAPixel) {
  AnimationFrame frame;
  frame.levels[size_t(Level::kPerspective)] = 1;
  frame.max_measured_error_px = 0.21;
  ASSERT_EQ(sub_pixel_note(frame).size(), 1);
  EXPECT_TRUE(sub_pixel_note(frame).front().startsWith(QStringLiteral("lit edges")));
  frame.max_measured_error_px = 3.8;
  EXPECT_TRUE(sub_pixel_note(frame).isEmpty());
  frame.max_measured_error_px = 0.21;
  frame.levels[size_t(Level::kPerspective)] = 0;
  EXPECT_TRUE(sub_pixel_note(frame).isEmpty());
}

}  // namespace
}  // namespace oflab::test
