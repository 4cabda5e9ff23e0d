// A program in a child process, where a test can see what a user sees: its exit status (a
// signal, an abort), its wall time and its peak memory. Shared by the CLI's process tests
// (tests/analysis/cli/cli_process_test.cpp) and the GUI's (tests/gui/app/hostile_gui_test.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace oflab::testing {

// The limits for a hostile input: 2 GB of address space, 60 s of wall time.
constexpr long kHostileAddressSpace = 2L << 30;  // bytes
constexpr double kHostileTimeLimitSeconds = 60.0;

struct ChildResult {
  bool exited = false;  // false: killed by a signal (or by the time limit)
  int code = -1;        // exit status when exited
  int signal = 0;
  bool timed_out = false;
  double seconds = 0.0;  // wall time
  long peak_rss_kb = 0;  // getrusage ru_maxrss of the child
  std::string out, err;  // what it wrote
};

// Runs `binary` with `args` in a child (stdout and stderr into files of `dir`), its address
// space limited to `address_space` bytes (0: no limit), killed after `limit_s` seconds of
// wall time. The child inherits the environment (DISPLAY included).
ChildResult run_child(const std::string& binary, const std::vector<std::string>& args,
                      const std::filesystem::path& dir, long address_space, double limit_s);

// Runs `binary` with `args` under the hostile-input limits and expects it to end in time
// with exit status 0 or 2 and, on 2, a message of exactly one line; `what` names the case
// in failures.
void expect_ends_cleanly(const std::string& binary, const std::vector<std::string>& args,
                         const std::filesystem::path& dir, const std::string& what);

// The hand-made motion scripts that are not fuzz inputs, written into `dir` from
// the shipped zoom script: a plane 1e-6 in front of the eye (closer than the warp can
// take), a plane of size 1e-300, focal lengths of 1e6 and 1e-300. Returns their paths.
std::vector<std::filesystem::path> write_degenerate_plane_scripts(const std::filesystem::path& dir);

// The scene of one shipped polygon repeated `copies` times (single-1's square, its
// tile texture by absolute path), about 93 KB for 1000, written into `dir` as
// repeated-polygon-COPIES.json: 1000 and 100 copies are over the scene engine's memory limit
// at the walk viewer's 1280 x 720 px, 27 the most within it. Returns its path.
std::filesystem::path write_repeated_polygon_scene(const std::filesystem::path& dir,
                                                   int copies = 1000);

// The scene of 100 polygons of 2000 vertices each, circles of radius 0.5 through a
// small box at random orientations (seeded), so that they all cut each other.
std::filesystem::path write_intersecting_circles_scene(const std::filesystem::path& dir);

// The shipped single-1 scene with its square repeated 20 times as an impostor facade at
// content quality 256.
std::filesystem::path write_detailed_impostor_scene(const std::filesystem::path& dir);

// The large inputs (points 1 to 3), written into `dir`; each must be refused up
// front by a limit, or played within 60 s and 2 GB:
// - an OBJ file of 60 552 triangles (a 175 x 175 grid of vertices), about 2 MB;
std::filesystem::path write_large_obj(const std::filesystem::path& dir);
// - make-scene's largest output, `make-scene --cubes 20000` (written by the same generator
//   and writer, the tile texture by absolute path);
std::filesystem::path write_cube_grid_scene(const std::filesystem::path& dir);
// - 3000 unit squares at random positions in a box of side 2 and random orientations
//   (seeded), cutting each other;
std::filesystem::path write_random_squares_scene(const std::filesystem::path& dir);
// - ten texture entries naming one 4096 x 4096 PNG (one colour, about 70 KB), each on a
//   square of its own.
std::filesystem::path write_shared_texture_scene(const std::filesystem::path& dir);
// - the train-sideways viewer script with a camera of 4096 x 4096 px (focal length 400 px):
//   scene shifting of the train-window scene then needs layers of up to 576 MiB a slice.
std::filesystem::path write_large_camera_viewer_script(const std::filesystem::path& dir);

}  // namespace oflab::testing
