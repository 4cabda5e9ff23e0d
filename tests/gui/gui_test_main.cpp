// Test entry point: GoogleTest first (so --gtest_list_tests works without a display), then
// the QApplication every GUI test needs, with Qt's default surface format as oflab has it.
#include <gtest/gtest.h>

#include <QApplication>

#include "app/app_runner.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
  oflab::GuardedApplication app(argc, argv);  // as oflab runs: escaped exceptions shown
  return RUN_ALL_TESTS();
}
