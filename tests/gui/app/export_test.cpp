// The window's exports, as the File > Export menu runs them (the dialogs only choose the
// path): numbered PNGs, the Ogg Theora video and the per-frame CSV of every source kind,
// each one frame per frame of the animation, none overwriting an existing file unless told to.
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QTemporaryDir>
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "app/exports.h"
#include "app/screenshot.h"
#include "flow/flow_field.h"
#include "image_checks.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/animation_view.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

using ExportTest = WindowTest;

constexpr int kFrames = 8;

// Loads a short rotation script of `frames` frames; the animation view plays it.
void play_short_script(MainWindow& window, const QTemporaryDir& dir, int frames = kFrames) {
  const QString path = dir.filePath("short.json");
  std::ofstream(path.toStdString()) << R"({"format": "oflab-script", "version": 1,
    "name": "short", "camera": {"focal_px": 256, "image": [320, 240]},
    "plane": {"point": [0, 0, 1], "normal": [0, 0, 1], "up": [0, -1, 0],
              "size": [0.949, 0.773]},
    "motion_model": "centre",
    "segments": [{"frames": )" << frames
                                    << R"(, "velocity": [0, 0, 0], "omega": [0, 0, 0.05]}]})";
  ASSERT_TRUE(window.load_script(path)) << window.message().toStdString();
  ASSERT_NE(window.model()->animation()->animator(), nullptr);
  ASSERT_EQ(window.model()->animation()->animator()->frame_count(), frames);
}

std::string read_all(const QString& path) {
  std::ifstream in(path.toStdString(), std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST_F(ExportTest, PngFramesAreOnePerFrameDifferAndAreNotOverwritten) {
  QTemporaryDir dir;
  play_short_script(window(), dir);
  window().model()->scene()->set_frame(3);
  const QString out = dir.filePath("frames");
  QString error;
  ASSERT_TRUE(export_frames_png(&window(), out, false, &error)) << error.toStdString();
  EXPECT_EQ(window().model()->scene()->frame(), 3);  // restored
  const QStringList files = QDir(out).entryList({"frame-*.png"}, QDir::Files, QDir::Name);
  ASSERT_EQ(files.size(), kFrames);
  EXPECT_EQ(files.front(), "frame-0000.png");
  const QImage first(QDir(out).filePath(files.front()));
  const QImage last(QDir(out).filePath(files.back()));
  ASSERT_FALSE(first.isNull());
  EXPECT_GT(first.width(), 100);
  // The whole view as on screen (every panel), not one re-rendered panel.
  EXPECT_EQ(first.size(), view_page<AnimationView>(window(), "animation")->size());
  EXPECT_EQ(first.size(), last.size());
  EXPECT_NE(first, last);  // the plane turned

  // A second export refuses to replace the frames and leaves them as they were.
  const std::string before = read_all(QDir(out).filePath(files.front()));
  EXPECT_FALSE(export_frames_png(&window(), out, false, &error));
  EXPECT_TRUE(error.contains("exists")) << error.toStdString();
  EXPECT_EQ(read_all(QDir(out).filePath(files.front())), before);
  EXPECT_TRUE(export_frames_png(&window(), out, true, &error)) << error.toStdString();
}

// In the blink layout the exported frames blink as the screen does: half a second (15
// frames at 30 fps) of the engine's frame, then half a second of the exact one. Each
// exported frame's panel is the view's panel at that frame in that phase (the panel's
// picture only: its captions carry measured times, which differ from run to run).
TEST_F(ExportTest, BlinkExportAlternatesEngineAndExactAsOnScreen) {
  QTemporaryDir dir;
  constexpr int kLong = 32;
  play_short_script(window(), dir, kLong);
  AnimationView* view = view_page<AnimationView>(window(), "animation");
  window().model()->set_panel_display(PanelDisplay::kBlink);
  const QString out = dir.filePath("blink");
  QString error;
  ASSERT_TRUE(export_frames_png(&window(), out, false, &error)) << error.toStdString();
  const QStringList files = QDir(out).entryList({"frame-*.png"}, QDir::Files, QDir::Name);
  ASSERT_EQ(files.size(), kLong);
  EXPECT_FALSE(view->blink_phase());  // blinking starts again from the engine's frame
  const QWidget* canvas = view->findChild<QWidget*>("animation_canvas");
  ASSERT_NE(canvas, nullptr);
  QImage previous;
  for (int k : {0, 14, 15, 29, 30}) {
    const bool exact = k >= 15 && k < 30;
    EXPECT_EQ(AnimationView::blink_phase_at(k, kExportFps), exact) << k;
    window().model()->scene()->set_frame(k);
    view->set_blink_phase(exact);
    view->render_image();
    ASSERT_EQ(view->panel_rects().size(), 1u);
    const QRect panel =
        view->panel_rects().front().toAlignedRect().translated(canvas->mapTo(view, QPoint(0, 0)));
    const QImage on_screen = grab_with_vtk(view).convertToFormat(QImage::Format_RGB32).copy(panel);
    const QImage exported =
        QImage(QDir(out).filePath(files[k])).convertToFormat(QImage::Format_RGB32).copy(panel);
    EXPECT_EQ(exported, on_screen) << "frame " << k << (exact ? " (exact)" : " (engine)");
    if (k == 15 || k == 30) {  // the phase changed: engine and exact differ
      EXPECT_GT(changed_fraction(previous, exported), 0.01) << k;
    }
    previous = exported;
  }
  view->set_blink_phase(false);
}

TEST_F(ExportTest, VideoIsAnOggFileAndAnExistingFileIsKept) {
  QTemporaryDir dir;
  play_short_script(window(), dir);
  const QString path = dir.filePath("movie.ogv");
  QString error;
  ASSERT_TRUE(export_video(&window(), path, false, &error)) << error.toStdString();
  const std::string bytes = read_all(path);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(0, 4), "OggS");
  EXPECT_NE(bytes.find("theora"), std::string::npos);

  const QString mine = dir.filePath("mine.ogv");
  std::ofstream(mine.toStdString()) << "a user's file";
  EXPECT_FALSE(export_video(&window(), mine, false, &error));
  EXPECT_TRUE(error.contains("exists")) << error.toStdString();
  EXPECT_EQ(read_all(mine), "a user's file");
}

// MP4 and GIF go through the same encoder (decoded back in
// tests/analysis/formats/video_file_test.cpp).
TEST_F(ExportTest, VideoFormatFollowsTheExtension) {
  QTemporaryDir dir;
  play_short_script(window(), dir);
  QString error;
  ASSERT_TRUE(export_video(&window(), dir.filePath("movie.mp4"), false, &error))
      << error.toStdString();
  EXPECT_EQ(read_all(dir.filePath("movie.mp4")).substr(4, 4), "ftyp");
  ASSERT_TRUE(export_video(&window(), dir.filePath("movie.gif"), false, &error))
      << error.toStdString();
  EXPECT_EQ(read_all(dir.filePath("movie.gif")).substr(0, 6), "GIF89a");
  EXPECT_FALSE(export_video(&window(), dir.filePath("movie.avi"), false, &error));
  EXPECT_TRUE(error.contains("mp4, gif, ogv")) << error.toStdString();
  EXPECT_FALSE(QFileInfo::exists(dir.filePath("movie.avi")));
}

// The CSV's header line and the number of rows after it, each row starting with its frame.
std::pair<std::string, int> read_csv(const QString& path) {
  std::istringstream csv(read_all(path));
  std::string header;
  std::getline(csv, header);
  int rows = 0;
  for (std::string line; std::getline(csv, line);) {
    if (line.empty()) continue;
    EXPECT_EQ(line.rfind(std::to_string(rows) + ",", 0), 0u) << line;
    ++rows;
  }
  return {header, rows};
}

TEST_F(ExportTest, PlaneCsvHasTheAnimateHeaderAndOneRowPerFrameAndIsNotOverwritten) {
  QTemporaryDir dir;
  play_short_script(window(), dir);
  const QString path = dir.filePath("frames.csv");
  QString error;
  ASSERT_TRUE(export_frame_csv(&window(), path, false, &error)) << error.toStdString();
  const auto [header, rows] = read_csv(path);
  EXPECT_EQ(header.rfind("frame,level,visible,", 0), 0u) << header;
  EXPECT_EQ(rows, kFrames);

  const std::string before = read_all(path);
  EXPECT_FALSE(export_frame_csv(&window(), path, false, &error));
  EXPECT_TRUE(error.contains("exists")) << error.toStdString();
  EXPECT_EQ(read_all(path), before);
}

// Scenes and scene shifting export the per-polygon-level columns of `oflab-cli animate
// --scene`, one row per frame of their viewer script.
TEST_F(ExportTest, SceneAndSceneShiftingCsvsHaveTheSceneHeaderAndOneRowPerFrame) {
  QTemporaryDir dir;
  const SourceChoice sources[] = {{"scene", "two", "translate"},
                                  {"scene-shifting", "train-window", "train-sideways"}};
  for (const SourceChoice& source : sources) {
    ASSERT_TRUE(window().model()->animation()->set_source(source))
        << window().message().toStdString();
    const int frames = window().model()->animation()->animator()->frame_count();
    const QString path = dir.filePath(QString::fromStdString(source.kind + ".csv"));
    QString error;
    ASSERT_TRUE(export_frame_csv(&window(), path, false, &error)) << error.toStdString();
    const auto [header, rows] = read_csv(path);
    EXPECT_EQ(header.rfind("frame,polygons,drawn,none,translate,affine,perspective,rerender,", 0),
              0u)
        << source.kind << ": " << header;
    EXPECT_EQ(rows, frames) << source.kind;
  }
}

// File > Export > ParaView data: the flow of the scene model's pose and the current frame of
// the animation view, read back with VTK's readers; an existing directory is kept.
TEST_F(ExportTest, ParaViewDataHasTheFlowAndTheCurrentFrameAndKeepsAnExistingDirectory) {
  QTemporaryDir dir;
  play_short_script(window(), dir);
  window().model()->scene()->set_frame(3);
  const QString out = dir.filePath("paraview");
  QString error;
  ASSERT_TRUE(export_paraview_data(&window(), out, false, &error)) << error.toStdString();

  vtkNew<vtkXMLImageDataReader> flow;
  flow->SetFileName((out + "/flow.vti").toStdString().c_str());
  flow->Update();
  vtkImageData* grid = flow->GetOutput();
  ASSERT_GT(grid->GetNumberOfPoints(), 0);
  // Against the projection of the 3D velocity of the plane point seen at the grid point
  // nearest the principal point (on the plane: it faces the eye on the line of sight).
  const PlaneScene& scene = window().model()->scene()->scene();
  const vtkIdType k = grid->FindPoint(0.0, 0.0, 0.0);
  double xyz[3];
  grid->GetPoint(k, xyz);
  const Vec2 want = exact_flow_at(scene.camera, scene.pose, scene.motion, Vec2(xyz[0], xyz[1]));
  vtkDataArray* vectors = grid->GetPointData()->GetArray("flow");
  EXPECT_NEAR(vectors->GetComponent(k, 0), want.x, 1e-9 * std::max(1.0, glm::length(want)));
  EXPECT_NEAR(vectors->GetComponent(k, 1), want.y, 1e-9 * std::max(1.0, glm::length(want)));

  vtkNew<vtkXMLImageDataReader> shown;
  shown->SetFileName((out + "/frame_00003_shown.vti").toStdString().c_str());
  shown->Update();
  int dims[3];
  shown->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 320);
  EXPECT_EQ(dims[1], 240);
  for (const char* name : {"exact", "difference", "layers"}) {
    const QString pvd = read_all(out + "/" + name + ".pvd").c_str();
    EXPECT_TRUE(pvd.contains("timestep=\"3\"")) << name;
  }
  const std::string before = read_all(out + "/flow.vti");
  window().model()->scene()->set_frame(5);
  EXPECT_FALSE(export_paraview_data(&window(), out, false, &error));
  EXPECT_TRUE(error.contains("not empty")) << error.toStdString();
  EXPECT_EQ(read_all(out + "/flow.vti"), before);
  EXPECT_FALSE(QFileInfo::exists(out + "/frame_00005_shown.vti"));
}

// The CSV and the PNG frames go through the atomic writer: a device is never written (a plain
// stream would write into /dev/full), and a successful export leaves no temporary file.
TEST_F(ExportTest, CsvAndPngExportsAreWrittenWholeAndNeverIntoADevice) {
  QTemporaryDir dir;
  play_short_script(window(), dir, 3);
  QString error;
  EXPECT_FALSE(export_frame_csv(&window(), QStringLiteral("/dev/full"), true, &error));
  EXPECT_TRUE(error.contains("not a regular file")) << error.toStdString();
  const QString path = dir.filePath("frames.csv");
  ASSERT_TRUE(export_frame_csv(&window(), path, false, &error)) << error.toStdString();
  ASSERT_TRUE(export_frames_png(&window(), dir.filePath("png"), false, &error))
      << error.toStdString();
  for (const QString& folder : {dir.path(), dir.filePath("png")}) {
    const QStringList left = QDir(folder).entryList({".*.tmp-*"}, QDir::Files | QDir::Hidden);
    EXPECT_TRUE(left.isEmpty()) << left.join(", ").toStdString();
  }
}

}  // namespace
}  // namespace oflab::test
