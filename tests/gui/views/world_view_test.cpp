// The world view (gui/views/world_view.h): its actors hold the teaching layer's geometry
// (session/display/world_geometry.h, tested in tests/session/display/world_geometry_test.cpp)
// to the bit, the picture at 1920 x 1080 in both
// looks against baselines (with controls: a picture without the arrows and the frustum is
// rejected, and each part hidden on its own changes the picture), frames that move the
// plane without making a single actor anew, texts that neither overlap nor are cut (both
// looks, the cause-and-effect layout, a scene), one render per change and none without, and
// the mouse turning the camera.
#include "views/world_view.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <QPainter>
#include <cmath>
#include <random>
#include <set>

#include "adapters/world_actors.h"
#include "app/view_table.h"
#include "flow/plane_scene.h"
#include "image/mip_pyramid.h"
#include "image/thread_pool.h"
#include "image_checks.h"
#include "models/scene_model.h"
#include "views/image_canvas.h"
#include "views/world_scene.h"
#include "views/world_texts.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class WorldViewTest : public WindowTest {
 protected:
  WorldView& world() { return *view_page<WorldView>(window(), "world"); }
  void show_world(bool presentation) {
    window().resize(1920, 1080);
    window().model()->set_presentation(presentation);
    window().set_external_clock(true);
    ASSERT_TRUE(window().show_view("world"));
    QApplication::processEvents();
    window().play_frames(10);
  }
  // Every text the world view painted is readable: none elided, off the canvas or over
  // another; the labels and the caption are all there.
  void expect_clear_texts(WorldView& view, const char* where) {
    view.render_image();
    const std::vector<PaintedText> texts = view.painted_texts();
    QStringList all;
    for (const PaintedText& t : texts) all << t.text;
    const QString joined = all.join(QStringLiteral(" | "));
    for (const char* label : {"eye", "image plane", "World: the cause of the flow"}) {
      EXPECT_TRUE(all.contains(QString::fromLatin1(label))) << where << ": " << label;
    }
    EXPECT_TRUE(joined.contains(QStringLiteral("about the eye"))) << where;
    EXPECT_GE(all.size(), 6) << where;
    QString problems;
    for (const QString& p : view.text_problems()) problems += p + QStringLiteral("; ");
    EXPECT_TRUE(problems.isEmpty()) << where << ": " << problems.toStdString();
  }
  void expect_no_text_problems(WorldView& view, const char* where) {
    view.render_image();
    QString problems;
    for (const QString& p : view.text_problems()) problems += p + QStringLiteral("; ");
    EXPECT_TRUE(problems.isEmpty()) << where << ": " << problems.toStdString();
  }
  std::set<vtkProp*> props() {
    std::set<vtkProp*> all;
    vtkPropCollection* collection = world().renderer()->GetViewProps();
    collection->InitTraversal();
    while (vtkProp* p = collection->GetNextProp()) all.insert(p);
    return all;
  }
  // The rendered view compared with baselines/<name>.png (image_checks.h).
  void expect_matches_baseline(const QImage& rendered, const QString& name) {
    test::expect_matches_baseline(rendered, name, kWorldBaselineWidth);
  }
  // The world view's baselines keep the thin lines and arrows of a 1920-pixel view visible.
  static constexpr int kWorldBaselineWidth = 640;
};

// The frame on the image plane: each pixel its premultiplied colour plus (1 - alpha) of the
// backdrop, rounded (worked out here per pixel in integers and doubles), the same on 1 thread
// and on 2 (the rows are copied in bands). Control: another backdrop changes the copy.
TEST(WorldFramePixels, ThePremultipliedFrameOverTheBackdrop) {
  Image image(300, 200);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const auto a = static_cast<std::uint8_t>((x * 7 + y * 3) % 256);
      const auto c = [&](int k) { return static_cast<std::uint8_t>((x + k * y) % (a + 1)); };
      image.at(x, y) = Pixel{c(1), c(2), c(3), a};
    }
  }
  const RgbF backdrop{0.25f, 0.5f, 0.75f};
  auto copy = [&](int threads, const RgbF& back) {
    set_worker_threads(threads);
    vtkNew<vtkImageData> pixels;
    copy_frame_pixels(image, pixels, back);
    set_worker_threads(1);
    const auto* p = static_cast<const unsigned char*>(pixels->GetScalarPointer());
    EXPECT_EQ(pixels->GetNumberOfScalarComponents(), 4);
    return std::vector<unsigned char>(p, p + size_t(image.width()) * image.height() * 4);
  };
  const std::vector<unsigned char> one = copy(1, backdrop), two = copy(2, backdrop);
  EXPECT_EQ(one, two);
  size_t wrong = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Pixel p = image.at(x, y);
      const std::uint8_t channel[3] = {p.r, p.g, p.b};
      for (int c = 0; c < 3; ++c) {
        const double want = std::min(255.0, channel[c] + (255 - p.a) * double(backdrop[c]) + 0.5);
        wrong += one[(size_t(y) * image.width() + x) * 4 + c] != static_cast<unsigned char>(want);
      }
      wrong += one[(size_t(y) * image.width() + x) * 4 + 3] != 255;  // opaque
    }
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_NE(copy(2, RgbF{0.0f, 0.0f, 0.0f}), two);
}

// The image plane's texture against the image plane as the camera draws it: its texels
// (the texture's size) and the lengths of its quad's edges on the screen, the actor's own
// points through its matrix, projected by the renderer (canvas pixels): across (the longer of
// the top and bottom edges) and down (the longer side).
struct ImagePlaneOnScreen {
  int texels_across = 0, texels_down = 0;
  double across = 0.0, down = 0.0;
};

ImagePlaneOnScreen image_plane_on_screen(const WorldView& view) {
  const WorldScene& scene = view.drawn_scene();
  ImagePlaneOnScreen r;
  const int* dims = scene.frame_pixels->GetDimensions();
  r.texels_across = dims[0];
  r.texels_down = dims[1];
  vtkActor* actor = scene.image_plane.actor;
  vtkPoints* points = scene.image_plane.data->GetPoints();
  if (!points || points->GetNumberOfPoints() != 4) return r;
  std::array<Vec2, 4> p;  // top-left, top-right, bottom-right, bottom-left (set_textured_quad)
  for (vtkIdType i = 0; i < 4; ++i) {
    double local[4] = {0.0, 0.0, 0.0, 1.0}, world[4];
    points->GetPoint(i, local);
    actor->GetMatrix()->MultiplyPoint(local, world);
    view.renderer()->SetWorldPoint(world[0] / world[3], world[1] / world[3], world[2] / world[3],
                                   1.0);
    view.renderer()->WorldToDisplay();
    const double* d = view.renderer()->GetDisplayPoint();
    p[size_t(i)] = Vec2(d[0], d[1]);
  }
  r.across = std::max(glm::length(p[1] - p[0]), glm::length(p[2] - p[3]));
  r.down = std::max(glm::length(p[3] - p[0]), glm::length(p[2] - p[1]));
  return r;
}

// The frame on the image plane has about as many texels as the image plane takes pixels on
// the screen: at least one texel per pixel along both axes, and one halving more would leave
// fewer (the frame is not copied and uploaded whole every frame to be minified by OpenGL,
// which skips pixels). Zooming the camera in makes the image plane larger on the screen and
// the texture finer, up to the whole frame (800 x 600 for the demo's plane).
TEST_F(WorldViewTest, TheImagePlanesTextureFollowsItsSizeOnTheScreen) {
  show_world(false);
  world().render_image();
  const ImagePlaneOnScreen whole = image_plane_on_screen(world());
  // The 1920 x 1080 view draws the image plane large: the whole frame, no texel to spare.
  EXPECT_EQ(whole.texels_across, 800);
  EXPECT_TRUE(whole.across > 400.0 || whole.down > 300.0) << whole.across << " x " << whole.down;
  world().renderer()->GetActiveCamera()->Zoom(0.3);  // farther: the image plane smaller
  world().refresh();
  const ImagePlaneOnScreen small = image_plane_on_screen(world());
  EXPECT_GT(small.across, 30.0);
  EXPECT_LT(small.texels_across, 800) << "the frame is reduced";
  EXPECT_GE(small.texels_across, small.across);
  EXPECT_GE(small.texels_down, small.down);
  EXPECT_TRUE((small.texels_across + 1) / 2 < small.across ||
              (small.texels_down + 1) / 2 < small.down)
      << small.texels_across << " x " << small.texels_down << " texels for " << small.across
      << " x " << small.down << " pixels";
  world().renderer()->GetActiveCamera()->Zoom(3.0);  // closer again: the texture finer
  world().refresh();
  const ImagePlaneOnScreen large = image_plane_on_screen(world());
  EXPECT_GT(large.across, 2.5 * small.across);
  EXPECT_GT(large.texels_across, small.texels_across) << "the control: a finer texture";
  EXPECT_GE(large.texels_across, std::min(large.across, 800.0));
  EXPECT_GE(large.texels_down, std::min(large.down, 600.0));
}

// With a reduction of 2^k the texture is the frame halved k times (halve_image, each level of
// the mip pyramid, tested in tests/core/image/mipmap_test.cpp) and then copied over the
// backdrop: ceil(w / 2^k) x ceil(h / 2^k) texels, on an odd-sized frame too. Control: the
// frame copied whole is not the halved copy.
TEST(WorldFramePixels, AReducedFrameIsTheHalvedFrameCopied) {
  std::mt19937 rng(4);
  Image image(301, 199);
  for (Pixel& p : image.pixels()) {
    const auto a = static_cast<std::uint8_t>(rng() % 256);
    p = Pixel{static_cast<std::uint8_t>(rng() % (a + 1u)),
              static_cast<std::uint8_t>(rng() % (a + 1u)),
              static_cast<std::uint8_t>(rng() % (a + 1u)), a};
  }
  const RgbF backdrop{0.25f, 0.5f, 0.75f};
  const auto bytes = [](vtkImageData* pixels) {
    const int* d = pixels->GetDimensions();
    const auto* p = static_cast<const unsigned char*>(pixels->GetScalarPointer());
    return std::vector<unsigned char>(p, p + size_t(d[0]) * d[1] * 4);
  };
  Image half, quarter;
  halve_image(image, half);
  halve_image(half, quarter);
  vtkNew<vtkImageData> reduced, expected;
  copy_frame_pixels(image, reduced, backdrop, 2);
  copy_frame_pixels(half, expected, backdrop);
  EXPECT_EQ(reduced->GetDimensions()[0], 151);
  EXPECT_EQ(reduced->GetDimensions()[1], 100);
  EXPECT_EQ(bytes(reduced), bytes(expected));
  copy_frame_pixels(image, reduced, backdrop, 4);
  copy_frame_pixels(quarter, expected, backdrop);
  EXPECT_EQ(reduced->GetDimensions()[0], 76);
  EXPECT_EQ(reduced->GetDimensions()[1], 50);
  EXPECT_EQ(bytes(reduced), bytes(expected));
  copy_frame_pixels(image, reduced, backdrop);
  EXPECT_EQ(reduced->GetDimensions()[0], 301);
}

TEST_F(WorldViewTest, TheWorldViewFollowsTheFlowViewInTheTable) {
  const std::vector<std::string> names = view_table_names();
  ASSERT_GE(names.size(), 2u);
  EXPECT_EQ(names[0], "flow");
  EXPECT_EQ(names[1], "world");
}

TEST_F(WorldViewTest, WorldViewOfTheDemoMatchesItsBaseline) {
  show_world(false);
  expect_matches_baseline(world().render_image(), "world-demo");
}

TEST_F(WorldViewTest, WorldViewInPresentationModeMatchesItsBaseline) {
  show_world(true);
  EXPECT_GE(world().smallest_text_px(), kPresentationMinTextPx);
  expect_matches_baseline(world().render_image(), "world-demo-presentation");
}

TEST_F(WorldViewTest, ToleranceCatchesAWorldViewWithoutArrowsAndFrustum) {
  show_world(false);
  const QImage baseline(QStringLiteral(OFLAB_GUI_BASELINES "/world-demo.png"));
  ASSERT_FALSE(baseline.isNull()) << "missing baseline world-demo.png";
  for (WorldPart part : {WorldPart::kVelocity, WorldPart::kOmega, WorldPart::kFrustum}) {
    world().set_part_shown(part, false);
  }
  const QImage rendered = scaled_rgb(world().render_image(), baseline.size());
  EXPECT_LT(psnr_db(baseline, rendered), kBaselinePsnrDb);
}

TEST_F(WorldViewTest, FrustumPlaneBothArrowsAndPathAreEachDrawn) {
  for (bool presentation : {false, true}) {
    show_world(presentation);
    const QImage full = world().render_image();
    for (WorldPart part :
         {WorldPart::kFrustum, WorldPart::kImagePlane, WorldPart::kPlane, WorldPart::kVelocity,
          WorldPart::kOmega, WorldPart::kRays, WorldPart::kPath}) {
      world().set_part_shown(part, false);
      const QImage without = world().render_image();
      world().set_part_shown(part, true);
      // At least 600 pixels of a 1920 x 1080 window belong to each part (the thinnest, the
      // path, has about 800 since Reset view keeps the whole loop in the picture; a part not
      // drawn changes none).
      EXPECT_GT(changed_fraction(full, without) * full.width() * full.height(), 600.0)
          << "part " << int(part) << (presentation ? " in presentation mode" : "");
    }
  }
}

TEST_F(WorldViewTest, SteppingMovesThePlaneWithoutMakingActorsAnew) {
  show_world(false);
  world().render_image();
  const std::set<vtkProp*> before = props();
  const QImage first = world().render_image();
  SceneModel* scene = window().model()->scene();
  for (int step = 0; step < 5; ++step) {
    window().play_frames(1);  // what the Step key does, and each tick of play
    const Vec3 expected = scene->current_pose().point;
    EXPECT_NEAR(glm::length(world().drawn_centre() - expected), 0.0, 1e-12) << step;
  }
  scene->set_frame(40);  // the scrub slider
  QApplication::processEvents();
  EXPECT_NEAR(glm::length(world().drawn_centre() - scene->current_pose().point), 0.0, 1e-12);
  EXPECT_GT(changed_fraction(first, world().render_image()), 0.002);
  EXPECT_EQ(props(), before);  // the same objects: nothing was made anew
}

// The desktop draws the teaching layer's plane world (session/display/world_geometry.h), the
// numbers the page's world view draws (web/world_json.h): the plane's points and the arrows'
// matrices of frame 40 are plane_world_frame's, computed here from the scene model.
TEST_F(WorldViewTest, ActorsHoldTheTeachingLayersPlaneWorld) {
  show_world(false);
  SceneModel* scene = window().model()->scene();
  scene->set_frame(40);
  QApplication::processEvents();
  world().render_image();
  const PlaneWorldLoop loop = plane_world_loop(scene->as_script(), scene->scene().camera,
                                               scene->current_pose(), SceneModel::kSecondsPerFrame);
  const PlaneWorldFrame f =
      plane_world_frame(loop, scene->current_pose(), scene->current_motion(), scene->frame());
  const WorldScene& drawn = world().drawn_scene();
  EXPECT_EQ(drawn.depth, loop.depth);
  vtkPoints* corners = drawn.plane.data->GetPoints();
  ASSERT_EQ(corners->GetNumberOfPoints(), 4);
  for (int k = 0; k < 4; ++k) {  // VTK keeps points as floats
    const double* p = corners->GetPoint(k);
    const Vec3 expected = f.plane_corners[size_t(k)];
    EXPECT_NEAR(glm::length(Vec3(p[0], p[1], p[2]) - expected), 0.0, 1e-6 * glm::length(expected));
  }
  const std::pair<const WorldScene::Arrow*, WorldArrow> arrows[] = {
      {&drawn.velocity, f.motion.velocity},
      {&drawn.omega, f.motion.omega},
      {&drawn.normal, f.normal},
      {&drawn.up, f.up}};
  for (const auto& [arrow, expected] : arrows) {
    const std::array<double, 16> m = arrow_matrix(expected);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(arrow->matrix->GetElement(i / 4, i % 4), m[size_t(i)]);
  }
  EXPECT_GT(f.motion.velocity.length, 0.0);  // the demo moves and turns: both are drawn
  EXPECT_GT(f.motion.omega.length, 0.0);
}

TEST_F(WorldViewTest, ASceneSourceShowsItsPolygonsWithTheSameActors) {
  show_world(false);
  const std::set<vtkProp*> before = props();
  ASSERT_TRUE(window().model()->animation()->set_source({"scene", "four-cubes", "circle"}))
      << window().message().toStdString();
  window().play_frames(5);
  const QImage image = world().render_image();
  EXPECT_TRUE(world().scene_mode());
  const Animator* animator = window().model()->animation()->animator();
  ASSERT_NE(animator, nullptr);
  const Vec3 eye = viewer_to_world(animator->view(), Vec3(0.0));
  EXPECT_NEAR(glm::length(world().drawn_centre() - eye), 0.0, 1e-12);
  EXPECT_GT(distinct_colours(image), 50);
  EXPECT_EQ(props(), before);
}

// The labels "eye" and "image plane" used to overlap, and the caption's last line ran past
// the right edge of a narrow view.
// The share of the world view's picture the plane covers: the pixels that change when the
// plane (its texture, outline and axes) is hidden.
double plane_share(WorldView& view) {
  const QImage full = view.render_image();
  view.set_part_shown(WorldPart::kPlane, false);
  const QImage without = view.render_image();
  view.set_part_shown(WorldPart::kPlane, true);
  return changed_fraction(full, without);
}

// Through the eye the camera sees the demo's plane, turned 22 degrees at 2 units with
// f = 600 px, as a sixteenth of its image; the view shows the image with a margin. Measured
// at 1920 x 1080: 0.039 of the view (the plane's pixels), in both looks.
constexpr double kLeastEyePlaneShare = 0.02, kMostEyePlaneShare = 0.5;

TEST_F(WorldViewTest, ViewFromTheCameraShowsTheTexturedPlane) {
  for (bool presentation : {false, true}) {
    show_world(presentation);
    window().model()->set_world_camera(WorldCamera::kEye);
    EXPECT_TRUE(world().from_eye());
    const double share = plane_share(world());
    EXPECT_GT(share, kLeastEyePlaneShare) << (presentation ? "presentation" : "normal");
    EXPECT_LT(share, kMostEyePlaneShare);
    // The control: a world whose plane is not drawn fails the same check.
    world().set_part_shown(WorldPart::kPlane, false);
    EXPECT_LT(plane_share(world()), kLeastEyePlaneShare);
    world().set_part_shown(WorldPart::kPlane, true);
    expect_no_text_problems(world(), "through the eye");
    // A drag leaves the eye; the state says so.
    emit world()
        .findChild<ImageCanvas*>(QStringLiteral("world_canvas"))
        ->dragged(QPointF(30, 0), Qt::LeftButton, Qt::NoModifier);
    EXPECT_FALSE(world().from_eye());
    EXPECT_EQ(window().model()->world_camera(), WorldCamera::kOrbit);
  }
}

// The panel_fill measure of the world view (WorldView::drawn_share): through the eye only the
// plane is drawn, so the hull of its corners is the plane's image, which holds every pixel the
// plane changes (plane_share above, counted independently from the pixels; its texture's
// transparent parts change none) and not far more; the orbit's hull adds the eye and its
// image plane. The control: the camera zoomed twice as close covers more of the picture.
TEST_F(WorldViewTest, DrawnShareIsTheHullOfWhatTheViewDraws) {
  show_world(true);
  window().model()->set_world_camera(WorldCamera::kEye);
  const double pixels = plane_share(world());
  const double hull = world().drawn_share();
  RecordProperty("eye_hull", std::to_string(hull));
  RecordProperty("eye_pixels", std::to_string(pixels));
  EXPECT_GE(hull, pixels);
  EXPECT_LT(hull, 3.0 * pixels);
  world().reset_camera();
  const double orbit = world().drawn_share();
  EXPECT_GT(orbit, 0.05);
  EXPECT_LT(orbit, 1.0);
  world().renderer()->GetActiveCamera()->Zoom(2.0);
  world().refresh();
  EXPECT_GT(world().drawn_share(), 1.5 * orbit) << "the control: a closer camera";
}

TEST_F(WorldViewTest, ZeroVectorsAreNotLabelledAndVelocityHasItsUnit) {
  show_world(false);
  QStringList texts;
  for (const PaintedText& t : world().painted_texts()) texts << t.text;
  EXPECT_TRUE(texts.join(QStringLiteral("|")).contains(QStringLiteral(" units/s")))
      << texts.join(QStringLiteral("|")).toStdString();
  PlaneScene still = window().model()->scene()->scene();
  still.motion.velocity = Vec3(0.0);  // a pure turn: V is zero
  still.motion.omega = Vec3(0.0, 0.0, 0.8);
  window().model()->scene()->set_scene(still);
  world().render_image();
  texts.clear();
  for (const PaintedText& t : world().painted_texts()) texts << t.text;
  const QString joined = texts.join(QStringLiteral("|"));
  for (const QString& text : texts)
    EXPECT_FALSE(text.startsWith(QStringLiteral("V "))) << text.toStdString();
  EXPECT_FALSE(joined.contains(QStringLiteral("0.00"))) << joined.toStdString();
  EXPECT_TRUE(joined.contains(QStringLiteral("Omega 0.80"))) << joined.toStdString();
}

TEST_F(WorldViewTest, LabelsAndCaptionNeitherOverlapNorAreCut) {
  for (bool presentation : {false, true}) {
    show_world(presentation);
    expect_clear_texts(world(), presentation ? "presentation" : "normal");
    // Presentation mode's texts are at least 18 px tall at 1920 x 1080.
    for (const PaintedText& t : world().painted_texts()) {
      if (presentation) {
        EXPECT_GE(t.box.height(), kPresentationMinTextPx) << t.text.toStdString();
      }
    }
  }
}

// The labels_over_content measure (the lessons' claim of that name) against a forced case:
// a picture covering the whole canvas leaves no place clear, and every label is reported
// over it; the same labels beside a picture next to their points are placed clear of it.
TEST(WorldTexts, LabelsOverThePicturesAreFoundAndAvoidedWhereTheyCanBe) {
  WorldTexts texts;
  texts.labels[kEyeLabel] = {"eye", Vec3(0.0), {0.0, 0.0, 0.0}, true};
  texts.labels[kOmegaLabel] = {"Omega 0.80 rad/s about the eye", Vec3(1.0), {0.5, 0.2, 0.5}, true};
  const QSize size(800, 500);
  const auto project = [](const Vec3& at, QPointF* canvas) {
    *canvas = at.x > 0.5 ? QPointF(500, 250) : QPointF(300, 250);
    return true;
  };
  const ViewTheme theme = view_theme(false);
  texts.content = {QPolygonF(QRectF(0, 0, 800, 500))};
  texts.lay_out(size, QFont(), theme, project);
  EXPECT_EQ(texts.labels_over_content().size(), 2u);
  // A picture right of and above each point: the wanted places cover it, others do not.
  texts.content = {QPolygonF(QRectF(300, 180, 400, 70))};
  texts.lay_out(size, QFont(), theme, project);
  QString over;
  for (const QString& o : texts.labels_over_content()) over += o + QStringLiteral("; ");
  EXPECT_TRUE(over.isEmpty()) << over.toStdString();
  texts.content.clear();
  texts.lay_out(size, QFont(), theme, project);
  texts.content = {QPolygonF(QRectF(300, 180, 400, 70))};
  EXPECT_FALSE(texts.labels_over_content().empty()) << "the wanted places cover the picture";
}

// The caption wrapped once and kept while its text, font and width are the same: painted
// after a second lay-out, and after a lay-out at another width and back, the texts are the
// pixels of a first lay-out by a fresh WorldTexts (controls: another width and another
// caption paint other pixels).
TEST(WorldTexts, AKeptCaptionPaintsThePixelsOfAFreshLayOut) {
  const QSize size(700, 400);
  const ViewTheme theme = view_theme(true);
  const auto project = [](const Vec3&, QPointF* canvas) {
    *canvas = QPointF(350, 200);
    return true;
  };
  const std::string caption =
      "The viewer moves sideways past four cubes; each pixel moves by its own depth.\n"
      "What the rendered frame did not see has no pixel to move: a hole.";
  const auto painted = [&](WorldTexts& texts, const QSize& at) {
    texts.lay_out(at, QFont(), theme, project);
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    texts.paint(painter);
    return image;
  };
  WorldTexts fresh;
  fresh.caption = caption;
  const QImage first = painted(fresh, size);
  WorldTexts kept;
  kept.caption = caption;
  painted(kept, size);
  EXPECT_TRUE(painted(kept, size) == first);  // laid out again from what it kept
  const QImage narrower = painted(kept, QSize(420, 400));
  EXPECT_FALSE(narrower == first);  // control: another width wraps anew
  EXPECT_TRUE(painted(kept, size) == first);
  kept.caption = "Another caption.";
  EXPECT_FALSE(painted(kept, size) == first);  // control: another caption
}

TEST_F(WorldViewTest, LabelsLeaveTheImagePlanesPictureAndThePlaneClear) {
  for (bool presentation : {false, true}) {
    show_world(presentation);
    QString over;
    for (const QString& o : world().labels_over_content()) over += o + QStringLiteral("; ");
    EXPECT_TRUE(over.isEmpty()) << (presentation ? "presentation: " : "normal: ")
                                << over.toStdString();
  }
}

TEST_F(WorldViewTest, TextsStayClearInTheCauseAndEffectLayout) {
  for (bool presentation : {false, true}) {
    window().resize(1920, 1080);
    window().model()->set_presentation(presentation);
    window().model()->set_cause_and_effect(true);
    window().set_external_clock(true);
    QApplication::processEvents();
    window().play_frames(10);
    ASSERT_EQ(window().layout_views().size(), 2u);
    auto* cause = qobject_cast<WorldView*>(window().layout_views()[0]);
    ASSERT_NE(cause, nullptr);
    ASSERT_TRUE(cause->isVisible());
    EXPECT_LT(cause->width(), 1000);  // the narrow half that used to cut the caption
    expect_clear_texts(*cause, presentation ? "layout, presentation" : "layout");
  }
}

TEST_F(WorldViewTest, TextsOfASceneWorldStayClear) {
  show_world(true);
  ASSERT_TRUE(window().model()->animation()->set_source({"scene", "four-cubes", "circle"}))
      << window().message().toStdString();
  window().play_frames(5);
  ASSERT_TRUE(world().scene_mode());
  world().render_image();
  QString problems;
  for (const QString& p : world().text_problems()) problems += p + QStringLiteral("; ");
  EXPECT_TRUE(problems.isEmpty()) << problems.toStdString();
}

TEST_F(WorldViewTest, RendersOncePerChangeAndNeverWithoutOne) {
  show_world(false);
  world().render_image();
  const int rendered = world().render_count();
  world().render_image();
  QApplication::processEvents();
  EXPECT_EQ(world().render_count(), rendered);  // nothing changed: the same picture
  window().play_frames(1);
  world().render_image();
  QApplication::processEvents();
  EXPECT_EQ(world().render_count(), rendered + 1);  // one frame, one render
}

TEST_F(WorldViewTest, DraggingOrbitsPanningSlidesAndTheWheelZooms) {
  show_world(false);
  auto* canvas = world().findChild<ImageCanvas*>(QStringLiteral("world_canvas"));
  ASSERT_NE(canvas, nullptr);
  vtkCamera* camera = world().renderer()->GetActiveCamera();
  const QImage before = world().render_image();
  const double distance = camera->GetDistance();
  double position[3];
  camera->GetPosition(position);
  const auto drag = [canvas](Qt::MouseButton button, Qt::KeyboardModifiers modifiers) {
    const QPointF from(canvas->width() / 2.0, canvas->height() / 2.0), to = from + QPointF(120, 40);
    QMouseEvent press(QEvent::MouseButtonPress, from, button, button, modifiers);
    QMouseEvent move(QEvent::MouseMove, to, Qt::NoButton, button, modifiers);
    QMouseEvent release(QEvent::MouseButtonRelease, to, button, Qt::NoButton, modifiers);
    for (QMouseEvent* e : {&press, &move, &release}) QApplication::sendEvent(canvas, e);
  };
  drag(Qt::LeftButton, Qt::NoModifier);  // orbit: about the focal point, at the same distance
  EXPECT_NEAR(camera->GetDistance(), distance, 1e-9 * distance);
  EXPECT_GT(
      std::hypot(camera->GetPosition()[0] - position[0], camera->GetPosition()[1] - position[1],
                 camera->GetPosition()[2] - position[2]),
      0.1 * distance);
  EXPECT_GT(changed_fraction(before, world().render_image()), 0.01);
  double focal[3];
  camera->GetFocalPoint(focal);
  drag(Qt::LeftButton, Qt::ShiftModifier);  // pan: the focal point moves, the distance stays
  EXPECT_NEAR(camera->GetDistance(), distance, 1e-6 * distance);
  EXPECT_GT(std::hypot(camera->GetFocalPoint()[0] - focal[0], camera->GetFocalPoint()[1] - focal[1],
                       camera->GetFocalPoint()[2] - focal[2]),
            1e-3 * distance);
  QWheelEvent wheel(QPointF(100, 100), QPointF(canvas->mapToGlobal(QPoint(100, 100))), QPoint(),
                    QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(canvas, &wheel);  // one notch away from the user: 1.1^2 closer
  EXPECT_NEAR(camera->GetDistance(), distance / 1.21, 1e-6 * distance);
}

}  // namespace
}  // namespace oflab::test
