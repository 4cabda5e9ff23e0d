// The budget policy in the GUI: choosing it in the animation view's mode box shows a spin
// box of its pixel budget per frame, whose value reaches the engine; the frames played then
// keep within it after the first.
#include <QComboBox>
#include <QSpinBox>

#include "models/animation_model.h"
#include "views/animation_view.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class BudgetControlsTest : public WindowTest {
 protected:
  AnimationView& animation() { return *view_page<AnimationView>(window(), "animation"); }
  AnimationModel& model() { return *window().model()->animation(); }

  // Picks `policy` in the mode box as a user does (the box's activated signal).
  void choose_mode(QComboBox* box, const QString& policy) {
    const int index = box->findData(policy);
    ASSERT_GE(index, 0) << policy.toStdString();
    box->setCurrentIndex(index);
    emit box->activated(index);
    QApplication::processEvents();
  }
};

TEST_F(BudgetControlsTest, ChoosingTheBudgetPolicyShowsItsPixelBudgetWhichReachesTheEngine) {
  window().show_view("animation");
  auto* mode = animation().findChild<QComboBox*>(QStringLiteral("animation_mode"));
  auto* budget = animation().findChild<QSpinBox*>(QStringLiteral("animation_budget"));
  ASSERT_NE(mode, nullptr);
  ASSERT_NE(budget, nullptr);
  EXPECT_FALSE(budget->isVisibleTo(&animation()));  // perspective: no budget
  ASSERT_TRUE(model().set_source({"scene", "four-cubes", "circle"}));
  choose_mode(mode, QStringLiteral("budget"));
  EXPECT_TRUE(budget->isVisibleTo(&animation()));
  EXPECT_STREQ(model().settings().policy->name, "budget");
  EXPECT_EQ(model().settings().budget.unit, FrameBudget::Unit::kNone);  // "auto"
  budget->setValue(6000);
  QApplication::processEvents();
  ASSERT_EQ(model().settings().budget.unit, FrameBudget::Unit::kPixels);
  EXPECT_DOUBLE_EQ(model().settings().budget.amount, 6000.0);
  window().play_frames(10);
  const std::vector<AnimationFrame>& frames = model().history();
  ASSERT_GE(frames.size(), 10u);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    EXPECT_TRUE(frames[i].budget.active) << i;
    EXPECT_LE(frames[i].pixels_written, 6000) << i;
  }
  // Back to a policy without a budget: the box goes away and the engine has none.
  choose_mode(mode, QStringLiteral("exact"));
  EXPECT_FALSE(budget->isVisibleTo(&animation()));
  EXPECT_EQ(model().settings().budget.unit, FrameBudget::Unit::kNone);
}

}  // namespace
}  // namespace oflab::test
