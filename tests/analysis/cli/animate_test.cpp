// The seven Experiment 1 scripts behave as section 6.4 describes (properties of the level
// counts), the error budget holds in every mode, and `oflab-cli animate` keeps its
// command-line contract.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.h"
#include "cli_capture.h"
#include "flow/homography.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/script_file.h"
#include "runs/source_kinds.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// Documented in manual/animation.md ("The exact check"): how far the measured corner error
// may exceed the budget of the level in force. The whole-pixel placement of a translated
// layer is measured, not allowed for, so none; kTolerancePx is floating-point rounding.
constexpr double kSamplingAllowancePx = 0.0;
constexpr double kTolerancePx = 1e-9;

// The engine's reports of a script played as the plane kind, without the baseline.
struct ScriptRun {
  std::vector<FrameReport> reports;
  RunSummary summary;
};

ScriptRun run_script(const std::string& name, const std::string& policy,
                     Sampling sampling = Sampling::kNearest) {
  static const Image texture = read_image(default_texture_path());
  RunSource source;
  source.script = read_script_file(resolve_script_path(name));
  source.texture = texture;
  source.settings.engine.policy = &reuse_policy(policy);
  source.settings.engine.sampling = sampling;
  PlayOptions o;
  o.baseline = false;
  const AnimationRun run = source_kind("plane").play(source, o);
  ScriptRun r{{}, run.summary};
  for (const AnimationFrame& f : run.frames) r.reports.push_back(f.layer_reports.at(0));
  return r;
}

// Frames at level `l` (a plane frame not visible counts at its engine's level).
int count(const ScriptRun& r, Level l) {
  int n = 0;
  for (const FrameReport& f : r.reports) n += f.level == l;
  return n;
}

TEST(Experiment1, StationaryIsAllNoUpdate) {
  const ScriptRun r = run_script("stationary", "perspective");
  EXPECT_EQ(count(r, Level::kNone), r.summary.frames - 1);
  EXPECT_EQ(r.reports[0].level, Level::kRerender);
}

TEST(Experiment1, TranslationOneAlternatesNoUpdateAndTranslate) {
  // 0.77 px per frame: two frames without an update would owe more than 1 px. Whole-pixel
  // translations leave a sub-pixel rest, so now and then two translations follow each
  // other (the rest plus a frame's motion exceeds the budget).
  const ScriptRun r = run_script("translation-1", "perspective");
  EXPECT_EQ(count(r, Level::kNone) + count(r, Level::kTranslate), r.summary.frames - 1);
  for (size_t i = 2; i < r.reports.size(); ++i) {
    EXPECT_FALSE(r.reports[i].level == Level::kNone && r.reports[i - 1].level == Level::kNone)
        << "frame " << i;
  }
  EXPECT_GE(count(r, Level::kTranslate), 0.45 * r.summary.frames);
  EXPECT_LE(count(r, Level::kTranslate), 0.65 * r.summary.frames);
}

TEST(Experiment1, ZoomIsMostlyNoUpdateAndAffine) {
  const ScriptRun r = run_script("zoom", "perspective");
  EXPECT_GE(count(r, Level::kNone) + count(r, Level::kAffine), 0.8 * r.summary.frames);
  EXPECT_GT(count(r, Level::kNone), 0);
  EXPECT_GT(count(r, Level::kAffine), 0);
  EXPECT_EQ(count(r, Level::kPerspective), 0);
}

TEST(Experiment1, RotationNeedsAffineWarpsAndRerenders) {
  const ScriptRun r = run_script("rotation", "perspective");
  EXPECT_GT(count(r, Level::kAffine), r.summary.frames / 2);
  EXPECT_GT(count(r, Level::kRerender), 5);
  EXPECT_EQ(count(r, Level::kPerspective), 0);
}

TEST(Experiment1, LoopUsesPerspectiveNearTheViewerAndCheapLevelsFarAway) {
  const MotionScript s = read_script_file(resolve_script_path("loop"));
  const ScriptRun r = run_script("loop", "perspective");
  EXPECT_GT(count(r, Level::kPerspective), 0);
  double persp_depth = 0, cheap_depth = 0;
  int persp = 0, cheap = 0;
  for (const FrameReport& f : r.reports) {
    const double z = s.frames[f.frame].pose.point.z;
    if (f.level == Level::kPerspective) persp_depth += z, ++persp;
    if (f.level == Level::kNone || f.level == Level::kTranslate) cheap_depth += z, ++cheap;
  }
  ASSERT_GT(cheap, 0);
  EXPECT_LT(persp_depth / persp, cheap_depth / cheap);
}

TEST(Experiment1, MeasuredErrorStaysWithinTheBudgetInEveryModeAndScript) {
  // Every shipped script, every policy: the measured error (from where the pixels are)
  // stays within the threshold plus the allowance, and a reused frame's estimate bounds it
  // (the affine policy's view misses its perspective on top, affine_view_error_px).
  for (const std::string& name : shipped_script_names()) {
    for (const ReusePolicy& policy : reuse_policies()) {
      if (!policy.bounded) continue;  // the printed rule does not bound it (manual/policies.md)
      const std::string mode = policy.name;
      const ScriptRun r = run_script(name, mode);
      for (const FrameReport& f : r.reports) {
        if (!f.visible) continue;
        const double view = f.affine_view_error_px;
        EXPECT_LE(f.measured_error_px, 1.0 + kSamplingAllowancePx + kTolerancePx + view)
            << name << " " << mode << " frame " << f.frame;
        if (f.level == Level::kRerender) continue;
        EXPECT_LE(f.measured_error_px, f.estimated_error_px + kTolerancePx + view)
            << name << " " << mode << " frame " << f.frame;
      }
      if (policy.initial_view == InitialView::kExact) {
        EXPECT_LE(r.summary.max_excess_px, kTolerancePx) << name << " " << mode;
      }
    }
  }
}

TEST(Experiment1, ReuseErrorSeparatesWhatReuseAddsFromTheAffineView) {
  // reuse_error_px measures the shown layer against the policy's own view: zero on a
  // re-render, equal to the measured error under an exact initial view, and with the affine
  // view's own error it bounds the measured error (triangle inequality at each corner).
  for (const char* mode : {"affine", "perspective"}) {
    int reused = 0;
    for (const char* script : {"swing", "loop"}) {
      const ScriptRun r = run_script(script, mode);
      for (const FrameReport& f : r.reports) {
        if (!f.visible) continue;
        if (f.level == Level::kRerender) {
          EXPECT_LT(f.reuse_error_px, kTolerancePx) << mode << " frame " << f.frame;
        } else {
          ++reused;
        }
        if (std::string(mode) == "perspective") {
          EXPECT_DOUBLE_EQ(f.reuse_error_px, f.measured_error_px) << "frame " << f.frame;
        } else {
          EXPECT_LE(f.measured_error_px, f.affine_view_error_px + f.reuse_error_px + kTolerancePx)
              << "frame " << f.frame;
        }
      }
    }
    EXPECT_GT(reused, 0) << mode;  // the bound was tested on reused frames too
  }
}

// Alpha-weighted centroid of an image (premultiplied: alpha is the weight), top-left pixels.
Vec2 alpha_centroid(const Image& image) {
  double sum = 0.0;
  Vec2 c(0.0);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const double a = image.at(x, y).a;
      sum += a;
      c += a * Vec2(x + 0.5, y + 0.5);
    }
  }
  return sum > 0.0 ? c / sum : Vec2(std::nan(""));
}

TEST(Experiment1, TranslationOneMeasuredErrorIsNeverBelowTheShownDisplacement) {
  // An independent measure of what is shown: the alpha-weighted centroid of the shown frame
  // against that of the exact render of the same pose (bilinear, so sub-pixel positions
  // show), while the plane lies wholly inside the image.
  const MotionScript script = read_script_file(resolve_script_path("translation-1"));
  const Image texture = read_image(default_texture_path());
  EngineSettings settings;
  settings.sampling = Sampling::kBilinear;
  EngineSettings exact = settings;
  exact.policy = &reuse_policy("rerender");
  const auto shown = make_plane_animator(script, texture, settings);
  const auto truth = make_plane_animator(script, texture, exact);
  int compared = 0, displaced = 0;
  for (int i = 0; i < shown->frame_count(); ++i) {
    const AnimationFrame f = i == 0 ? shown->start() : shown->advance();
    if (i == 0)
      truth->start();
    else
      truth->advance();
    const FrameReport& r = f.layer_reports.at(0);
    bool inside = true;
    for (const Vec2& p : projected_corners(script.camera, script.frames[i].pose)) {
      const Vec2 q = centred_to_pixel(script.camera, p);
      inside = inside && q.x > 1 && q.y > 1 && q.x < script.camera.width - 1 &&
               q.y < script.camera.height - 1;
    }
    if (!inside) continue;
    const double d = glm::length(alpha_centroid(shown->image()) - alpha_centroid(truth->image()));
    EXPECT_GE(r.measured_error_px + 0.01, d) << "frame " << i;
    ++compared;
    displaced += d > 0.1;
  }
  EXPECT_GT(compared, 30);
  EXPECT_GT(displaced, 10);  // the check has teeth: most frames show a sub-pixel offset
}

TEST(AnimateCommand, PlaneFlyingIntoTheEyePlaysToItsEndClippedThenNotVisible) {
  const ScriptRun r = run_script("approach", "perspective");
  int clipped = 0, hidden = 0;
  for (const FrameReport& f : r.reports) {
    clipped += f.clipped;
    hidden += !f.visible;
  }
  EXPECT_EQ(r.reports.size(), 14u);
  EXPECT_GT(clipped, 0);
  EXPECT_GT(hidden, 0);
  const testing::CliResult c =
      testing::run_cli_captured({"animate", "--script", "approach", "--json", "--quiet"});
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["invisible_frames"].get<int>(), hidden);
}

TEST(AnimateCommand, PlaneLeavingTheImageIsNotVisibleInTheCsv) {
  const fs::path dir = testing::fresh_test_dir("oflab-leaving-plane");
  nlohmann::json script =
      nlohmann::json::parse(std::ifstream(resolve_script_path("translation-1")));
  script["segments"][0]["frames"] = 30;
  script["segments"][0]["velocity"] = {0.1, 0.0, 0.0};  // 25.6 px per frame, out by frame 20
  std::ofstream(dir / "leaving.json") << script.dump();
  const testing::CliResult c =
      testing::run_cli_captured({"animate", "--script", (dir / "leaving.json").string(), "--out",
                                 (dir / "out").string(), "--quiet"});
  ASSERT_EQ(c.code, 0) << c.err;
  std::ifstream csv(dir / "out" / "frames.csv");
  std::string line;
  std::getline(csv, line);
  int outside = 0;
  while (std::getline(csv, line)) {
    const bool hidden = line.find(",rerender,0,") != std::string::npos;
    const bool noted = line.find("\"outside the image\"") != std::string::npos;
    EXPECT_EQ(hidden, noted) << line;
    outside += hidden && noted;
  }
  EXPECT_GE(outside, 8);
  fs::remove_all(dir);
}

TEST(Experiment1, ExactModeKeepsNoModelErrorAndNeverNeedsTheHigherOrderBudget) {
  for (const char* name : {"translation-2", "zoom-rotation", "loop"}) {
    const ScriptRun r = run_script(name, "exact");
    for (const FrameReport& f : r.reports) {
      EXPECT_EQ(f.accumulated[3], 0.0);
      if (f.frame > 0 && f.level == Level::kRerender) {
        EXPECT_FALSE(f.note.empty()) << f.frame;
      }
    }
  }
}

using Cli = testing::CliResult;

Cli cli(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

TEST(AnimateCommand, JsonSummaryHasTheContractedFields) {
  const Cli c = cli({"animate", "--script", "translation-1", "--frames", "20", "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  const auto j = nlohmann::json::parse(c.out);
  EXPECT_EQ(j["frames"], 20);
  for (const char* k : {"none", "translate", "affine", "perspective", "rerender"}) {
    EXPECT_TRUE(j["levels"].contains(k)) << k;
  }
  for (const char* k : {"time_saved", "work_saved", "max_measured_error_px", "mean_psnr_db"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_GT(j["work_saved"].get<double>(), 0.5);
  // The medians of the timed passes, engine and interleaved re-render.
  EXPECT_GT(j["median_frame_ms"].get<double>(), 0.0);
  EXPECT_GT(j["baseline_median_frame_ms"].get<double>(), 0.0);
}

TEST(AnimateCommand, RepeatTimingTakesAPositiveWholeNumber) {
  for (const char* n : {"1", "2", "5"}) {
    const Cli c =
        cli({"animate", "--script", "zoom", "--frames", "5", "--repeat-timing", n, "--json"});
    EXPECT_EQ(c.code, 0) << n << ": " << c.err;
  }
  for (const char* n : {"0", "-3", "2.5", "x", "1001"}) {
    const Cli c = cli({"animate", "--script", "zoom", "--frames", "5", "--repeat-timing", n});
    EXPECT_EQ(c.code, 2) << n;
    EXPECT_NE(c.err.find("--repeat-timing"), std::string::npos) << c.err;
    EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;  // one line
  }
  EXPECT_EQ(cli({"animate", "--script", "zoom", "--repeat-timing"}).code, 2);
  const Cli scene = cli({"animate", "--scene", "four-cubes", "--script", "circle", "--frames", "3",
                         "--repeat-timing", "0"});
  EXPECT_EQ(scene.code, 2);
  EXPECT_NE(scene.err.find("--repeat-timing"), std::string::npos) << scene.err;
}

TEST(AnimateCommand, RepeatPlaysTheScriptAgainAndTakesAWholeNumberInItsRange) {
  const Cli once =
      cli({"animate", "--script", "zoom", "--json", "--quiet", "--repeat-timing", "1"});
  ASSERT_EQ(once.code, 0) << once.err;
  const int frames = nlohmann::json::parse(once.out).at("frames");
  const Cli thrice = cli({"animate", "--script", "zoom", "--repeat", "3", "--no-warm-up",
                          "--repeat-timing", "1", "--json", "--quiet"});
  ASSERT_EQ(thrice.code, 0) << thrice.err;
  const auto j = nlohmann::json::parse(thrice.out);
  EXPECT_EQ(j.at("frames"), 3 * frames);
  int counted = 0;
  for (const auto& [level, n] : j.at("levels").items()) counted += n.get<int>();
  EXPECT_EQ(counted, 3 * frames);
  for (const char* n : {"0", "-1", "x", "2.5", "1000001"}) {
    const Cli c = cli({"animate", "--script", "zoom", "--repeat", n});
    EXPECT_EQ(c.code, 2) << n;
    EXPECT_NE(c.err.find("--repeat"), std::string::npos) << c.err;
    EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;
  }
  const Cli scene =
      cli({"animate", "--scene", "four-cubes", "--script", "circle", "--repeat", "2"});
  EXPECT_EQ(scene.code, 2);
  EXPECT_NE(scene.err.find("--repeat"), std::string::npos) << scene.err;
}

// --threads N, the option of every command: a count outside 1..64 is refused naming it.
TEST(AnimateCommand, ThreadsTakeAWholeNumberInTheirRange) {
  EXPECT_EQ(cli({"animate", "--script", "zoom", "--frames", "2", "--threads", "2"}).code, 0);
  for (const char* n : {"0", "65", "x", "1.5"}) {
    const Cli c = cli({"animate", "--script", "zoom", "--frames", "2", "--threads", n});
    EXPECT_EQ(c.code, 2) << n;
    EXPECT_NE(c.err.find("--threads"), std::string::npos) << c.err;
    EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;  // one line
  }
  const Cli missing = cli({"animate", "--script", "zoom", "--threads"});
  EXPECT_EQ(missing.code, 2);
}

TEST(AnimateCommand, AllScriptsRunInAllModes) {
  for (const std::string& s : shipped_script_names()) {
    for (const char* mode : {"perspective", "affine", "rerender", "exact"}) {
      const Cli c = cli({"animate", "--script", s, "--mode", mode, "--frames", "12", "--json"});
      EXPECT_EQ(c.code, 0) << s << " " << mode << ": " << c.err;
    }
  }
}

TEST(AnimateCommand, WritesCsvAndRefusesToOverwriteWithoutForce) {
  const fs::path scratch = testing::fresh_test_dir("oflab-animate-out");
  const fs::path dir = scratch / "out";
  Cli c = cli({"animate", "--script", "zoom", "--frames", "10", "--out", dir.string(),
               "--frames-png", "--quiet"});
  ASSERT_EQ(c.code, 0) << c.err;
  std::ifstream csv(dir / "frames.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_NE(header.find("measured_error_px"), std::string::npos);
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 10);
  EXPECT_TRUE(fs::exists(dir / "frame_00009.png"));
  c = cli({"animate", "--script", "zoom", "--frames", "10", "--out", dir.string()});
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("--force"), std::string::npos);
  c = cli({"animate", "--script", "zoom", "--frames", "10", "--out", dir.string(), "--force"});
  EXPECT_EQ(c.code, 0) << c.err;
  fs::remove_all(scratch);
}

// A script file with one thing wrong must name the file, the frame or segment and the field.
void expect_script_error(const std::string& text, const std::string& where,
                         const std::string& field) {
  const fs::path dir = testing::fresh_test_dir("oflab-bad-script");
  const fs::path file = dir / "bad_script.json";
  std::ofstream(file) << text;
  const Cli c = cli({"animate", "--script", file.string(), "--frames", "3"});
  EXPECT_EQ(c.code, 2) << text;
  EXPECT_NE(c.err.find(file.string()), std::string::npos) << c.err;
  EXPECT_NE(c.err.find(where), std::string::npos) << c.err;
  EXPECT_NE(c.err.find(field), std::string::npos) << c.err;
  fs::remove_all(dir);
}

const char* kHead =
    R"({"camera": {"focal_px": 256, "image": [320, 240]},
        "plane": {"size": [1, 0.8]},)";

TEST(AnimateCommand, BadScriptsNameTheFileTheFrameAndTheField) {
  const std::string frame_ok =
      R"({"point": [0,0,2], "normal": [0,0,1], "up": [0,-1,0], "velocity": [0,0,0], "omega": [0,0,0]})";
  expect_script_error(
      std::string(kHead) + R"("frames": [)" + frame_ok +
          R"(, {"point": [0,0,2], "normal": [0,0,0], "up": [0,-1,0], "velocity": [0,0,0], "omega": [0,0,0]}]})",
      "frame 1", "normal");
  expect_script_error(
      std::string(kHead) + R"("frames": [)" + frame_ok +
          R"(, {"point": [0,0,-2], "normal": [0,0,1], "up": [0,-1,0], "velocity": [0,0,0], "omega": [0,0,0]}]})",
      "frame 1", "point");
  expect_script_error(
      std::string(kHead) +
          R"("frames": [{"point": [0,0,2], "normal": [0,0,1], "up": [0,-1,0], "velocity": [0,"x",0], "omega": [0,0,0]}]})",
      "frame 0", "velocity");
  expect_script_error(
      std::string(kHead) +
          R"("frames": [{"point": [0,0,2], "normal": [0,0,1], "up": [0,-1,0], "omega": [0,0,0]}]})",
      "frame 0", "velocity");
  expect_script_error(
      std::string(kHead) +
          R"("frames": [{"point": [0,0,2], "normal": [0,0,1], "up": [0,-1,0], "velocity": [0,0,NaN], "omega": [0,0,0]}]})",
      "not valid JSON", "");
  expect_script_error(
      R"({"camera": {"focal_px": 256, "image": [320, 240]}, "plane": {"size": [1, 0.8], "point": [0,0,2], "normal": [0,0,1], "up": [0,-1,0]}, "segments": [{"frames": 0, "velocity": [0,0,0], "omega": [0,0,0]}]})",
      "segment 1", "frames");
  expect_script_error("{\"camera\": ", "not valid JSON", "");
}

TEST(AnimateCommand, BadOptionsNameTheOption) {
  EXPECT_NE(cli({"animate", "--script", "no-such-script"}).err.find("--script"), std::string::npos);
  EXPECT_NE(cli({"animate", "--script", "zoom", "--mode", "fast"}).err.find("--mode"),
            std::string::npos);
  EXPECT_NE(
      cli({"animate", "--script", "zoom", "--texture", "/nonexistent.png"}).err.find("--texture"),
      std::string::npos);
  EXPECT_NE(cli({"animate", "--script", "zoom", "--threshold", "-1"}).err.find("--threshold"),
            std::string::npos);
  EXPECT_EQ(cli({"animate", "--script", "zoom", "--delta", "half"}).code, 2);
  const Cli content = cli({"animate", "--script", "zoom", "--content", "brick"});
  EXPECT_EQ(content.code, 2);
  EXPECT_NE(content.err.find("--content: 'brick' is not one of texture, shaded, impostor"),
            std::string::npos)
      << content.err;
  const Cli quality = cli({"animate", "--script", "zoom", "--content", "shaded", "--quality", "0"});
  EXPECT_EQ(quality.code, 2);
  EXPECT_NE(quality.err.find("--quality"), std::string::npos) << quality.err;
}

// The limits of core/flow/limits.h, in the words of Limit::problem after the option.
TEST(AnimateCommand, OutOfRangeValuesAreRefusedNamingTheOptionTheValueAndTheRange) {
  const auto expect_refused = [](const std::vector<std::string>& more, const std::string& line) {
    std::vector<std::string> args = {"animate", "--script", "zoom", "--frames", "2"};
    args.insert(args.end(), more.begin(), more.end());
    const Cli c = cli(args);
    EXPECT_EQ(c.code, 2) << line;
    EXPECT_EQ(c.err, "oflab-cli animate: " + line + "\n");
  };
  expect_refused({"--threshold", "1e6"}, "--threshold: 1e+06 is outside 0..100 px");
  expect_refused({"--threshold", "-1"}, "--threshold: -1 is outside 0..100 px");
  expect_refused({"--thresholds", "1", "2", "3", "101"}, "--thresholds: 101 is outside 0..100 px");
  expect_refused({"--thresholds", "1", "2", "3", "nan"},
                 "--thresholds: 'nan' is not a finite number");
  expect_refused({"--content", "shaded", "--quality", "257"}, "--quality: 257 is outside 1..256");
  expect_refused({"--mode", "budget", "--budget-pixels", "2e9"},
                 "--budget-pixels: 2e+09 is outside 0..1e+09 px");
  const Cli frames = cli({"animate", "--script", "zoom", "--frames", "0"});
  EXPECT_EQ(frames.err, "oflab-cli animate: --frames: 0 is outside 1..1e+06 frames\n");
  // The ends of the threshold range are allowed.
  EXPECT_EQ(
      cli({"animate", "--script", "zoom", "--frames", "2", "--thresholds", "0", "100", "0.5", "1"})
          .code,
      0);
}

TEST(AnimateCommand, ContentChoosesWhatAReRenderDrawsAndTheSummaryCarriesItsCosts) {
  const Cli c = cli({"animate", "--script", "rotation", "--frames", "12", "--content", "shaded",
                     "--repeat-timing", "1", "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  const auto j = nlohmann::json::parse(c.out);
  EXPECT_EQ(j["content"], "shaded");
  EXPECT_EQ(j["content_quality"], 1);
  EXPECT_GT(j["max_photometric_error"].get<double>(), 0.0);  // rotation turns the lit plane
  EXPECT_GT(j["render_ms"].get<double>(), 0.0);
  EXPECT_GT(j["model_work_saved"].get<double>(), 0.0);
  const Cli t =
      cli({"animate", "--script", "rotation", "--frames", "12", "--repeat-timing", "1", "--json"});
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_EQ(nlohmann::json::parse(t.out)["max_photometric_error"], 0.0);
}

TEST(Butterfly, CommittedTextureIsTheGeneratorsOutput) {
  const fs::path dir = testing::fresh_test_dir("oflab-butterfly");
  const fs::path file = dir / "butterfly.png";
  ASSERT_EQ(cli({"make-butterfly", "--out", file.string()}).code, 0);
  const Image fresh = read_image(file.string());
  const Image committed = read_image(default_texture_path());
  EXPECT_EQ(fresh.width(), 243);
  EXPECT_EQ(fresh.height(), 198);
  EXPECT_EQ(fresh.pixels(), committed.pixels());
  EXPECT_EQ(committed.at(0, 0).a, 0);                                  // transparent background
  EXPECT_EQ(cli({"make-butterfly", "--out", file.string()}).code, 2);  // no silent overwrite
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
