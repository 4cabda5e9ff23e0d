// Test entry point: GoogleTest first (so --gtest_list_tests works without a display), then
// VTK's surface format and the QApplication every GUI test needs.
#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>

#include <QApplication>
#include <QSurfaceFormat>

#include "app/app_runner.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  oflab::GuardedApplication app(argc, argv);  // as oflab runs: escaped exceptions shown
  return RUN_ALL_TESTS();
}
