// The real oflab binary: --screenshot writes a PNG and exits 0, bad input exits 2 with one
// line, --benchmark prints frames per second. Runs on the test's display.
#include <gtest/gtest.h>

#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

#include "image_checks.h"

namespace oflab::test {
namespace {

struct ProcessResult {
  int exit_code = -1;
  QString out, err;
};

ProcessResult run_oflab(const QStringList& args, int timeout_ms = 60000) {
  QProcess process;
  process.start(QStringLiteral(OFLAB_GUI_BINARY), args);
  ProcessResult run;
  if (!process.waitForFinished(timeout_ms)) {
    process.kill();
    process.waitForFinished();
    return run;
  }
  run.exit_code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
  run.out = QString::fromUtf8(process.readAllStandardOutput());
  run.err = QString::fromUtf8(process.readAllStandardError());
  return run;
}

TEST(CommandLine, ScreenshotOfTheFlowViewWritesANonEmptyPng) {
  QTemporaryDir dir;
  const QString path = dir.filePath("out.png");
  const ProcessResult run = run_oflab({"--screenshot", path, "--frames", "3", "--view", "flow"});
  ASSERT_EQ(run.exit_code, 0) << run.err.toStdString();
  const QImage image(path);
  ASSERT_FALSE(image.isNull());
  EXPECT_GT(image.width(), 100);
  EXPECT_GT(distinct_colours(image), 50);
}

TEST(CommandLine, WindowScreenshotIsTheRequestedSize) {
  QTemporaryDir dir;
  const QString path = dir.filePath("window.png");
  const ProcessResult run = run_oflab({"--screenshot", path, "--frames", "1", "--size", "1024",
                                       "700", "--lesson", "basis-deformations"});
  ASSERT_EQ(run.exit_code, 0) << run.err.toStdString();
  const QImage image(path);
  EXPECT_EQ(image.size(), QSize(1024, 700));
  EXPECT_GT(distinct_colours(image), 50);
}

TEST(CommandLine, UnknownViewExitsWithTwoAndOneLine) {
  QTemporaryDir dir;
  const ProcessResult run =
      run_oflab({"--screenshot", dir.filePath("x.png"), "--frames", "1", "--view", "sideways"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.err.startsWith("oflab: --view:")) << run.err.toStdString();
  EXPECT_EQ(run.err.trimmed().count('\n'), 0);
  EXPECT_FALSE(QFileInfo::exists(dir.filePath("x.png")));
}

TEST(CommandLine, BadValuesExitWithTwo) {
  EXPECT_EQ(run_oflab({"--frames", "3"}).exit_code, 2);
  EXPECT_EQ(run_oflab({"--screenshot", "x.png", "--frames", "many"}).exit_code, 2);
  EXPECT_EQ(run_oflab({"--lesson", "nope"}).exit_code, 2);
  EXPECT_EQ(run_oflab({"--scene", "office"}).exit_code, 2);
  const ProcessResult mode = run_oflab({"--mode", "sideways"});
  EXPECT_EQ(mode.exit_code, 2);
  EXPECT_TRUE(mode.err.startsWith("oflab: --mode:")) << mode.err.toStdString();
  EXPECT_EQ(mode.err.trimmed().count('\n'), 0);
}

TEST(CommandLine, ScreenshotsOfTheAnimationAndAnalysisViewsAfterFrames) {
  QTemporaryDir dir;
  for (const QString view : {"animation", "analysis"}) {
    const QString path = dir.filePath(view + ".png");
    const ProcessResult run =
        run_oflab({"--screenshot", path, "--frames", "5", "--view", view, "--mode", "affine"});
    ASSERT_EQ(run.exit_code, 0) << run.err.toStdString();
    const QImage image(path);
    ASSERT_FALSE(image.isNull()) << view.toStdString();
    EXPECT_GT(distinct_colours(image), 20) << view.toStdString();
  }
}

TEST(CommandLine, SceneScreenshotOfTheAnimationView) {
  QTemporaryDir dir;
  const QString path = dir.filePath("scene.png");
  const ProcessResult run = run_oflab({"--scene", "two", "--script", "translate", "--screenshot",
                                       path, "--frames", "4", "--view", "animation"});
  ASSERT_EQ(run.exit_code, 0) << run.err.toStdString();
  EXPECT_GT(distinct_colours(QImage(path)), 20);
}

TEST(CommandLine, UnwritableScreenshotExitsWithOne) {
  const ProcessResult run = run_oflab({"--screenshot", "/nonexistent-dir/x.png", "--view", "flow"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(run.err.contains("cannot write")) << run.err.toStdString();
}

TEST(CommandLine, BenchmarkPrintsFramesPerSecond) {
  const ProcessResult run =
      run_oflab({"--benchmark", "10", "--size", "640", "480", "--threads", "2"});
  ASSERT_EQ(run.exit_code, 0) << run.err.toStdString();
  EXPECT_TRUE(run.out.contains("frames per second")) << run.out.toStdString();
  EXPECT_TRUE(run.out.contains("animation view")) << run.out.toStdString();
  // Where the frame went, stage by stage, on the threads asked for.
  EXPECT_TRUE(run.out.contains("per frame (ms, 2 threads): engine ")) << run.out.toStdString();
  EXPECT_TRUE(run.out.contains(" exact frame ")) << run.out.toStdString();
}

}  // namespace
}  // namespace oflab::test
