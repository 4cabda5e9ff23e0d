#include "fuzz_inputs.h"

#include <sstream>
#include <vector>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "flow/camera.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/obj_scene.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "scene/scene_animator.h"
#include "scene/viewer_script.h"
#include "state/window_state_file.h"

namespace oflab::fuzz {
namespace {

// Scenes read by the fuzzers are also played for one frame (the scene engine's budgets and
// the BSP caps are part of reading a scene safely): a scene engine at 80 x 60 px renders
// frame 0 seen from 5 units in front (+Z) of the polygons' mean centre, looking at it. Up to
// this many polygons, so that one input stays quick.
constexpr std::size_t kMaxPlayedPolygons = 64;

void play(const Scene& scene) {
  if (scene.polygons.empty() || scene.polygons.size() > kMaxPlayedPolygons) return;
  Vec3 centre(0.0);
  for (const ScenePolygon& p : scene.polygons) centre += p.centre;
  centre /= static_cast<double>(scene.polygons.size());
  try {
    SceneEngine engine(scene, make_camera(64.0, 80, 60), SceneSettings{});
    (void)engine.start(look_at(centre + Vec3(0.0, 0.0, 5.0), centre, Vec3(0.0, 1.0, 0.0)));
  } catch (const std::invalid_argument&) {  // a limit or a polygon the engine refuses
  }
}

void motion_script(const std::string& bytes) {
  try {
    (void)parse_script(bytes, "fuzz.json");
  } catch (const ScriptError&) {
  }
}

void viewer_script(const std::string& bytes) {
  try {
    (void)parse_viewer_script(bytes, "fuzz.json");
  } catch (const ViewerScriptError&) {
  }
}

void scene(const std::string& bytes) {
  try {
    play(parse_scene(bytes, "fuzz.json", datasets_dir() + "/scenes"));
  } catch (const SceneError&) {
  }
}

void session(const std::string& bytes) {
  try {
    (void)parse_session(bytes, "fuzz.json");
  } catch (const SessionError&) {
  }
}

void obj(const std::string& bytes) {
  try {
    play(parse_obj_scene(bytes, "fuzz.obj", Image(1, 1), "t"));
  } catch (const SceneError&) {
  }
}

void image(const std::string& bytes) {
  try {
    (void)decode_image(bytes, "fuzz.png");
  } catch (const ImageFileError&) {
  }
}

// The arguments: the input split at NUL bytes or newlines. The first argument chooses the
// headless command (flow or slices, whose option readers are the CLI's), the rest are its
// options; a usage error is the UsageError that run_cli turns into exit code 2, and any
// other exception or exit code is a finding.
void command_line(const std::string& bytes) {
  std::vector<std::string> args;
  std::string current;
  for (char c : bytes) {
    if (c == '\0' || c == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  args.push_back(current);
  std::ostringstream out, err;
  const CommandArgs rest(args.begin() + 1, args.end());
  try {
    const int code =
        args[0] == "slices" ? run_slices_command(rest, out, err) : run_flow_command(rest, out, err);
    if (code != 0 && code != 2) throw std::logic_error("unexpected exit code");
  } catch (const UsageError&) {  // what run_cli reports as exit code 2
  }
}

}  // namespace

const std::map<std::string, Target>& targets() {
  static const std::map<std::string, Target> all = {{"motion-script", motion_script},
                                                    {"viewer-script", viewer_script},
                                                    {"scene", scene},
                                                    {"session", session},
                                                    {"obj", obj},
                                                    {"image", image},
                                                    {"command-line", command_line}};
  return all;
}

}  // namespace oflab::fuzz
