// A shown MainWindow at a fixed size, for tests that render.
#pragma once

#include <gtest/gtest.h>

#include <QtTest/QTest>
#include <memory>

#include "app/main_window.h"
#include "models/animation_model.h"
#include "models/window_model.h"
#include "views/animation_view.h"

namespace oflab::test {

// The window's view named `name` as a V, for what it paints (tests read and set the window's
// state through window.model(), never through a view); fails the test when there is none.
template <class V>
V* view_page(MainWindow& window, const char* name) {
  auto* view = qobject_cast<V*>(window.view(QString::fromLatin1(name)));
  EXPECT_NE(view, nullptr) << name;
  return view;
}

class WindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    window_ = std::make_unique<MainWindow>();
    window_->resize(1280, 800);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get(), 10000));
    QApplication::processEvents();
  }
  void TearDown() override { window_.reset(); }

  MainWindow& window() { return *window_; }

 private:
  std::unique_ptr<MainWindow> window_;
};

// The window, with the animation view and its model at hand.
class AnimationWindowTest : public WindowTest {
 protected:
  AnimationView& animation() { return *view_page<AnimationView>(window(), "animation"); }
  AnimationModel& model() { return *window().model()->animation(); }
};

}  // namespace oflab::test
