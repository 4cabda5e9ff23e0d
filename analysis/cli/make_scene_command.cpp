// `oflab-cli make-scene`: writes scene files (a grid of cubes for the scale experiment, or an
// OBJ file converted to the scene format) and the scenes' shared tile texture.
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "formats/image_io.h"
#include "formats/obj_scene.h"
#include "formats/scene_file.h"
#include "generators/cube_grid.h"
#include "generators/tile_texture.h"

namespace oflab {
namespace {

int make_scene(const CliArgs& a, std::ostream& out) {
  const int sources = a.has("--cubes") + a.has("--from-obj") + a.has("--tile-texture");
  if (sources != 1) {
    throw UsageError("--cubes: give exactly one of --cubes N, --from-obj FILE, --tile-texture");
  }
  const std::string path = a.values("--out").at(0);
  const Overwrite overwrite = check_out_file("--out", path, a.has("--force"));
  if (a.has("--tile-texture")) {
    write_png(path, make_tile_texture(), overwrite);
    out << "wrote " << path << " (128 x 128 RGBA, opaque)\n";
    return 0;
  }
  Scene scene;
  if (a.has("--cubes")) {
    scene = make_cube_grid(a.integer_in("--cubes", limits::kSceneCubes));
    scene.texture_names = {"tile"};
  } else {
    scene = read_obj_scene(a.values("--from-obj").at(0), Image(1, 1), "tile");
  }
  const std::string texture = a.text_or("--texture", "datasets:textures/tile.png");
  write_file_atomically(path, scene_to_json(scene, {texture}).dump(1) + "\n", overwrite);
  out << "wrote " << path << " (" << scene.polygons.size() << " polygons, texture " << texture
      << ")\n";
  return 0;
}

}  // namespace

int run_make_scene_command(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  try {
    const CliArgs a(args, {{"--cubes", 1},
                           {"--from-obj", 1},
                           {"--tile-texture", 0},
                           {"--texture", 1},
                           {"--out", 1},
                           {"--force", 0}});
    return make_scene(a, out);
  } catch (const SceneError& e) {
    err << "oflab-cli make-scene: --from-obj: " << e.what() << "\n";
    return 2;
  } catch (const FileWriteError& e) {
    err << "oflab-cli make-scene: --out: " << e.what() << "\n";
    return 1;
  } catch (const ImageFileError& e) {
    err << "oflab-cli make-scene: --out: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace oflab
