// Frame generation, view interpolation and the depth mesh from the command line
// (manual/policies.md "Frame generation by extrapolation", "View interpolation", "Textured depth
// meshes"): the motion-vector policies, view-interpolation and depth-mesh run on every shipped
// scene and viewer script, and the comparison's rows carry their holes, inpainting and latency.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_capture.h"
#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "runs/policy_runs.h"
#include "runs/source_kinds.h"

namespace oflab {
namespace {

using testing::CliResult;

// Both motion-vector policies, view interpolation and the depth mesh on a scene and viewer
// script, three frames (render, generated, interpolated or meshed, render), one pass without the
// exact baseline: what is checked is that they run.
std::vector<PolicyRun> play_generation(const std::string& scene, const std::string& script) {
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(scene)));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path(script));
  PlayOptions options;
  options.max_frames = 3;
  options.warm_up = false;
  options.timing_repetitions = 1;
  options.baseline = false;
  return run_policies(source_kind("scene"), source,
                      parse_policy_list("mv-extrapolation,mv-no-inpaint,view-interpolation,"
                                        "depth-mesh"),
                      options);
}

TEST(FrameGenerationCommand, RunsOnEveryShippedSceneAndViewerScript) {
  const std::vector<std::string> scenes = shipped_names("scenes");
  const std::vector<std::string> scripts = shipped_names("viewer-scripts");
  ASSERT_GE(scenes.size(), 10u);
  ASSERT_GE(scripts.size(), 10u);
  std::vector<std::pair<std::string, std::string>> runs;
  for (const std::string& scene : scenes) runs.push_back({scene, "compound"});
  for (const std::string& script : scripts) runs.push_back({"two-cubes", script});
  for (const auto& [scene, script] : runs) {
    std::vector<PolicyRun> played;
    ASSERT_NO_THROW(played = play_generation(scene, script)) << scene << ", " << script;
    ASSERT_EQ(played.size(), 4u);
    for (const PolicyRun& run : played) {
      ASSERT_EQ(run.run.frames.size(), 3u) << scene << ", " << script;
      // Frame 1 is generated (interpolated): every drawn polygon counted at that level; the
      // depth mesh's near polygons are rendered, its far ones meshed.
      const AnimationFrame& generated = run.run.frames[1];
      const int rendered = generated.levels[static_cast<int>(Level::kRerender)];
      if (run.policy->pixel_motion == PixelMotion::kFarMesh) {
        EXPECT_EQ(rendered + generated.levels[static_cast<int>(Level::kPerspective)],
                  generated.drawn())
            << scene << ", " << script;
      } else {
        EXPECT_EQ(rendered, 0);
      }
      EXPECT_GE(generated.hole_pixels, 0);
      if (!run.policy->inpaint) EXPECT_EQ(generated.inpainted_pixels, 0);
    }
  }
}

// The comparison's rows of a scene carry the holes, the inpainted pixels, PSNR, SSIM and the
// latency of every policy; the inpainting variant fills exactly the pixels no splat reached.
TEST(FrameGenerationCommand, CompareRowsCarryHolesInpaintingPsnrSsimAndLatency) {
  const CliResult r = testing::run_cli_captured(
      {"compare", "--scene", "four-cubes", "--script", "translate", "--policies",
       "perspective,depth-reprojection,mv-extrapolation,mv-no-inpaint,view-interpolation,"
       "depth-mesh",
       "--frames", "5", "--json", "--repeat-timing", "1"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out).at("policies");
  ASSERT_EQ(rows.size(), 6u);
  for (const auto& row : rows) {
    for (const char* field :
         {"hole_pixels", "inpainted_pixels", "mean_psnr_db", "mean_ssim", "latency_frames"}) {
      EXPECT_TRUE(row.contains(field)) << row["name"] << " " << field;
    }
    // At cadence 2 view interpolation shows each frame one frame late; the others extrapolate.
    EXPECT_EQ(row["latency_frames"], row["name"] == "view-interpolation" ? 1 : 0) << row["name"];
    EXPECT_GT(row["mean_ssim"].get<double>(), 0.0) << row["name"];
    EXPECT_LE(row["mean_ssim"].get<double>(), 1.0) << row["name"];
  }
  EXPECT_EQ(rows[0]["hole_pixels"], 0);  // a layer warp shows every layer whole
  EXPECT_EQ(rows[0]["inpainted_pixels"], 0);
  EXPECT_EQ(rows[3]["inpainted_pixels"], 0);
  EXPECT_GT(rows[2]["inpainted_pixels"].get<long>(), 0);
  // Inpainting fills the holes (and revealed background) the raw frames leave empty.
  EXPECT_GE(rows[2]["inpainted_pixels"].get<long>(), rows[3]["hole_pixels"].get<long>());
  EXPECT_EQ(rows[2]["hole_pixels"], rows[3]["hole_pixels"]);
  EXPECT_GT(rows[2]["mean_psnr_db"].get<double>(), rows[3]["mean_psnr_db"].get<double>());
  // Extrapolating a steady slide: the error stays near the splat's resampling.
  EXPECT_GT(rows[2]["max_measured_error_px"].get<double>(), 0.0);
  // Interpolating between two renders reveals what either saw: fewer holes than depth
  // reprojection from the last render alone, nothing inpainted.
  EXPECT_LT(rows[4]["hole_pixels"].get<long>(), rows[1]["hole_pixels"].get<long>());
  EXPECT_EQ(rows[4]["inpainted_pixels"], 0);
  // The depth mesh renders the near cubes every frame and meshes the far ones: an error of its
  // mesh's pixels, holes only where it dropped rubber sheets, at no latency.
  EXPECT_EQ(rows[5]["name"], "depth-mesh");
  EXPECT_GT(rows[5]["max_measured_error_px"].get<double>(), 0.0);
  EXPECT_EQ(rows[5]["inpainted_pixels"], 0);
}

// The depth mesh's options: out of their limits, with an unknown word, or without depth-mesh
// among the compared policies, each is refused in one line naming it, exit code 2.
TEST(FrameGenerationCommand, MeshOptionsOutOfRangeOrWithoutDepthMeshAreRefused) {
  const std::vector<std::string> base = {"compare",   "--scene",  "four-cubes", "--script",
                                         "translate", "--frames", "2"};
  const struct {
    std::vector<std::string> extra;
    std::string message;
  } cases[] = {
      {{"--policies", "depth-mesh", "--mesh-grid", "0"}, "--mesh-grid"},
      {{"--policies", "depth-mesh", "--mesh-jump", "-1"}, "--mesh-jump"},
      {{"--policies", "depth-mesh", "--rubber-sheets", "sideways"}, "--rubber-sheets: 'sideways'"},
      {{"--policies", "perspective", "--mesh-split", "3"}, "--mesh-split: needs one of depth-mesh"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = base;
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const CliResult r = testing::run_cli_captured(args);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace oflab
