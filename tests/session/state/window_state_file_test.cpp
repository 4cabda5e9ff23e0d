// Session files (session/state/window_state_file.h): what they refuse and how the message
// reads (the file, the field, the limit, each once), and where the files they name are found
// (beside the session first).
#include "state/window_state_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "formats/datasets.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string error_of_session(const json& state) {
  json j = state;
  j["format"] = "oflab-session";
  j["version"] = 2;
  try {
    parse_session(j.dump(), "s.json");
  } catch (const SessionError& e) {
    return e.what();
  }
  return "";
}

TEST(SessionFiles, AnUpAlongTheNormalIsNamedOnce) {
  const std::string error =
      error_of_session({{"plane", {{"pose", {{"normal", {0, 0, 1}}, {"up", {0, 0, 2}}}}}}});
  EXPECT_EQ(error,
            "s.json: field 'plane': plane up must be non-zero and not parallel to the normal");
}

TEST(SessionFiles, AGivenStabilizationPlaneThroughOrBehindTheEyeIsRefused) {
  const auto stabilization = [](json point, json normal) {
    return json{
        {"animation",
         {{"stabilization", {{"automatic", false}, {"point", point}, {"normal", normal}}}}}};
  };
  // Through the eye: the plane X = 0 contains the eye at the origin.
  EXPECT_EQ(error_of_session(stabilization({0, 0, 3}, {1, 0, 0})),
            "s.json: animation: field 'stabilization': the plane passes 0 u from the eye; it "
            "must pass at least 0.01 u away (the least distance of a plane)");
  // Behind: the plane Z = -2.
  EXPECT_EQ(error_of_session(stabilization({0, 0, -2}, {0, 0, 1})),
            "s.json: animation: field 'stabilization': the plane meets the optical axis behind "
            "the eye, at Z = -2 u; it must be in front (Z > 0)");
  EXPECT_EQ(error_of_session(stabilization({0, 0, -2}, {0, 0, -1})).empty(), false);
  // In front, facing either way, or parallel to the axis beside it: accepted.
  EXPECT_EQ(error_of_session(stabilization({0, 0, 2}, {0, 0, -1})), "");
  EXPECT_EQ(error_of_session(stabilization({0, 0, 2}, {0.3, 0.1, 1})), "");
  EXPECT_EQ(error_of_session(stabilization({1, 0, 0}, {1, 0, 0})), "");
}

TEST(SessionFiles, ASubnormalNumberIsAFiniteNumber) {
  // 1e-310 is below the smallest normal double but finite: a thresholds value like any other.
  EXPECT_EQ(error_of_session({{"animation", {{"thresholds", {1e-310, 1, 1, 1}}}}}), "");
}

TEST(SessionFiles, TheFilesASessionNamesAreFoundBesideIt) {
  const fs::path dir = fs::temp_directory_path() / ("oflab-beside-" + std::to_string(getpid()));
  fs::create_directories(dir / "lab");
  fs::copy_file(fs::path(datasets_dir()) / "scripts" / "zoom.json", dir / "lab" / "mine.json",
                fs::copy_options::overwrite_existing);
  fs::copy_file(default_texture_path(), dir / "lab" / "tex.png",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir / "lab" / "s.json")
      << R"({"format": "oflab-session", "version": 2, "script": "mine.json",
            "texture": "tex.png"})";
  const WindowState s = read_session_file((dir / "lab" / "s.json").string());
  EXPECT_EQ(s.script, (dir / "lab" / "mine.json").string());
  EXPECT_EQ(s.texture, (dir / "lab" / "tex.png").string());
  // A shipped name and an absolute path stay as they are.
  EXPECT_EQ(with_files_beside(WindowState(), (dir / "lab" / "s.json").string()).script, "");
  WindowState named;
  named.script = "zoom";
  named.texture = default_texture_path();
  const WindowState kept = with_files_beside(named, (dir / "lab" / "s.json").string());
  EXPECT_EQ(kept.script, "zoom");
  EXPECT_EQ(kept.texture, default_texture_path());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
