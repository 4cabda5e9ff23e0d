// The animation view's exact panel (gui/adapters/exact_frames.h): core's exact render, the
// default, against VTK's independent render of the same frames; the choice of renderer
// through the view, its picker, the command line and session files; and each layer content
// drawn in the exact panel as the engine's re-render draws it.
//
// Agreement of the two renderers. Both sample the nearest texel at pixel centres but round
// edges and texel boundaries differently: alpha masks (silhouettes) overlap with IoU >=
// kExactAgreementIou, and over the pixels both cover the PSNR is >= kExactAgreementPsnrDb
// (tests/gui/image_checks.h, where the choice is explained). The negative control shows
// the measure fails for frames that are not the same (the plane a few frames apart).
#include "adapters/exact_frames.h"

#include <QComboBox>
#include <QTemporaryDir>
#include <fstream>

#include "adapters/frame_images.h"
#include "app/launch_options.h"
#include "image/image_compare.h"
#include "image_checks.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "runs/vtk_scene_renderer.h"
#include "state/window_state_file.h"
#include "views/animation_view.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class ExactFramesTest : public AnimationWindowTest {
 protected:
  // The current frame drawn by the renderer named `name`.
  Image exact_frame(const std::string& name) {
    const Animator& a = *model().animator();
    auto renderer = find_exact_renderer(name)->make(a.scene(), a.camera(), model().settings());
    return renderer->render(a.view());
  }

  void expect_renderers_agree(const std::string& what) {
    const Image core = exact_frame("core"), vtk = exact_frame("vtk");
    ASSERT_EQ(core.width(), vtk.width());
    const FrameAgreement a =
        agreement_writing_failures(core, vtk, kExactAgreementIou, kExactAgreementPsnrDb,
                                   QString::fromStdString(what), "core", "vtk");
    EXPECT_GT(std::count_if(core.pixels().begin(), core.pixels().end(),
                            [](const Pixel& p) { return p.a != 0; }),
              1000)
        << what;
    EXPECT_GE(a.mask_iou, kExactAgreementIou) << what;
    EXPECT_GE(a.psnr_db, kExactAgreementPsnrDb) << what;
  }
};

TEST_F(ExactFramesTest, CoreAndVtkDrawThePlaneAlike) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  for (int frame : {0, 20, 40}) {
    window().model()->scene()->set_frame(frame);
    expect_renderers_agree("plane-" + std::to_string(frame));
  }
}

TEST_F(ExactFramesTest, CoreAndVtkDrawASceneAlike) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "circle"}));
  for (int frame : {0, 30}) {
    window().model()->scene()->set_frame(frame);
    expect_renderers_agree("four-cubes-" + std::to_string(frame));
  }
}

TEST_F(ExactFramesTest, TheAgreementMeasureFailsForDifferentFrames) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  window().model()->scene()->set_frame(10);
  const Image vtk = exact_frame("vtk");
  window().model()->scene()->set_frame(16);
  const FrameAgreement a = frame_agreement(exact_frame("core"), vtk);
  EXPECT_TRUE(a.mask_iou < kExactAgreementIou || a.psnr_db < kExactAgreementPsnrDb);
}

TEST_F(ExactFramesTest, TheViewDrawsCoresExactFrameByDefaultAndVtksWhenChosen) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  window().show_view("animation");
  window().play_frames(6);
  EXPECT_EQ(animation().exact_renderer().name, "core");
  EXPECT_TRUE(std::isinf(frame_agreement(animation().exact_image(), exact_frame("core")).psnr_db));
  // Chosen in the picker under the panels, as a user does.
  auto* box = animation().findChild<QComboBox*>(QStringLiteral("exact_renderer"));
  ASSERT_NE(box, nullptr);
  ASSERT_EQ(box->count(), int(exact_renderers().size()));
  box->setCurrentIndex(1);
  emit box->activated(1);
  EXPECT_EQ(animation().exact_renderer().name, "vtk");
  EXPECT_TRUE(std::isinf(frame_agreement(animation().exact_image(), exact_frame("vtk")).psnr_db));
  window().model()->set_exact_renderer("core");
  EXPECT_EQ(box->currentIndex(), 0);
}

// Each content of the engine (texture, shaded, impostor) is what the exact panel draws: in
// re-render mode the engine's frame and core's exact frame are the same picture.
TEST_F(ExactFramesTest, TheExactPanelDrawsTheEnginesContent) {
  window().show_view("animation");
  for (ContentKind kind : {ContentKind::kTexture, ContentKind::kShaded, ContentKind::kImpostor}) {
    EngineSettings settings = model().settings();
    settings.policy = &reuse_policy("rerender");
    settings.content.kind = kind;
    ASSERT_TRUE(model().set_settings(settings));
    window().model()->scene()->set_frame(12);
    const Image& engine = animation().engine_image();
    EXPECT_GT(psnr_db(engine, animation().exact_image()), 40.0) << content_name(kind);
  }
}

// A scene of lit contents (the street: facade impostors and shaded walls, at the scene's
// quality): in re-render mode the engine's frame and core's exact frame are the same
// picture, on a straight stretch and in the turn.
TEST_F(ExactFramesTest, TheExactPanelDrawsASceneOfLitContentsAsTheEngineDoes) {
  window().show_view("animation");
  ASSERT_TRUE(model().set_source({"scene", "street", "walk"}));
  EngineSettings settings = model().settings();
  settings.policy = &reuse_policy("rerender");
  ASSERT_TRUE(model().set_settings(settings));
  for (int frame : {0, 90}) {
    window().model()->scene()->set_frame(frame);
    EXPECT_GT(psnr_db(animation().engine_image(), animation().exact_image()), 40.0)
        << "street frame " << frame;
  }
}

TEST_F(ExactFramesTest, ASessionKeepsTheExactRenderer) {
  QTemporaryDir dir;
  const QString path = dir.filePath("session.json");
  window().model()->set_exact_renderer("vtk");
  ASSERT_TRUE(window().save_session(path, false));
  window().model()->set_exact_renderer("core");
  ASSERT_TRUE(window().load_session(path)) << window().message().toStdString();
  EXPECT_EQ(animation().exact_renderer().name, "vtk");
  EXPECT_EQ(read_session_file(path.toStdString()).exact_renderer, "vtk");
}

TEST_F(ExactFramesTest, ASessionWithAnUnknownRendererIsRefusedAndChangesNothing) {
  QTemporaryDir dir;
  const QString path = dir.filePath("session.json");
  ASSERT_TRUE(window().save_session(path, false));
  std::ifstream in(path.toStdString());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("\"core\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 6, "\"povray\"");
  std::ofstream(path.toStdString()) << text;
  EXPECT_FALSE(window().load_session(path));
  EXPECT_NE(window().message().indexOf(QStringLiteral("exact_renderer")), -1)
      << window().message().toStdString();
  EXPECT_EQ(animation().exact_renderer().name, "core");
}

TEST(ExactRendererOption, TheCommandLineChoosesARendererAndRefusesUnknownOnes) {
  EXPECT_EQ(parse_launch_options({}).state.exact_renderer, "core");
  EXPECT_EQ(parse_launch_options({"--animation-exact", "vtk"}).state.exact_renderer, "vtk");
  try {
    parse_launch_options({"--animation-exact", "povray"});
    ADD_FAILURE() << "an unknown renderer was accepted";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("--animation-exact", 0), 0u) << message;
    EXPECT_NE(message.find("core"), std::string::npos) << message;
  }
  EXPECT_NE(launch_usage().find("--animation-exact core|vtk"), std::string::npos);
}

}  // namespace
}  // namespace oflab::test
