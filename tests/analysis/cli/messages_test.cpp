// The messages of issue 28's point 11, each naming the option or field at fault, and the
// limits behind them (core/flow/limits.h).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_capture.h"
#include "formats/datasets.h"
#include "formats/viewer_script_file.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using testing::run_cli_captured;

// The one line `args` prints on stderr; expects exit code `code`.
std::string refusal(const std::vector<std::string>& args, int code = 2) {
  const testing::CliResult r = run_cli_captured(args);
  EXPECT_EQ(r.code, code) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  return r.err;
}

TEST(Messages, LargeWholeNumbersNameTheOptionAndItsRange) {
  const std::vector<std::string> zoom = {"animate", "--script", "zoom", "--frames", "2"};
  auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = zoom;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  EXPECT_EQ(refusal({"animate", "--script", "zoom", "--frames", "2147483647"}),
            "oflab-cli animate: --frames: 2.14748e+09 is outside 1..1e+06 frames\n");
  EXPECT_EQ(refusal(with({"--content", "shaded", "--quality", "-2147483648"})),
            "oflab-cli animate: --quality: -2.14748e+09 is outside 1..256\n");
  EXPECT_EQ(refusal(with({"--thresholds", "1", "2", "3", "nan"})),
            "oflab-cli animate: --thresholds: 'nan' is not a finite number\n");
  EXPECT_EQ(refusal({"animate", "--script", "zoom", "--repeat", "2147483647"}),
            "oflab-cli animate: --repeat: 2147483647 is outside 1..1000000 (plays of the "
            "script's 90 frames)\n");
  EXPECT_EQ(refusal(with({"--repeat-timing", "1e12"})),
            "oflab-cli animate: --repeat-timing: 1e+12 is outside 1..1000 passes\n");
  EXPECT_EQ(refusal(with({"--video", "x.gif", "--fps", "2147483647"})),
            "oflab-cli animate: --fps: 2.14748e+09 is outside 1..60 fps\n");
  EXPECT_EQ(refusal({"make-scene", "--cubes", "2147483647", "--out", "x.json"}),
            "oflab-cli make-scene: --cubes: 2.14748e+09 is outside 1..20000 cubes\n");
}

// Issue 39, point 12: a command-line number is decimal ("0x10" read as 16 before), and a
// subnormal such as 1e-310 is a finite number that the option's limit judges (it was "not a
// finite number"); a value too large for a double is still not one.
TEST(Messages, CommandLineNumbersAreDecimalAndSubnormalsAreFinite) {
  EXPECT_EQ(refusal({"animate", "--script", "zoom", "--frames", "0x10"}),
            "oflab-cli animate: --frames: '0x10' is not a decimal number\n");
  EXPECT_EQ(refusal({"animate", "--script", "zoom", "--frames", "0X1p4"}),
            "oflab-cli animate: --frames: '0X1p4' is not a decimal number\n");
  EXPECT_EQ(refusal({"animate", "--script", "zoom", "--frames", "1e-310"}),
            "oflab-cli animate: --frames: 1e-310 is outside 1..1e+06 frames\n");
  EXPECT_EQ(refusal({"animate", "--script", "zoom", "--frames", "1e400"}),
            "oflab-cli animate: --frames: '1e400' is not a finite number\n");
  const testing::CliResult at =
      run_cli_captured({"explain", "--coefficients", "16", "0", "0", "0", "0", "0", "0", "0",
                        "--focal", "500", "--at", "1e-310", "0"});
  EXPECT_EQ(at.code, 0) << at.err;
}

TEST(Messages, AViewerScriptWithAZeroUpNamesUp) {
  const fs::path dir = testing::fresh_test_dir("oflab-messages");
  nlohmann::json script =
      nlohmann::json::parse(std::ifstream(resolve_viewer_script_path("circle")));
  script["viewer"]["up"] = {0, 0, 0};
  const fs::path file = dir / "zero-up.json";
  std::ofstream(file) << script.dump();
  const std::string err =
      refusal({"animate", "--scene", "four-cubes", "--script", file.string(), "--frames", "1"});
  EXPECT_NE(err.find("field 'up': up must be non-zero"), std::string::npos) << err;
  EXPECT_EQ(err.find("look_at"), std::string::npos) << err;
  fs::remove_all(dir);
}

TEST(Messages, ATinySceneShiftingToleranceNamesEpsilon) {
  const std::string err =
      refusal({"animate", "--mode", "scene-shifting", "--scene", "train-window", "--script",
               "train-sideways", "--epsilon", "1e-9", "--frames", "2"});
  EXPECT_EQ(err.rfind("oflab-cli animate: --epsilon: the slicing needs", 0), 0u) << err;
}

TEST(Messages, AFailedFramePngWriteNamesTheFileNotTheTexture) {
  const fs::path dir = testing::fresh_test_dir("oflab-messages");
  // A full disk for this process: writes past 2000 bytes fail (EFBIG, the signal ignored).
  rlimit old{};
  ::getrlimit(RLIMIT_FSIZE, &old);
  const rlimit small{2000, old.rlim_max};
  const auto previous = ::signal(SIGXFSZ, SIG_IGN);
  ::setrlimit(RLIMIT_FSIZE, &small);
  const testing::CliResult r =
      run_cli_captured({"animate", "--script", "zoom", "--frames", "3", "--repeat-timing", "1",
                        "--out", (dir / "out").string(), "--frames-png"});
  ::setrlimit(RLIMIT_FSIZE, &old);
  ::signal(SIGXFSZ, previous);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("frame_00000.png': cannot write the file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--texture"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));  // the run's directory appears whole or not at all
  EXPECT_TRUE(fs::is_empty(dir));         // and its temporary is gone
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
