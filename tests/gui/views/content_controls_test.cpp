// The layer content in the window: the animation bar's content box and quality spin box edit
// the model's engine settings, the animator's scene carries the content so that the exact
// panel draws it, a session keeps it, and a scene's polygons keep their own contents.
#include <QComboBox>
#include <QSpinBox>
#include <QTemporaryDir>

#include "adapters/frame_images.h"
#include "image_checks.h"
#include "lessons/lessons.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/animation_view.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class ContentControlsTest : public WindowTest {
 protected:
  AnimationView& animation() { return *view_page<AnimationView>(window(), "animation"); }
  AnimationModel& model() { return *window().model()->animation(); }
  QComboBox* content_box() { return animation().findChild<QComboBox*>("animation_content"); }
  QSpinBox* quality_box() { return animation().findChild<QSpinBox*>("animation_quality"); }

  // Picks `kind` in the content box as a user does (an activated entry).
  void pick_content(ContentKind kind) {
    QComboBox* box = content_box();
    const int index = box->findData(int(kind));
    ASSERT_GE(index, 0) << content_name(kind);
    box->setCurrentIndex(index);
    emit box->activated(index);
  }
};

TEST_F(ContentControlsTest, ContentBoxListsTheContentsAndEveryControlHasATooltip) {
  QComboBox* box = content_box();
  QSpinBox* quality = quality_box();
  ASSERT_NE(box, nullptr);
  ASSERT_NE(quality, nullptr);
  const std::vector<ContentKind> kinds = content_kinds();
  ASSERT_EQ(box->count(), int(kinds.size()));
  for (int i = 0; i < box->count(); ++i) {
    EXPECT_EQ(box->itemText(i).toStdString(), content_name(kinds[size_t(i)]));
  }
  EXPECT_FALSE(box->toolTip().isEmpty());
  EXPECT_FALSE(quality->toolTip().isEmpty());
  EXPECT_EQ(quality->minimum(), 1);
  EXPECT_EQ(quality->maximum(), kMaxContentQuality);
}

TEST_F(ContentControlsTest, PickingAContentAndAQualityChangesWhatTheEnginePlays) {
  window().show_view("animation");
  pick_content(ContentKind::kImpostor);
  quality_box()->setValue(2);
  EXPECT_EQ(model().settings().content.kind, ContentKind::kImpostor);
  EXPECT_EQ(model().settings().content.quality, 2);
  ASSERT_NE(model().animator(), nullptr);
  // The animator's scene carries the content: an exact renderer of it draws the facade.
  const Scene& scene = model().animator()->scene();
  ASSERT_EQ(scene.polygons.size(), 1u);
  EXPECT_EQ(scene.polygons[0].content, ContentKind::kImpostor);
  EXPECT_EQ(scene.content_quality, 2);
  // A re-render now costs the facade's fragments, not one warp per pixel.
  const AnimationFrame& first = model().current();
  EXPECT_GT(first.model_work, 2.0 * first.pixels_written);
}

TEST_F(ContentControlsTest, SettingsFromTheModelShowInTheControls) {
  EngineSettings settings = model().settings();
  settings.content.kind = ContentKind::kShaded;
  settings.content.quality = 4;
  ASSERT_TRUE(model().set_settings(settings));
  EXPECT_EQ(content_box()->currentData().toInt(), int(ContentKind::kShaded));
  EXPECT_EQ(quality_box()->value(), 4);
}

TEST_F(ContentControlsTest, AnImpossibleQualityIsRefusedAndChangesNothing) {
  EngineSettings settings = model().settings();
  const LayerContent kept = settings.content;
  settings.content.quality = kMaxContentQuality + 1;
  EXPECT_FALSE(model().set_settings(settings));
  EXPECT_EQ(model().settings().content.quality, kept.quality);
  EXPECT_TRUE(window().message().contains("quality")) << window().message().toStdString();
}

TEST_F(ContentControlsTest, AScenesPolygonsKeepTheirOwnContents) {
  window().show_view("animation");
  ASSERT_TRUE(model().set_source({"scene", "street", "walk"}));
  EXPECT_FALSE(content_box()->isEnabled());
  EXPECT_TRUE(quality_box()->isEnabled());
  ASSERT_NE(model().animator(), nullptr);
  const Scene& scene = model().animator()->scene();
  int lit = 0;
  for (const ScenePolygon& p : scene.polygons) lit += p.content != ContentKind::kTexture;
  EXPECT_EQ(lit, int(scene.polygons.size())) << "the street's facades and walls are all lit";
  EXPECT_EQ(model().settings().content.kind, ContentKind::kTexture) << "the box is unchanged";
  ASSERT_TRUE(model().set_source({"plane", "", ""}));
  EXPECT_TRUE(content_box()->isEnabled());
}

TEST_F(ContentControlsTest, SessionSaveThenLoadRestoresTheContent) {
  QTemporaryDir dir;
  const QString path = dir.filePath("content.json");
  EngineSettings settings = model().settings();
  settings.content.kind = ContentKind::kShaded;
  settings.content.quality = 3;
  ASSERT_TRUE(model().set_settings(settings));
  ASSERT_TRUE(window().save_session(path, false));
  settings.content = LayerContent{};
  ASSERT_TRUE(model().set_settings(settings));
  ASSERT_TRUE(window().load_session(path)) << window().message().toStdString();
  EXPECT_EQ(model().settings().content.kind, ContentKind::kShaded);
  EXPECT_EQ(model().settings().content.quality, 3);
  EXPECT_EQ(content_box()->currentData().toInt(), int(ContentKind::kShaded));
  EXPECT_EQ(quality_box()->value(), 3);
}

TEST_F(ContentControlsTest, TheReuseLessonWalksTheStreetAgainstReRendering) {
  const Lesson* lesson = find_lesson("when-reuse-pays");
  ASSERT_NE(lesson, nullptr);
  window().apply_lesson(*lesson);
  EXPECT_EQ(window().current_view_name(), "animation");
  EXPECT_EQ(model().source().kind, "scene");
  EXPECT_EQ(model().source().name, "street");
  EXPECT_EQ(model().source().viewer, "walk");
  EXPECT_STREQ(model().settings().policy->name, "perspective");
  EXPECT_EQ(animation().display(), PanelDisplay::kComparison);
  EXPECT_FALSE(window().caption().isEmpty());
  window().model()->set_playing(false);
}

}  // namespace
}  // namespace oflab::test
