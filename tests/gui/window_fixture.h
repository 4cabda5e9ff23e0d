// A shown MainWindow at a fixed size, for tests that render.
#pragma once

#include <gtest/gtest.h>

#include <QtTest/QTest>
#include <memory>

#include "app/main_window.h"

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

}  // namespace oflab::test
