// ParaView data read back with VTK's own readers (vtkXMLImageDataReader, vtkXMLPolyDataReader)
// and the .pvd series parsed as XML: `flow --vtk` against `flow --json` (the flow computed
// here from the printed coefficients, and the projection of the 3D velocity), `animate
// --vtk-series` against the run, and the refusals.
#include "formats/vtk_export.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "cli_capture.h"
#include "flow/flow_field.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::exact_text;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

// A tilted, finite plane moving and turning: every Taylor order is non-zero.
const Camera kCamera = make_camera(500.0, 640, 480);
const PlanePose kPose{Vec3(0.1, -0.05, 2.0), Vec3(0.3, -0.2, 1.0), Vec3(0.0, -1.0, 0.0),
                      Vec2(3.0, 2.0)};
const RigidMotion kMotion{Vec3(0.2, -0.1, 0.3), Vec3(0.05, 0.08, -0.1)};

std::vector<std::string> flow_args(const RigidMotion& motion, const std::string& vti,
                                   const std::vector<std::string>& extra = {}) {
  std::vector<std::string> a = {"flow", "--focal", "500", "--image", "640", "480"};
  const auto add = [&](const char* option, const Vec3& v) {
    a.insert(a.end(), {option, exact_text(v.x), exact_text(v.y), exact_text(v.z)});
  };
  add("--plane-point", kPose.point);
  add("--plane-normal", kPose.normal);
  add("--plane-up", kPose.up);
  a.insert(a.end(), {"--plane-size", exact_text(kPose.size.x), exact_text(kPose.size.y)});
  add("--velocity", motion.velocity);
  add("--omega", motion.omega);
  a.insert(a.end(), {"--json", "--vtk", vti});
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

vtkSmartPointer<vtkImageData> read_vti(const fs::path& file) {
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

vtkSmartPointer<vtkPolyData> read_vtp(const fs::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

// The flow at centred p from the coefficients `flow --json` printed, by the planar flow's
// formula (core/flow/flow_field.h's header), and its orders.
struct JsonFlow {
  Vec2 translation, first, second;
  Vec2 total() const { return translation + first + second; }
};
JsonFlow json_flow(const nlohmann::json& k, const Vec2& p) {
  const auto c = [&](const char* name) { return k.at(name).get<double>(); };
  const double q = c("px") * p.x + c("py") * p.y;
  return {Vec2(c("tx"), c("ty")),
          Vec2(c("j11") * p.x + c("j12") * p.y, c("j21") * p.x + c("j22") * p.y), q * p};
}

Vec2 vec2_at(vtkImageData* grid, const char* array, vtkIdType k) {
  vtkDataArray* a = grid->GetPointData()->GetArray(array);
  EXPECT_NE(a, nullptr) << array;
  if (!a) return Vec2(NAN, NAN);
  return Vec2(a->GetComponent(k, 0), a->GetComponent(k, 1));
}

// Largest relative difference |a - b| / max(|b|, 1 px/s) of the arrays against `flow --json`
// over every grid point.
double worst_relative_difference(vtkImageData* grid, const nlohmann::json& coefficients) {
  double worst = 0.0;
  for (vtkIdType k = 0; k < grid->GetNumberOfPoints(); ++k) {
    double xyz[3];
    grid->GetPoint(k, xyz);
    const Vec2 p(xyz[0], xyz[1]);
    const JsonFlow want = json_flow(coefficients, p);
    const auto rel = [&](const Vec2& got, const Vec2& expected) {
      return glm::length(got - expected) / std::max(glm::length(expected), 1.0);
    };
    worst = std::max({worst, rel(vec2_at(grid, "flow", k), want.total()),
                      rel(vec2_at(grid, "translation", k), want.translation),
                      rel(vec2_at(grid, "first_order", k), want.first),
                      rel(vec2_at(grid, "second_order", k), want.second)});
    const double magnitude = grid->GetPointData()->GetArray("magnitude")->GetTuple1(k);
    worst = std::max(worst, std::abs(magnitude - glm::length(want.total())) /
                                std::max(glm::length(want.total()), 1.0));
  }
  return worst;
}

TEST(VtkExport, FlowVtiReadsBackAndMatchesFlowJsonAtEveryGridPoint) {
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  const fs::path vti = dir / "flow.vti";
  const CliResult r = run(flow_args(kMotion, vti.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  vtkSmartPointer<vtkImageData> grid = read_vti(vti);
  ASSERT_EQ(grid->GetNumberOfPoints(), 161 * 121);  // -320..320 by 4, -240..240 by 4
  EXPECT_LT(worst_relative_difference(grid, j["coefficients"]), 1e-9);
  fs::remove_all(dir);
}

TEST(VtkExport, FlowVtiMatchesTheProjectedVelocityOnThePlane) {
  // Independent of the coefficients: the projection of the 3D velocity V + Omega x R of the
  // plane point seen at each sample point.
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  const fs::path vti = dir / "flow.vti";
  ASSERT_EQ(run(flow_args(kMotion, vti.string(), {"--vtk-step", "10"})).code, 0);
  vtkSmartPointer<vtkImageData> grid = read_vti(vti);
  int checked = 0;
  for (vtkIdType k = 0; k < grid->GetNumberOfPoints(); k += 37) {
    double xyz[3];
    grid->GetPoint(k, xyz);
    const Vec2 p(xyz[0], xyz[1]);
    const Vec2 want = exact_flow_at(kCamera, kPose, kMotion, p);
    EXPECT_LT(glm::length(vec2_at(grid, "flow", k) - want), 1e-9 * std::max(glm::length(want), 1.0))
        << "at " << p.x << ", " << p.y;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  fs::remove_all(dir);
}

TEST(VtkExport, FlowVtiOfAnotherMotionDoesNotMatchTheJson) {
  // Negative control: the comparison above fails for the file of another motion.
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  const CliResult r = run(flow_args(kMotion, (dir / "a.vti").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  RigidMotion other = kMotion;
  other.omega.z += 0.01;
  ASSERT_EQ(run(flow_args(other, (dir / "b.vti").string())).code, 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(worst_relative_difference(read_vti(dir / "b.vti"), j["coefficients"]), 1e-3);
  fs::remove_all(dir);
}

TEST(VtkExport, FlowGridHasThePrincipalPointAndStaysInsideTheImage) {
  const Camera odd = make_camera(300.0, 101, 77);  // principal point at (50.5, 38.5)
  const FlowGrid g = flow_grid(odd, 5);
  EXPECT_DOUBLE_EQ(g.x0, -50.0);  // the first multiple of 5 right of -50.5
  EXPECT_DOUBLE_EQ(g.y0, -35.0);
  EXPECT_EQ(g.columns, 21);  // -50 .. 50
  EXPECT_EQ(g.rows, 15);     // -35 .. 35
  EXPECT_EQ(flow_grid(kCamera, 1).points(), 641L * 481L);
}

TEST(VtkExport, RefusesAGridOverItsLimitNamingTheFigureAndTheStep) {
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  std::vector<std::string> args =
      flow_args(kMotion, (dir / "big.vti").string(), {"--vtk-step", "1"});
  args[4] = args[5] = "8192";  // --image 8192 8192
  const CliResult r = run(args);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err,
            "oflab-cli flow: --vtk-step: 1 gives 8193 x 8193 = 67125249 grid points, more than "
            "1048576; a step of 9 or more fits\n");
  EXPECT_FALSE(fs::exists(dir / "big.vti"));
  EXPECT_NE(run(flow_args(kMotion, (dir / "a.vti").string(), {"--vtk-step", "0"}))
                .err.find("--vtk-step: 0 is outside 1..1024 px"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(VtkExport, RefusesAnotherExtensionAndAnExistingFileWithoutForce) {
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  EXPECT_EQ(run(flow_args(kMotion, (dir / "flow.vtk").string())).err,
            "oflab-cli flow: --vtk: '" + (dir / "flow.vtk").string() +
                "' does not end in .vti (VTK XML image data)\n");
  const fs::path vti = dir / "flow.vti";
  { std::ofstream(vti) << "keep"; }
  const CliResult refused = run(flow_args(kMotion, vti.string()));
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("add --force"), std::string::npos) << refused.err;
  EXPECT_EQ(testing::file_contents(vti), "keep");
  EXPECT_EQ(run(flow_args(kMotion, vti.string(), {"--force"})).code, 0);
  EXPECT_EQ(read_vti(vti)->GetNumberOfPoints(), 161 * 121);
  fs::remove_all(dir);
}

// The (timestep, file) pairs of a .pvd, in order.
std::vector<std::pair<double, std::string>> pvd_entries(const fs::path& pvd) {
  const std::string xml = testing::file_contents(pvd);
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\""), std::string::npos);
  const std::regex entry("<DataSet timestep=\"([^\"]*)\"[^>]*file=\"([^\"]*)\"/>");
  std::vector<std::pair<double, std::string>> entries;
  for (auto m = std::sregex_iterator(xml.begin(), xml.end(), entry); m != std::sregex_iterator();
       ++m) {
    entries.emplace_back(std::stod((*m)[1]), (*m)[2]);
  }
  return entries;
}

double array_max(vtkDataArray* a) {
  double range[2];
  a->GetRange(range, 0);
  return range[1];
}

// `animate` with `source` (its source and frame options), one untimed pass, the series into
// `series`.
CliResult animate_series(std::vector<std::string> source, const fs::path& series) {
  std::vector<std::string> args = {"animate"};
  args.insert(args.end(), source.begin(), source.end());
  args.insert(args.end(),
              {"--repeat-timing", "1", "--no-warm-up", "--vtk-series", series.string(), "--json"});
  return run(args);
}

TEST(VtkExport, AnimateSeriesHasEveryFrameOfEachPartReadableWithTheFrameAsTime) {
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  const fs::path series = dir / "series";
  const CliResult r =
      animate_series({"--script", "rotation", "--mode", "affine", "--frames", "4"}, series);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* part : {"shown", "exact", "difference", "layers"}) {
    const auto entries = pvd_entries(series / (std::string(part) + ".pvd"));
    ASSERT_EQ(entries.size(), 4u) << part;
    for (int f = 0; f < 4; ++f) {
      EXPECT_EQ(entries[f].first, f);
      EXPECT_TRUE(fs::is_regular_file(series / entries[f].second)) << entries[f].second;
    }
  }
  // rotation: 640 x 480. The shown image covers the exact one's grid; frame 0 is re-rendered, so
  // it equals the exact frame; the affine frames after it differ.
  vtkSmartPointer<vtkImageData> shown = read_vti(series / "frame_00000_shown.vti");
  int dims[3];
  shown->GetDimensions(dims);
  EXPECT_EQ(dims[0], 640);
  EXPECT_EQ(dims[1], 480);
  EXPECT_EQ(shown->GetPointData()->GetArray("rgba")->GetNumberOfComponents(), 4);
  EXPECT_GT(array_max(shown->GetPointData()->GetArray("rgba")), 0.0);
  EXPECT_EQ(
      array_max(
          read_vti(series / "frame_00000_difference.vti")->GetPointData()->GetArray("difference")),
      0.0);
  EXPECT_GT(
      array_max(
          read_vti(series / "frame_00003_difference.vti")->GetPointData()->GetArray("difference")),
      0.0);
  // One layer, the plane, re-rendered (level 4) at frame 0 and warped affinely (2) after.
  vtkSmartPointer<vtkPolyData> layers0 = read_vtp(series / "frame_00000_layers.vtp");
  ASSERT_EQ(layers0->GetNumberOfPolys(), 1);
  EXPECT_EQ(layers0->GetCellData()->GetArray("level")->GetTuple1(0), 4.0);
  EXPECT_EQ(layers0->GetCellData()->GetArray("error_px")->GetTuple1(0), 0.0);
  vtkSmartPointer<vtkPolyData> layers3 = read_vtp(series / "frame_00003_layers.vtp");
  ASSERT_EQ(layers3->GetNumberOfPolys(), 1);
  EXPECT_EQ(layers3->GetCellData()->GetArray("level")->GetTuple1(0), 2.0);
  const double error3 = layers3->GetCellData()->GetArray("error_px")->GetTuple1(0);
  EXPECT_GT(error3, 0.0);
  // The outline's points are in centred pixels: about the principal point (the rotation script's
  // plane spins facing the eye on the line of sight).
  double bounds[6];
  layers3->GetBounds(bounds);
  EXPECT_NEAR(bounds[0] + bounds[1], 0.0, 2.0);
  EXPECT_NEAR(bounds[2] + bounds[3], 0.0, 2.0);
  EXPECT_GT(bounds[1], 0.0);
  fs::remove_all(dir);
}

TEST(VtkExport, AnimateSeriesOfASceneHasOnePolygonCellPerDrawnLayer) {
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  const fs::path series = dir / "series";
  const CliResult r =
      animate_series({"--scene", "four-cubes", "--script", "circle", "--frames", "2"}, series);
  ASSERT_EQ(r.code, 0) << r.err;
  vtkSmartPointer<vtkPolyData> layers = read_vtp(series / "frame_00001_layers.vtp");
  EXPECT_GT(layers->GetNumberOfPolys(), 1);
  vtkDataArray* polygon = layers->GetCellData()->GetArray("polygon");
  std::set<int> distinct;
  for (vtkIdType k = 0; k < polygon->GetNumberOfTuples(); ++k)
    distinct.insert(static_cast<int>(polygon->GetTuple1(k)));
  EXPECT_EQ(static_cast<vtkIdType>(distinct.size()), layers->GetNumberOfPolys());
  fs::remove_all(dir);
}

TEST(VtkExport, AnimateSeriesRefusesANonEmptyDirectoryWithoutForceAndReplacesItWithForce) {
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  const fs::path series = dir / "series";
  fs::create_directories(series);
  { std::ofstream(series / "old.txt") << "old"; }
  const std::vector<std::string> args = {
      "animate",         "--script", "zoom",         "--frames",     "2",
      "--repeat-timing", "1",        "--no-warm-up", "--vtk-series", series.string()};
  const CliResult refused = run(args);
  EXPECT_EQ(refused.code, 2);
  EXPECT_EQ(refused.err, "oflab-cli animate: --vtk-series: '" + series.string() +
                             "' is not empty (add --force to replace it)\n");
  EXPECT_EQ(testing::file_contents(series / "old.txt"), "old");
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  ASSERT_EQ(run(forced).code, 0);
  EXPECT_FALSE(fs::exists(series / "old.txt"));  // replaced whole: no stale file
  EXPECT_EQ(pvd_entries(series / "shown.pvd").size(), 2u);
  // Nothing but the series beside it (no temporary left).
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path() != series ? 1 : 0;
  EXPECT_EQ(entries, 0);
  fs::remove_all(dir);
}

TEST(VtkExport, DifferenceIsTheLargestChannelDifference) {
  const Camera camera = make_camera(100.0, 3, 2);
  Image a(3, 2), b(3, 2);
  a.at(0, 0) = {10, 20, 30, 40};
  b.at(0, 0) = {12, 15, 30, 40};  // 2, 5, 0, 0
  b.at(2, 1) = {0, 0, 0, 200};
  const fs::path dir = testing::fresh_test_dir("oflab-vtk");
  { std::ofstream(dir / "d.vti", std::ios::binary) << difference_vti(camera, a, b); }
  vtkSmartPointer<vtkImageData> d = read_vti(dir / "d.vti");
  vtkDataArray* values = d->GetPointData()->GetArray("difference");
  ASSERT_EQ(values->GetNumberOfTuples(), 6);
  EXPECT_EQ(values->GetTuple1(0), 5.0);
  EXPECT_EQ(values->GetTuple1(5), 200.0);  // pixel (2, 1): row-major, x fastest
  EXPECT_EQ(values->GetTuple1(1), 0.0);
  double xyz[3];
  d->GetPoint(5, xyz);  // pixel (2, 1)'s centre, centred: (2.5 - 1.5, 1.5 - 1)
  EXPECT_DOUBLE_EQ(xyz[0], 1.0);
  EXPECT_DOUBLE_EQ(xyz[1], 0.5);
  EXPECT_THROW(difference_vti(camera, a, Image(2, 2)), std::invalid_argument);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
