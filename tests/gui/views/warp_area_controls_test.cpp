// The warp area in the window: the animation bar's "Warp" menu sets EngineSettings::warp_area
// (the whole layer, or only what shows: core/image/pixel_rows.h), a scene's setting. Picking
// "what shows only" on the four cubes makes the engine leave covered pixels out of its warps
// while the frames stay the whole warp's bytes; a state's setting shows in the menu.
#include <QAction>
#include <QMenu>
#include <QToolButton>

#include "models/animation_model.h"
#include "views/animation_view.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class WarpAreaControlsTest : public WindowTest {
 protected:
  AnimationView& animation() { return *view_page<AnimationView>(window(), "animation"); }
  AnimationModel& model() { return *window().model()->animation(); }
  QToolButton* button() {
    return animation().findChild<QToolButton*>(QStringLiteral("animation_warp_area"));
  }
  // The menu's entry for `area` (its data is warp_area_name(area)).
  QAction* entry(WarpArea area) {
    for (QAction* action : button()->menu()->actions()) {
      if (action->data().toString() == QString::fromLatin1(warp_area_name(area))) return action;
    }
    return nullptr;
  }
  // Picks `area` in the menu as a user does (the entry's triggered signal).
  void pick(WarpArea area) {
    QAction* action = entry(area);
    ASSERT_NE(action, nullptr) << warp_area_name(area);
    action->trigger();
    QApplication::processEvents();
  }
};

TEST_F(WarpAreaControlsTest, TheMenuListsEveryWarpAreaWithOneCheckedAndOnlyScenesEnableIt) {
  window().show_view("animation");
  ASSERT_NE(button(), nullptr);
  ASSERT_NE(button()->menu(), nullptr);
  EXPECT_EQ(button()->menu()->actions().size(), kWarpAreaCount);
  int checked = 0;
  for (QAction* action : button()->menu()->actions()) checked += action->isChecked() ? 1 : 0;
  EXPECT_EQ(checked, 1);
  EXPECT_TRUE(entry(WarpArea::kWhole)->isChecked());
  EXPECT_FALSE(button()->toolTip().isEmpty());
  // A single plane hides nothing behind itself: the setting is a scene's.
  ASSERT_TRUE(model().set_source({"script", "zoom", ""}));
  QApplication::processEvents();
  EXPECT_FALSE(button()->isEnabled());
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "compound"}));
  QApplication::processEvents();
  EXPECT_TRUE(button()->isEnabled());
}

TEST_F(WarpAreaControlsTest, WhatShowsOnlyWarpsFewerPixelsForTheSameFrame) {
  window().show_view("animation");
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "compound"}));
  const int frames = 13;
  const auto run = [&](WarpArea area, std::int64_t* not_warped) {
    pick(area);
    EXPECT_EQ(model().settings().warp_area, area);
    window().stage_seek(0);
    window().play_frames(frames - 1);
    *not_warped = 0;
    for (const AnimationFrame& f : model().history()) *not_warped += f.pixels_not_warped;
    return model().animator()->image();
  };
  std::int64_t whole_left_out = -1, visible_left_out = -1;
  const Image whole = run(WarpArea::kWhole, &whole_left_out);
  const Image visible = run(WarpArea::kVisible, &visible_left_out);
  ASSERT_EQ(model().history().size(), std::size_t(frames));
  EXPECT_EQ(whole_left_out, 0);       // the control: the whole warp computes every pixel
  EXPECT_GT(visible_left_out, 1000);  // the cubes cover parts of each other
  EXPECT_EQ(visible.width(), whole.width());
  EXPECT_EQ(visible.height(), whole.height());
  EXPECT_TRUE(visible.pixels() == whole.pixels());  // the same bytes
  EXPECT_TRUE(entry(WarpArea::kVisible)->isChecked());
  EXPECT_FALSE(entry(WarpArea::kWhole)->isChecked());
}

TEST_F(WarpAreaControlsTest, TheModelsSettingShowsInTheMenu) {
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "compound"}));
  EngineSettings settings = model().settings();
  settings.warp_area = WarpArea::kVisible;
  ASSERT_TRUE(model().set_settings(settings));
  QApplication::processEvents();
  EXPECT_TRUE(entry(WarpArea::kVisible)->isChecked());
  settings.warp_area = WarpArea::kWhole;
  ASSERT_TRUE(model().set_settings(settings));
  QApplication::processEvents();
  EXPECT_TRUE(entry(WarpArea::kWhole)->isChecked());
}

}  // namespace
}  // namespace oflab::test
