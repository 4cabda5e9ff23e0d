// The window for real: it opens on the demo, every view renders, the controls drive the
// scene, impossible input is refused with a visible message, lessons set themselves up.
#include <QDoubleSpinBox>
#include <QLabel>
#include <QScreen>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QWindow>
#include <algorithm>
#include <fstream>

#include "../../analysis/child_process.h"
#include "app/view_table.h"
#include "flow/flow_field.h"
#include "image_checks.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/basis_view.h"
#include "views/coefficient_table.h"
#include "views/flow_view.h"
#include "views/image_canvas.h"
#include "views/scene_controls.h"
#include "views/slider_spin.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

using MainWindowTest = WindowTest;

bool same_pose(const PlanePose& a, const PlanePose& b) {
  return a.point == b.point && a.normal == b.normal && a.up == b.up && a.size == b.size;
}

// Types a value into a control's spin box, as a user would (Enter commits it).
void type_value(SceneControls* controls, const char* name, double value) {
  SliderSpin* control = controls->control(QString::fromLatin1(name));
  ASSERT_NE(control, nullptr) << name;
  control->spin_box()->setValue(value);
  QApplication::processEvents();
}

TEST_F(MainWindowTest, StartsOnTheDefaultDemoWithTheFlowViewInFront) {
  const PlaneScene demo = default_demo_scene();
  EXPECT_TRUE(same_pose(window().model()->scene()->scene().pose, demo.pose));
  EXPECT_EQ(window().model()->scene()->scene().motion.velocity, demo.motion.velocity);
  EXPECT_EQ(window().current_view_name(), "flow");
  EXPECT_EQ(window().view_names(),
            QStringList({"flow", "world", "basis", "animation", "analysis", "slices"}));
  EXPECT_TRUE(window().message().isEmpty());
  // The planar basis row "tx" shows core's coefficient (2.0022 px/s).
  const PlanarFlowCoefficients k = planar_flow_coefficients(demo.camera, demo.pose, demo.motion);
  EXPECT_NEAR(view_page<FlowView>(window(), "flow")->coefficient_table()->value_text(0).toDouble(),
              k.tx, 1e-3);
  EXPECT_NEAR(k.tx, 2.0022, 1e-4);
}

// The tabs are the view table's entries, in order, with its titles and names.
TEST_F(MainWindowTest, TabsAreTheViewTableInOrder) {
  const auto* tabs = window().findChild<QTabWidget*>(QStringLiteral("view_tabs"));
  ASSERT_NE(tabs, nullptr);
  const std::vector<ViewEntry>& table = view_table();
  ASSERT_EQ(tabs->count(), static_cast<int>(table.size()));
  for (int i = 0; i < tabs->count(); ++i) {
    const ViewEntry& entry = table[size_t(i)];
    const QString name = QString::fromStdString(entry.name);
    EXPECT_EQ(tabs->tabText(i), QString::fromStdString(entry.title));
    EXPECT_EQ(window().view_names().at(i), name);
    EXPECT_EQ(window().view(name), tabs->widget(i));
    ASSERT_TRUE(window().show_view(name));
    EXPECT_EQ(window().current_view_name(), name);
  }
}

TEST_F(MainWindowTest, EachViewRendersANonEmptyImage) {
  for (const QString& name : window().view_names()) {
    ASSERT_TRUE(window().show_view(name));
    QApplication::processEvents();
    const QImage image = window().view(name)->render_image();
    EXPECT_GT(image.width(), 100) << name.toStdString();
    EXPECT_GT(distinct_colours(image), 50) << name.toStdString();
  }
}

TEST_F(MainWindowTest, WindowScreenshotContainsTheRenderedViews) {
  const QImage image = window().grab_window_image();
  ASSERT_EQ(image.size(), window().size());
  const QWidget* vtk = view_page<FlowView>(window(), "flow")->canvas();
  const QRect area(vtk->mapTo(&window(), QPoint(0, 0)), vtk->size());
  EXPECT_GT(distinct_colours(image.copy(area)), 50);
}

TEST_F(MainWindowTest, TheWindowOnScreenIsTheWidgetsPictureWithoutAnAlphaChannel) {
  // No alpha in the window's format, so Qt's backing store does not clear what it repaints
  // before each repaint (it did under VTK's OpenGL format: a pass over the whole view).
  QWindow* handle = window().windowHandle();
  ASSERT_NE(handle, nullptr);
  EXPECT_FALSE(handle->format().hasAlpha());
  // What the screen shows is what the widgets paint. The screen grab reads the display's
  // pixels where the window is, so another program's window passing over it (the GUI tests
  // share one virtual display and run side by side) spoils a grab: the window is raised and
  // grabbed again, up to five times; a window that does not show its widgets fails them all.
  const QImage widgets = window().grab().toImage().convertToFormat(QImage::Format_RGB32);
  QImage screen;
  for (int attempt = 0; attempt < 5 && screen != widgets; ++attempt) {
    window().raise();
    window().repaint();
    QApplication::processEvents();
    QTest::qWait(50);
    screen = handle->screen()
                 ->grabWindow(window().winId())
                 .toImage()
                 .convertToFormat(QImage::Format_RGB32);
  }
  ASSERT_EQ(screen.size(), widgets.size());
  EXPECT_TRUE(screen == widgets);
  EXPECT_GT(distinct_colours(screen), 50);  // control: a real picture, not a blank one
}

TEST_F(MainWindowTest, ChangingAMotionValueChangesTheFlowView) {
  const QImage before = view_page<FlowView>(window(), "flow")->render_image();
  type_value(window().scene_controls(), "omega_z", -1.5);
  EXPECT_DOUBLE_EQ(window().model()->scene()->scene().motion.omega.z, -1.5);
  const QImage after = view_page<FlowView>(window(), "flow")->render_image();
  EXPECT_GT(changed_fraction(before, after), 0.01);
}

TEST_F(MainWindowTest, PlaneBehindTheCameraIsRejectedAndLeavesTheSceneAsItWas) {
  const PlaneScene kept = window().model()->scene()->scene();
  CoefficientTable* table = view_page<FlowView>(window(), "flow")->coefficient_table();
  const QString tx = table->value_text(0);
  type_value(window().scene_controls(), "distance", -1.0);
  EXPECT_TRUE(same_pose(window().model()->scene()->scene().pose, kept.pose));
  // The one rule for the distance names the value and its range.
  EXPECT_TRUE(window().message().contains("distance -1 is outside 0.01..10000 u"))
      << window().message().toStdString();
  EXPECT_DOUBLE_EQ(window().scene_controls()->control("distance")->value(), kept.pose.point.z);
  EXPECT_EQ(table->value_text(0), tx);  // the views still show the old scene
  // The next accepted edit clears the message.
  type_value(window().scene_controls(), "distance", 4.0);
  EXPECT_TRUE(window().message().isEmpty());
}

TEST_F(MainWindowTest, PlaneThroughTheEyeAndZeroFocalLengthAreRejected) {
  PlaneScene through_eye = window().model()->scene()->scene();
  through_eye.pose.normal = glm::cross(through_eye.pose.point, Vec3(0, 1, 0));
  EXPECT_FALSE(window().model()->scene()->set_scene(through_eye));
  EXPECT_TRUE(window().message().contains("eye"));
  type_value(window().scene_controls(), "focal", 0.0);
  EXPECT_TRUE(window().message().contains("focal"));
  EXPECT_DOUBLE_EQ(window().model()->scene()->scene().camera.focal_px, 600.0);
}

TEST_F(MainWindowTest, BrokenScriptFileShowsAnErrorAndKeepsTheSession) {
  QTemporaryDir dir;
  const QString path = dir.filePath("broken.json");
  std::ofstream(path.toStdString()) << "{ \"format\": \"oflab-script\", \"camera\": [1, 2";
  const PlaneScene kept = window().model()->scene()->scene();
  EXPECT_FALSE(window().load_script(path));
  EXPECT_FALSE(window().message().isEmpty());
  EXPECT_TRUE(same_pose(window().model()->scene()->scene().pose, kept.pose));
  EXPECT_TRUE(window().model()->scene()->script_name().isEmpty());
}

// The scene over the memory limit, chosen in the window: a banner with the CLI's
// words, and the window keeps playing what it had.
TEST_F(MainWindowTest, ASceneOverTheMemoryLimitShowsABannerAndKeepsTheSource) {
  QTemporaryDir dir;
  const std::filesystem::path scene =
      testing::write_repeated_polygon_scene(dir.path().toStdString());
  AnimationModel* animation = window().model()->animation();
  ASSERT_TRUE(animation->set_source({"scene", "four-cubes", "circle"}));
  EXPECT_FALSE(animation->set_source({"scene", scene.string(), "walk"}));
  EXPECT_TRUE(window().message().contains(
      "MiB of layers and textures, more than 768 MiB (the scene engine memory limit)"))
      << window().message().toStdString();
  EXPECT_EQ(animation->source().name, "four-cubes");
  window().model()->scene()->set_frame(3);  // and it still plays
  ASSERT_NE(animation->animator(), nullptr);
  EXPECT_EQ(animation->animator()->frame(), 3);
  // The status bar names what plays, and a later accepted change takes the banner down.
  const auto* status = window().findChild<QLabel*>(QStringLiteral("source_status"));
  ASSERT_NE(status, nullptr);
  EXPECT_EQ(status->text().toStdString(),
            "Animation plays: Scene: four-cubes, viewer script circle");
  ASSERT_TRUE(animation->set_source({"script", "swing", ""}));
  EXPECT_TRUE(window().message().isEmpty()) << window().message().toStdString();
  EXPECT_EQ(status->text().toStdString(), "Animation plays: Plane script: swing");
}

TEST_F(MainWindowTest, ShippedScriptPlaysItsFrames) {
  ASSERT_TRUE(window().load_script("zoom"));
  const PlanePose first = window().model()->scene()->current_pose();
  window().play_frames(5);
  EXPECT_EQ(window().model()->scene()->frame(), 5);
  EXPECT_LT(window().model()->scene()->current_pose().point.z, first.point.z);  // approaching
}

TEST_F(MainWindowTest, PlayingAdvancesTheMotionAndLoops) {
  window().play_frames(3);
  EXPECT_EQ(window().model()->scene()->frame(), 3);
  EXPECT_FALSE(same_pose(window().model()->scene()->current_pose(),
                         window().model()->scene()->scene().pose));
  window().model()->scene()->set_frame(SceneModel::kLoopFrames);
  EXPECT_EQ(window().model()->scene()->frame(), 0);
}

TEST_F(MainWindowTest, LessonsSetViewCaptionAndOptions) {
  window().apply_lesson(*find_lesson("basis-deformations"));
  EXPECT_EQ(window().current_view_name(), "basis");
  EXPECT_TRUE(window().caption().contains("px"));
  EXPECT_TRUE(view_page<BasisView>(window(), "basis")->playing());
  window().apply_lesson(*find_lesson("flow-of-a-plane"));
  EXPECT_EQ(window().current_view_name(), "flow");
  EXPECT_TRUE(view_page<FlowView>(window(), "flow")->display().streamlines);
  EXPECT_FALSE(view_page<BasisView>(window(), "basis")->playing());
}

TEST_F(MainWindowTest, GalleryGreysTheTermsAPlaneCannotExcite) {
  window().show_view("basis");
  QApplication::processEvents();
  BasisView* gallery = view_page<BasisView>(window(), "basis");
  window().model()->set_basis(BasisKind::kPlanar);
  gallery->render_image();
  EXPECT_EQ(gallery->active_tile_count(), 8);  // 2 + 4 + px, py
  window().model()->set_basis(BasisKind::kTaylor);
  gallery->render_image();
  EXPECT_EQ(gallery->active_tile_count(), 10);  // v1_yy and v2_xx stay zero
  window().model()->set_basis(BasisKind::kWaxmanUllman);
  gallery->render_image();
  EXPECT_EQ(gallery->active_tile_count(), 12);
}

TEST_F(MainWindowTest, GalleryAnimationMovesTheGrids) {
  window().show_view("basis");
  QApplication::processEvents();
  const QImage before = view_page<BasisView>(window(), "basis")->render_image();
  for (int i = 0; i < 6; ++i) view_page<BasisView>(window(), "basis")->step_animation();
  EXPECT_GT(changed_fraction(before, view_page<BasisView>(window(), "basis")->render_image()),
            0.005);
}

// Playing, the tiles swing between 35 % and all of the amount: over a whole loop no tile
// passes through zero amplitude (where every tile would look undeformed).
TEST_F(MainWindowTest, BasisTilesNeverPassThroughZeroAmplitude) {
  BasisView* basis = view_page<BasisView>(window(), "basis");
  window().show_view("basis");
  basis->set_amount(0.6);
  double lowest = 1.0, highest = 0.0;
  for (int i = 0; i < 96; ++i) {  // two cycles of 48 steps
    basis->step_animation();
    lowest = std::min(lowest, basis->animated_amount());
    highest = std::max(highest, basis->animated_amount());
  }
  EXPECT_GT(lowest, 0.3 * 0.6);
  EXPECT_NEAR(highest, 0.6, 0.01);
  EXPECT_LT(lowest, 0.4 * 0.6);  // it does swing
  // Presentation mode's sizes are those of a 1920 x 1080 window (smaller ones scale them).
  window().resize(1920, 1080);
  QApplication::processEvents();
  window().model()->set_presentation(true);
  EXPECT_GE(basis->value_font_size(), kPresentationMinTextPx);
}

TEST_F(MainWindowTest, ResidualPartDrawsNoArrowsAndSaysZero) {
  FlowDisplay d = view_page<FlowView>(window(), "flow")->display();
  d.part = FlowPart::kExactMinusHomography;
  window().model()->set_flow_display(d);
  view_page<FlowView>(window(), "flow")->render_image();
  EXPECT_LT(view_page<FlowView>(window(), "flow")->shown_max_magnitude(), 1e-6);
  d.part = FlowPart::kSecondOrder;
  window().model()->set_flow_display(d);
  view_page<FlowView>(window(), "flow")->render_image();
  EXPECT_GT(view_page<FlowView>(window(), "flow")->shown_max_magnitude(), 1.0);
}

// A plane moved out of the picture: the flow view draws no flow and says why (no
// "max |v| = 0" over a colour bar), the basis view says its terms describe nothing seen.
TEST_F(MainWindowTest, APlaneOutsideTheImageIsSaidToBeOutside) {
  view_page<FlowView>(window(), "flow")->render_image();
  EXPECT_TRUE(view_page<FlowView>(window(), "flow")->plane_in_image());
  EXPECT_FALSE(view_page<FlowView>(window(), "flow")->caption().contains("outside"));
  PlaneScene scene = default_demo_scene();
  scene.pose.point = Vec3(40.0, 0.0, scene.pose.point.z);  // far to the right of the image
  ASSERT_TRUE(window().model()->scene()->set_scene(scene));
  view_page<FlowView>(window(), "flow")->render_image();
  EXPECT_FALSE(view_page<FlowView>(window(), "flow")->plane_in_image());
  EXPECT_TRUE(
      view_page<FlowView>(window(), "flow")->caption().startsWith("The plane is outside the image"))
      << view_page<FlowView>(window(), "flow")->caption().toStdString();
  EXPECT_FALSE(view_page<FlowView>(window(), "flow")->caption().contains("max |v|"));
  EXPECT_EQ(view_page<FlowView>(window(), "flow")->shown_max_magnitude(), 0.0);
  EXPECT_FALSE(view_page<FlowView>(window(), "flow")->coefficient_table()->isEnabled());
  window().show_view("basis");
  QApplication::processEvents();
  EXPECT_TRUE(view_page<BasisView>(window(), "basis")
                  ->summary()
                  .startsWith("The plane is outside the image"));
}

// Nearly edge-on, the plane covers no grid sample: the residual is not called "zero up to
// rounding", the caption says there is nothing to compare.
TEST_F(MainWindowTest, AnEdgeOnPlaneHasNothingToCompare) {
  PlaneScene scene = default_demo_scene();
  scene.pose.point = Vec3(0.0031, 0.0, 5.0);
  scene.pose.normal = Vec3(1.0, 0.0, 1e-6);  // the view ray through the centre grazes it
  scene.pose.up = Vec3(0.0, -1.0, 0.0);
  ASSERT_TRUE(window().model()->scene()->set_scene(scene));
  FlowDisplay d = view_page<FlowView>(window(), "flow")->display();
  d.part = FlowPart::kExactMinusAffine;
  window().model()->set_flow_display(d);
  view_page<FlowView>(window(), "flow")->render_image();
  const QString caption = view_page<FlowView>(window(), "flow")->caption();
  EXPECT_TRUE(caption.contains("nothing to compare")) << caption.toStdString();
  EXPECT_FALSE(caption.contains("zero up to rounding")) << caption.toStdString();
  EXPECT_TRUE(view_page<FlowView>(window(), "flow")->plane_in_image());  // edge-on is not outside
}

// Everything the window shows beyond the scene comes back from a saved session: the flow
// options, the basis and its play state, presentation mode, the lesson, the rate, the view.
TEST_F(MainWindowTest, SessionRestoresTheWindowState) {
  QTemporaryDir dir;
  const QString path = dir.filePath("window.json");
  window().apply_lesson(*find_lesson("basis-deformations"));
  FlowDisplay flow = view_page<FlowView>(window(), "flow")->display();
  flow.part = FlowPart::kSecondOrder;
  flow.arrows = false, flow.streamlines = true, flow.colour_wheel = true;
  flow.texture = false, flow.zoom_to_plane = false, flow.common_scale = true;
  window().model()->set_flow_display(flow);
  window().model()->set_basis(BasisKind::kWaxmanUllman);
  window().model()->set_presentation(true);
  window().model()->set_play_rate(10);
  window().show_view("flow");
  ASSERT_TRUE(window().save_session(path, false));
  // Change everything, then load.
  window().apply_lesson(*find_lesson("flow-of-a-plane"));
  window().model()->set_presentation(false);
  window().model()->set_play_rate(60);
  window().model()->set_basis(BasisKind::kPlanar);
  window().show_view("analysis");
  ASSERT_TRUE(window().load_session(path)) << window().message().toStdString();
  const FlowDisplay back = view_page<FlowView>(window(), "flow")->display();
  EXPECT_EQ(back.part, FlowPart::kSecondOrder);
  EXPECT_FALSE(back.arrows);
  EXPECT_TRUE(back.streamlines);
  EXPECT_TRUE(back.colour_wheel);
  EXPECT_FALSE(back.texture);
  EXPECT_FALSE(back.zoom_to_plane);
  EXPECT_TRUE(back.common_scale);
  EXPECT_EQ(view_page<BasisView>(window(), "basis")->basis(), BasisKind::kWaxmanUllman);
  EXPECT_TRUE(window().model()->presentation());
  EXPECT_EQ(window().model()->lesson(), "basis-deformations");
  EXPECT_EQ(window().caption().toStdString(), find_lesson("basis-deformations")->narrative);
  EXPECT_EQ(window().model()->play_rate(), 10);
  EXPECT_EQ(window().current_view_name(), "flow");
}

TEST_F(MainWindowTest, PresentationModeTurnsTheViewsLight) {
  auto mean_grey = [](const QImage& image) {
    const QImage small = scaled_rgb(image, QSize(32, 32));
    double sum = 0;
    for (int y = 0; y < 32; ++y) {
      for (int x = 0; x < 32; ++x) sum += qGray(small.pixel(x, y));
    }
    return sum / (32 * 32);
  };
  EXPECT_LT(mean_grey(view_page<FlowView>(window(), "flow")->render_image()), 110.0);
  window().model()->set_presentation(true);
  EXPECT_GT(mean_grey(view_page<FlowView>(window(), "flow")->render_image()), 150.0);
  window().model()->set_presentation(
      false);  // the application's fonts are global: leave them normal
}

}  // namespace
}  // namespace oflab::test
