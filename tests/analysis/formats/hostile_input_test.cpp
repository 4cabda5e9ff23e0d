// Hostile input: each file and command line that once crashed, aborted or exhausted memory
// (the findings of the fuzz campaign, manual/robustness.md) ends with a clear error naming
// the file or argument, the place in it and the limit; the CLI exits with code 2.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "cli_capture.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/json_fields.h"
#include "formats/obj_scene.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path temp_file(const std::string& name, const std::string& bytes) {
  const fs::path file = testing::test_dir("oflab-hostile") / name;
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

// The error text of `read`, or "" when it does not throw.
std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string shipped(const std::string& folder, const std::string& name) {
  return json_fields::read_file_text<std::runtime_error>(datasets_dir() + "/" + folder + "/" +
                                                         name + ".json");
}

// The CLI's exit code is 2 and its one-line message contains `expected`.
void expect_usage_error(const std::vector<std::string>& args, const std::string& expected) {
  const testing::CliResult r = testing::run_cli_captured(args);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

// Finding 1: a number too large for a double in any JSON file.
TEST(HostileInput, NumberTooLargeForADoubleIsNotValidJsonInEveryFormat) {
  const std::string big = R"({"name": "x", "camera": {"focal_px": 1e400}})";
  for (const std::string& e : {error_of([&] { parse_script(big, "m.json"); }),
                               error_of([&] { parse_scene(big, "s.json", "."); }),
                               error_of([&] { parse_viewer_script(big, "v.json"); })}) {
    EXPECT_NE(e.find(".json: not valid JSON ("), std::string::npos) << e;
    EXPECT_NE(e.find("number overflow"), std::string::npos) << e;
    EXPECT_EQ(e.find("json.exception"), std::string::npos) << "no library codes: " << e;
  }
  // A syntax error says where, in a reader's words.
  const std::string cut = error_of([] { parse_script("{\n  \"name\": \"x\",\n}", "c.json"); });
  EXPECT_NE(cut.find("c.json: not valid JSON (line 3, column 1: unexpected '}'"), std::string::npos)
      << cut;
  EXPECT_EQ(cut.find("syntax error while parsing"), std::string::npos) << cut;
  const fs::path file = temp_file("big.json", big);
  expect_usage_error({"animate", "--script", file.string()}, "not valid JSON");
  fs::remove(file);
}

// Finding 2: a non-string name, description or motion model in a motion script.
TEST(HostileInput, NonStringTextFieldsOfAMotionScriptAreNamed) {
  for (const char* field : {"name", "description", "motion_model"}) {
    json j = json::parse(shipped("scripts", "zoom"));
    j[field] = 5;
    const std::string e = error_of([&] { parse_script(j.dump(), "zoom.json"); });
    EXPECT_EQ(e, std::string("zoom.json: field '") + field + "': must be a string");
  }
  json scene = json::parse(shipped("scenes", "two"));
  scene["texture"] = json::array();
  EXPECT_NE(error_of([&] {
              parse_scene(scene.dump(), "two.json", datasets_dir() + "/scenes");
            }).find("field 'texture': must be a string"),
            std::string::npos);
}

// Finding 4: segments are counted against the frame cap before anything is expanded.
TEST(HostileInput, MotionScriptSegmentsAreCountedBeforeExpansion) {
  json j = json::parse(shipped("scripts", "zoom"));
  j["segments"] = json::array();
  for (int i = 0; i < 20; ++i) {
    j["segments"].push_back({{"frames", 1000000}, {"velocity", {0, 0, 0}}, {"omega", {0, 0, 0}}});
  }
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(error_of([&] { parse_script(j.dump(), "long.json"); }),
            "long.json: segment 2: field 'frames': the script has more than 1000000 frames");
  // Refused before expanding: far below the 31 s the expansion took (a bound, not a timing).
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

// Findings 5, 6 and 11: OBJ indices out of range, texture-coordinate indices, huge coordinates.
TEST(HostileInput, ObjIndicesAndCoordinatesAreCheckedBeforeUse) {
  const Image texture(1, 1);
  const auto obj_error = [&](const std::string& text) {
    return error_of([&] { parse_obj_scene(text, "m.obj", texture, "t"); });
  };
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  EXPECT_EQ(obj_error(square + "f 1 2 9\n"),
            "m.obj: line 5: vertex index 9 is out of range (4 read before this line)");
  EXPECT_EQ(obj_error(square + "f 1 2 -5\n"),
            "m.obj: line 5: vertex index -5 is out of range (4 read before this line)");
  EXPECT_EQ(obj_error(square + "f 1 2 0\n"),
            "m.obj: line 5: '0' is not a vertex index (a non-zero whole number)");
  EXPECT_EQ(obj_error(square + "vt 0 0\nf 1/1 2/100000000 3/100000000\n"),
            "m.obj: line 6: texture coordinate index 100000000 is out of range (1 read before "
            "this line)");
  EXPECT_EQ(obj_error(square + "f 1//2 2//1 3//1\n"),
            "m.obj: line 5: normal index 2 is out of range (0 read before this line)");
  EXPECT_EQ(obj_error("v 1e150 0 0\n"),
            "m.obj: line 1: '1e150' is not a finite number of magnitude at most 1e6");
  EXPECT_EQ(obj_error(square + "f -4 -3 -2 -1\n").size(), 0u) << "relative indices are valid";
  const fs::path file = temp_file("bad.obj", square + "f 1 2 100000\n");
  const fs::path out = testing::fresh_test_dir("oflab-hostile-out") / "bad_scene.json";
  fs::remove(out);
  expect_usage_error({"animate", "--scene", file.string(), "--script", "circle", "--frames", "2"},
                     "vertex index 100000 is out of range");
  expect_usage_error({"make-scene", "--from-obj", file.string(), "--out", out.string()},
                     "line 5: vertex index 100000 is out of range");
  EXPECT_FALSE(fs::exists(out));
  fs::remove(file);
}

// The bytes of a PNG whose header declares `width` x `height` (no pixel data follows).
std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  bytes += std::string("\0\0\0\x0dIHDR", 8);
  for (std::uint32_t v : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes += char((v >> shift) & 0xff);
  }
  bytes += std::string("\x08\x06\0\0\0", 5);
  bytes += std::string(4, '\0');  // CRC (not checked by the header reader)
  return bytes;
}

// Findings 7 and 8: only PNG and JPEG, and the size is checked before decoding.
TEST(HostileInput, ImagesAreCheckedBySignatureAndHeaderBeforeDecoding) {
  const fs::path pgm = temp_file("16bit.pgm", "P5\n2 2\n65535\n" + std::string(8, '\x7f'));
  EXPECT_EQ(error_of([&] { read_image(pgm.string()); }),
            pgm.string() + ": not a PNG or JPEG file (the only image formats read)");
  expect_usage_error({"animate", "--script", "zoom", "--texture", pgm.string(), "--frames", "2"},
                     "not a PNG or JPEG file");
  const fs::path huge = temp_file("huge.png", png_header(30000, 17000));
  EXPECT_EQ(error_of([&] { check_image_file(huge.string()); }),
            huge.string() +
                ": image of 30000 x 17000 pixels is larger than the limit (16777216 "
                "pixels, 16384 on a side)");
  const fs::path square = temp_file("square.png", png_header(16000, 16000));
  EXPECT_NE(error_of([&] { read_image(square.string()); }).find("larger than the limit"),
            std::string::npos);
  expect_usage_error({"animate", "--script", "zoom", "--texture", square.string()},
                     "16000 x 16000 pixels is larger than the limit");
  EXPECT_NE(error_of([&] { read_image(fs::temp_directory_path().string()); }).find("cannot read"),
            std::string::npos);
  // A header within the limits whose pixel data is missing fails in the decoder, cleanly.
  const fs::path truncated = temp_file("truncated.png", png_header(64, 64));
  EXPECT_NE(error_of([&] { read_image(truncated.string()); }).find("cannot read image"),
            std::string::npos);
  // A chunk declaring more bytes than the file holds is refused before the decoder, which
  // would allocate the declared length first (a fuzzer found 2.8 GB asked for by 54 KB).
  std::string claims = png_header(64, 64) + std::string("\x40\0\0\0IDAT", 8) + "xy";
  const fs::path overlong = temp_file("overlong.png", claims);
  EXPECT_EQ(error_of([&] { read_image(overlong.string()); }),
            overlong.string() +
                ": PNG chunk 'IDAT' at byte 33 declares 1073741824 bytes of data, but 2 bytes "
                "(its CRC included) are left in the file: truncated or damaged");
  for (const fs::path& f : {pgm, huge, square, truncated, overlong}) fs::remove(f);
}

// Finding 9 and 11: sizes and vectors beyond the limits give messages, not undefined casts.
TEST(HostileInput, HugeSizesAndVectorsAreRefusedWithTheLimit) {
  // Session files: tests/gui/models/window_state_file_test.cpp.
  const std::vector<std::string> flow = {
      "flow", "--focal", "500", "--plane-point", "0", "0", "2", "--velocity",
      "0",    "0",       "0",   "--omega",       "0", "0", "0"};
  std::vector<std::string> image = flow;
  for (const char* a : {"--image", "1e10", "480", "--plane-normal", "0", "0", "1"}) {
    image.push_back(a);
  }
  expect_usage_error(image, "--image: 1e+10 is outside 2..8192 px");
  std::vector<std::string> normal = flow;
  for (const char* a : {"--image", "640", "480", "--plane-normal", "0", "0", "1e308"}) {
    normal.push_back(a);
  }
  expect_usage_error(normal, "--plane-normal: '1e308' is larger than 1e6 in magnitude");
}

}  // namespace
}  // namespace oflab
