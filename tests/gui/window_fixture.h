// A shown MainWindow at a fixed size, for tests that render.
#pragma once

#include <gtest/gtest.h>

#include <QtTest/QTest>
#include <memory>

#include "app/main_window.h"
#include "models/animation_model.h"
#include "views/animation_view.h"

namespace oflab::test {

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
  AnimationView& animation() { return *window().animation_view(); }
  AnimationModel& model() { return *window().animation_model(); }
};

}  // namespace oflab::test
