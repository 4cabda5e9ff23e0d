// Scene and viewer-script files: every shipped file loads and matches Fig. 25 and section
// 6.7.1; every malformed file gives an error naming the file, the polygon or segment and
// the field; the generators (cube grids, OBJ import, the tile texture) agree with the data.
#include "formats/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.h"
#include "cli_capture.h"
#include "formats/image_io.h"
#include "formats/obj_scene.h"
#include "formats/viewer_script_file.h"
#include "generators/cube_grid.h"
#include "generators/tile_texture.h"
#include "scene/scene_animator.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using Cli = testing::CliResult;

Cli cli(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

fs::path temp_file(const std::string& name, const std::string& text) {
  const fs::path file = testing::test_dir("oflab-scene-file") / name;
  std::ofstream(file) << text;
  return file;
}

TEST(SceneFiles, EveryShippedSceneOfFig25LoadsWithItsPolygonCount) {
  const std::map<std::string, int> expected = {
      {"single-0.1", 1},     {"single-1", 1},           {"single-3", 1},      {"two", 2},
      {"five-collinear", 5}, {"five-semi-occluded", 5}, {"five-parallel", 5}, {"cube", 5},
      {"two-cubes", 10},     {"four-cubes", 20}};
  const std::vector<std::string> names = shipped_scene_names();
  for (const auto& [name, count] : expected) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  for (const std::string& name : names) {
    const Scene scene = read_scene_file(resolve_scene_path(name));
    EXPECT_NO_THROW(SceneEngine(scene, make_camera(256, 64, 48), SceneSettings{})) << name;
    if (!expected.count(name)) continue;
    EXPECT_EQ(static_cast<int>(scene.polygons.size()), expected.at(name)) << name;
    EXPECT_EQ(scene.textures.size(), 1u) << name << ": Fig. 25's scenes share one texture";
    for (const ScenePolygon& p : scene.polygons) {
      EXPECT_TRUE(polygon_is_opaque(p, scene.textures[p.texture])) << name << " " << p.name;
    }
  }
}

TEST(SceneFiles, EveryShippedViewerScriptLoadsAndCompoundFollowsSection671) {
  for (const std::string& name : shipped_viewer_script_names()) {
    EXPECT_NO_THROW(read_viewer_script_file(resolve_viewer_script_path(name))) << name;
  }
  for (const char* name : {"translate", "zoom", "rotate", "stationary", "circle", "compound"}) {
    EXPECT_NO_THROW(resolve_viewer_script_path(name)) << name;
  }
  const ViewerScript s = read_viewer_script_file(resolve_viewer_script_path("compound"));
  ASSERT_EQ(s.frames.size(), 401u);  // frames 0 to 400
  auto camera_velocity = [&](int f) { return -s.frames[f].motion.velocity; };
  auto camera_omega = [&](int f) { return -s.frames[f].motion.omega; };
  EXPECT_GT(camera_velocity(0).x, 0.0);  // translate in X, frames 0-99
  EXPECT_GT(camera_velocity(99).x, 0.0);
  EXPECT_LT(camera_velocity(100).z, 0.0);  // zoom out (backwards) until 139
  EXPECT_LT(camera_velocity(139).z, 0.0);
  EXPECT_GT(camera_velocity(140).z, 0.0);  // back in until 199
  EXPECT_GT(camera_velocity(199).z, 0.0);
  EXPECT_NE(camera_omega(200).z, 0.0);  // rotate 200-325
  EXPECT_NE(camera_omega(325).z, 0.0);
  EXPECT_EQ(glm::length(camera_velocity(326)) + glm::length(camera_omega(346)), 0.0);
  EXPECT_NE(camera_omega(347).y, 0.0);  // circle until 400
  // Zooming out and back in returns to the same place; the roll is a full turn.
  EXPECT_LT(glm::length(eye_position(s.frames[100].pose) - eye_position(s.frames[200].pose)), 1e-6);
  double rotation_change = 0.0;
  for (int c = 0; c < 3; ++c) {
    rotation_change = std::max(rotation_change, glm::length(s.frames[200].pose.rotation[c] -
                                                            s.frames[326].pose.rotation[c]));
  }
  EXPECT_LT(rotation_change, 1e-6);
}

// One malformed scene: the CLI must exit 2 with the file, the polygon and the field named.
void expect_scene_error(const std::string& text, const std::vector<std::string>& needles) {
  const fs::path file = temp_file("oflab_bad_scene.json", text);
  const Cli c =
      cli({"animate", "--scene", file.string(), "--script", "stationary", "--frames", "2"});
  EXPECT_EQ(c.code, 2) << text;
  EXPECT_NE(c.err.find(file.string()), std::string::npos) << c.err;
  for (const std::string& n : needles) EXPECT_NE(c.err.find(n), std::string::npos) << c.err;
  EXPECT_EQ(c.err.find('\n'), c.err.size() - 1) << "one line: " << c.err;
  fs::remove(file);
}

std::string scene_text(const std::string& polygons, const std::string& textures = "") {
  const std::string tex =
      textures.empty() ? "{\"tile\": \"" + tile_texture_path() + "\"}" : textures;
  return R"({"textures": )" + tex + R"(, "texture": "tile", "polygons": [)" + polygons + "]}";
}

const char* kGood =
    R"({"name": "ok", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1]})";

// Entries naming the same file, directly or through a link, share one decoded image; a
// second file is an image of its own. Each polygon keeps the texture its entry names.
TEST(SceneFiles, EntriesNamingOneFileShareOneDecodedImage) {
  const fs::path dir = testing::fresh_test_dir("oflab-shared-texture");
  const fs::path link = dir / "link.png", other = dir / "other.png";
  fs::create_symlink(tile_texture_path(), link);
  write_png(other.string(), Image(8, 8, Pixel{255, 0, 0, 255}));
  const std::string polygon =
      R"({"name": "N", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1], "texture": "T"})";
  std::string polygons;
  for (const char* t : {"a", "b", "c", "d"}) {
    std::string p = polygon;
    p.replace(p.find('N'), 1, t);
    p.replace(p.find("\"T\""), 3, std::string("\"") + t + "\"");
    polygons += (polygons.empty() ? "" : ", ") + p;
  }
  const std::string textures = "{\"a\": \"" + tile_texture_path() + "\", \"b\": \"" +
                               tile_texture_path() + "\", \"c\": \"" + link.string() +
                               "\", \"d\": \"" + other.string() + "\", \"tile\": \"" +
                               tile_texture_path() + "\"}";
  const Scene scene = parse_scene(
      R"({"textures": )" + textures + R"(, "polygons": [)" + polygons + "]}", "shared.json", "");
  ASSERT_EQ(scene.textures.size(), 2u);
  EXPECT_EQ(scene.texture_names, (std::vector<std::string>{"a", "d"}));
  ASSERT_EQ(scene.polygons.size(), 4u);
  EXPECT_EQ(scene.polygons[0].texture, 0);
  EXPECT_EQ(scene.polygons[1].texture, 0);
  EXPECT_EQ(scene.polygons[2].texture, 0);
  EXPECT_EQ(scene.polygons[3].texture, 1);
  EXPECT_EQ(scene.textures[1].width(), 8);
  fs::remove_all(dir);
}

TEST(SceneFiles, ContentIsReadPerPolygonWithTheScenesDefaultAndBadValuesAreNamed) {
  const std::string good = kGood;
  expect_scene_error(
      scene_text(
          R"({"name": "b", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1], "content": "brick"})"),
      {"polygon 0 ('b')", "'content'", "'brick' is not one of texture, shaded, impostor"});
  const Scene street = read_scene_file(resolve_scene_path("street"));
  EXPECT_EQ(street.content_quality, 3);
  int impostors = 0, shaded = 0;
  for (const ScenePolygon& p : street.polygons) {
    impostors += p.content == ContentKind::kImpostor ? 1 : 0;
    shaded += p.content == ContentKind::kShaded ? 1 : 0;
  }
  EXPECT_EQ(impostors, 7);
  EXPECT_EQ(shaded, 6);
  // Written back, the contents survive; a texture polygon writes none.
  const Scene again = parse_scene(scene_to_json(street, {"../textures/tile.png"}).dump(),
                                  resolve_scene_path("street"),
                                  fs::path(resolve_scene_path("street")).parent_path().string());
  ASSERT_EQ(again.polygons.size(), street.polygons.size());
  for (std::size_t i = 0; i < again.polygons.size(); ++i) {
    EXPECT_EQ(again.polygons[i].content, street.polygons[i].content);
  }
  EXPECT_EQ(again.content_quality, 3);
  EXPECT_FALSE(
      scene_to_json(read_scene_file(resolve_scene_path("two")), {"t.png"}).dump().find("content") !=
      std::string::npos);
}

TEST(SceneFiles, MalformedScenesNameTheFileThePolygonAndTheField) {
  const std::string good = kGood;
  expect_scene_error(
      scene_text(good + R"(, {"name": "warped", "vertices": [[0,0,0],[1,0,0],[1,1,0.3],[0,1,0]]})"),
      {"polygon 1 ('warped')", "'vertices'", "not planar"});
  expect_scene_error(
      scene_text(R"({"name": "dart", "vertices": [[0,0,0],[2,0,0],[0.5,0.5,0],[0,2,0]]})"),
      {"polygon 0 ('dart')", "'vertices'", "not convex"});
  expect_scene_error(scene_text(good, R"({"tile": "no-such-texture.png"})"),
                     {"texture 'tile'", "no-such-texture.png"});
  expect_scene_error(
      scene_text(
          R"({"name": "x", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1], "texture": "brick"})"),
      {"polygon 0 ('x')", "'texture'", "brick"});
  expect_scene_error(
      scene_text(
          R"({"name": "n", "centre": [0,0,NaN], "normal": [0,0,1], "up": [0,1,0], "size": [1,1]})"),
      {"not valid JSON"});
  expect_scene_error(
      scene_text(
          R"({"name": "z", "centre": [0,0,0], "normal": [0,0,0], "up": [0,1,0], "size": [1,1]})"),
      {"polygon 0 ('z')", "'normal'"});
  expect_scene_error(
      scene_text(
          R"({"name": "p", "centre": [0,0,0], "normal": [0,0,1], "up": [0,0,2], "size": [1,1]})"),
      {"polygon 0 ('p')", "'up'"});
  expect_scene_error(
      scene_text(
          R"({"name": "s", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,-1]})"),
      {"polygon 0 ('s')", "'size'"});
  expect_scene_error(
      scene_text(
          R"({"name": "h", "centre": [0,1e300,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1]})"),
      {"polygon 0 ('h')", "'centre'"});
  expect_scene_error(
      scene_text(
          R"({"name": "t", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": "big"})"),
      {"polygon 0 ('t')", "'size'"});
  expect_scene_error(
      scene_text(R"({"name": "m", "normal": [0,0,1], "up": [0,1,0], "size": [1,1]})"),
      {"polygon 0 ('m')", "'centre'", "missing"});
  expect_scene_error(
      scene_text(
          R"({"name": "o", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1], "outline": [[0,0],[1.5,0],[0,1]]})"),
      {"polygon 0 ('o')", "'outline'"});
  expect_scene_error(
      scene_text(
          R"({"name": "c", "centre": [0,0,0], "normal": [0,0,1], "up": [0,1,0], "size": [1,1], "outline": [[0,0],[1,0],[0.2,0.2],[0,1]]})"),
      {"polygon 0 ('c')", "'outline'", "convex"});
  expect_scene_error(scene_text(R"({"name": "d", "vertices": [[0,0,0],[1,1,1],[2,2,2]]})"),
                     {"polygon 0 ('d')", "'vertices'", "no area"});
  expect_scene_error(scene_text(""), {"'polygons'"});
  expect_scene_error(
      R"({"textures": {"tile": ")" + tile_texture_path() + R"("}, "polygons": [)" + good + "]}",
      {"polygon 0 ('ok')", "'texture'"});
  expect_scene_error("", {"not valid JSON"});
  expect_scene_error(scene_text(good).substr(0, 60), {"not valid JSON"});
  expect_scene_error("[1, 2]", {"must be a JSON object"});
}

void expect_script_error(const std::string& text, const std::vector<std::string>& needles) {
  const fs::path file = temp_file("oflab_bad_viewer.json", text);
  const Cli c = cli({"animate", "--scene", "cube", "--script", file.string(), "--frames", "2"});
  EXPECT_EQ(c.code, 2) << text;
  EXPECT_NE(c.err.find(file.string()), std::string::npos) << c.err;
  for (const std::string& n : needles) EXPECT_NE(c.err.find(n), std::string::npos) << c.err;
  fs::remove(file);
}

TEST(SceneFiles, MalformedViewerScriptsNameTheFileTheSegmentAndTheField) {
  const std::string head = R"({"camera": {"focal_px": 256, "image": [64, 48]},
      "viewer": {"position": [0,0,5], "look_at": [0,0,0], "up": [0,1,0]}, "segments": )";
  expect_script_error(head + R"([{"frames": 3, "velocity": [0,0,0], "omega": [0,0,0]},
                                 {"frames": 0, "velocity": [0,0,0], "omega": [0,0,0]}]})",
                      {"segment 2", "'frames'"});
  expect_script_error(head + R"([{"frames": 3, "velocity": [0,"a",0], "omega": [0,0,0]}]})",
                      {"segment 1", "'velocity'"});
  expect_script_error(head + R"([{"frames": 3, "velocity": [0,0,0]}]})", {"segment 1", "'omega'"});
  expect_script_error(head + "[]}", {"'segments'"});
  expect_script_error(R"({"camera": {"focal_px": 256, "image": [64, 48]},
      "viewer": {"position": [0,0,5], "look_at": [0,0,5], "up": [0,1,0]},
      "segments": [{"frames": 3, "velocity": [0,0,0], "omega": [0,0,0]}]})",
                      {"viewer", "'look_at'"});
  expect_script_error(R"({"camera": {"focal_px": -1, "image": [64, 48]}})", {"camera.focal_px"});
  expect_script_error("{\"camera\": ", {"not valid JSON"});
  expect_script_error(R"({"name": 7})", {"'name'"});
}

TEST(SceneFiles, TheCommittedTileIsTheGeneratorsOutput) {
  const Image committed = read_image(tile_texture_path());
  EXPECT_EQ(committed.pixels(), make_tile_texture().pixels());
  for (const Pixel& p : committed.pixels()) ASSERT_EQ(p.a, 255);
}

TEST(SceneFiles, CubeGridOfFourIsTheFourCubesSceneAndGridsLoad) {
  const Scene grid = make_cube_grid(4);
  const Scene shipped = read_scene_file(resolve_scene_path("four-cubes"));
  ASSERT_EQ(grid.polygons.size(), shipped.polygons.size());
  for (std::size_t i = 0; i < grid.polygons.size(); ++i) {
    EXPECT_LT(glm::length(grid.polygons[i].centre - shipped.polygons[i].centre), 1e-12) << i;
    EXPECT_LT(glm::length(grid.polygons[i].front - shipped.polygons[i].front), 1e-12) << i;
  }
  for (int cubes : {4, 40, 400}) {
    const fs::path file =
        testing::fresh_test_dir("oflab-grid") / ("grid_" + std::to_string(cubes) + ".json");
    const Cli c = cli({"make-scene", "--cubes", std::to_string(cubes), "--out", file.string()});
    ASSERT_EQ(c.code, 0) << c.err;
    const Scene s = read_scene_file(file.string());
    EXPECT_EQ(s.polygons.size(), 5u * cubes);
    EXPECT_EQ(cli({"make-scene", "--cubes", "4", "--out", file.string()}).code, 2);  // no overwrite
    fs::remove(file);
  }
  EXPECT_EQ(cli({"make-scene", "--cubes", "0", "--out",
                 (testing::fresh_test_dir("oflab-grid") / "x.json").string()})
                .code,
            2);
}

TEST(SceneFiles, SceneJsonRoundTrips) {
  Scene scene = read_scene_file(resolve_scene_path("two"));
  scene.polygons[1].outline = {{0.0, 0.0}, {1.0, 0.0}, {0.5, 1.0}};
  const fs::path file =
      temp_file("oflab_round_trip.json", scene_to_json(scene, {tile_texture_path()}).dump(1));
  const Scene back = read_scene_file(file.string());
  ASSERT_EQ(back.polygons.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT(glm::length(back.polygons[i].centre - scene.polygons[i].centre), 1e-12);
    EXPECT_LT(glm::length(back.polygons[i].up - scene.polygons[i].up), 1e-12);
    EXPECT_EQ(back.polygons[i].outline, scene.polygons[i].outline);
  }
  fs::remove(file);
}

const char* kCubeObj = R"(# a unit cube, faces counter-clockwise seen from outside
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

TEST(ObjImport, PlanarFacesBecomePolygonsFacingOutwards) {
  const fs::path file = temp_file("oflab_cube.obj", kCubeObj);
  const Scene scene = read_obj_scene(file.string(), read_image(tile_texture_path()), "tile");
  ASSERT_EQ(scene.polygons.size(), 6u);
  for (const ScenePolygon& p : scene.polygons) {
    const Vec3 outward = p.centre - Vec3(0.5);
    EXPECT_NEAR(glm::dot(p.front, glm::normalize(outward)), 1.0, 1e-12) << p.name;
    EXPECT_NEAR(p.size.x * p.size.y, 1.0, 1e-12) << p.name;
  }
  // The CLI takes an OBJ scene directly, and make-scene converts one.
  const Cli c =
      cli({"animate", "--scene", file.string(), "--script", "circle", "--frames", "5", "--json"});
  EXPECT_EQ(c.code, 0) << c.err;
  const fs::path out = testing::fresh_test_dir("oflab-cube-scene") / "cube_scene.json";
  EXPECT_EQ(cli({"make-scene", "--from-obj", file.string(), "--out", out.string()}).code, 0);
  EXPECT_EQ(read_scene_file(out.string()).polygons.size(), 6u);
  fs::remove(out);
  fs::remove(file);
}

TEST(ObjImport, BadFacesAndFilesGiveClearErrors) {
  const fs::path warped =
      temp_file("oflab_warped.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nf 1 2 3 4\n");
  try {
    read_obj_scene(warped.string(), Image(1, 1), "t");
    ADD_FAILURE() << "no error for a non-planar face";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not planar"), std::string::npos) << e.what();
  }
  const fs::path empty = temp_file("oflab_empty.obj", "v 0 0 0\n");
  EXPECT_THROW(read_obj_scene(empty.string(), Image(1, 1), "t"), SceneError);
  EXPECT_THROW(read_obj_scene("/nonexistent/file.obj", Image(1, 1), "t"), SceneError);
  fs::remove(warped);
  fs::remove(empty);
}

}  // namespace
}  // namespace oflab
