#include "child_process.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <thread>

#include "flow/geometry.h"
#include "formats/atomic_file.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "generators/cube_grid.h"

namespace oflab::testing {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

ChildResult run_child(const std::string& binary, const std::vector<std::string>& args,
                      const fs::path& dir, long address_space, double limit_s) {
  const fs::path out = dir / "child.out", err = dir / "child.err";
  std::vector<char*> argv{const_cast<char*>(binary.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (address_space > 0) {
      const rlimit limit{static_cast<rlim_t>(address_space), static_cast<rlim_t>(address_space)};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  ChildResult r;
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
    const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
    if (t.count() > limit_s && !r.timed_out) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.exited = WIFEXITED(status);
  r.code = r.exited ? WEXITSTATUS(status) : -1;
  r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  r.peak_rss_kb = usage.ru_maxrss;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

void expect_ends_cleanly(const std::string& binary, const std::vector<std::string>& args,
                         const fs::path& dir, const std::string& what) {
  const ChildResult r =
      run_child(binary, args, dir, kHostileAddressSpace, kHostileTimeLimitSeconds);
  EXPECT_FALSE(r.timed_out) << what;
  EXPECT_LT(r.seconds, kHostileTimeLimitSeconds) << what;
  ASSERT_TRUE(r.exited) << what << ": signal " << r.signal << "\n" << r.err;
  EXPECT_TRUE(r.code == 0 || r.code == 2) << what << ": exit " << r.code << "\n" << r.err;
  if (r.code == 2) {
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << what << ": " << r.err;
  }
}

std::vector<fs::path> write_degenerate_plane_scripts(const fs::path& dir) {
  const nlohmann::json base = nlohmann::json::parse(std::ifstream(resolve_script_path("zoom")));
  std::vector<nlohmann::json> scripts(4, base);
  scripts[0]["plane"]["point"] = {0, 0, 1e-6};
  scripts[1]["plane"]["size"] = {1e-300, 1e-300};
  scripts[2]["camera"]["focal_px"] = 1e6;
  scripts[3]["camera"]["focal_px"] = 1e-300;
  std::vector<fs::path> files;
  for (std::size_t i = 0; i < scripts.size(); ++i) {
    files.push_back(dir / ("degenerate-" + std::to_string(i) + ".json"));
    std::ofstream(files.back()) << scripts[i].dump();
  }
  return files;
}

namespace {

// The shipped single-1 scene, its texture named by an absolute path.
nlohmann::json single_square_scene() {
  const fs::path shipped = resolve_scene_path("single-1");  // the shipped file
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(shipped));
  scene["textures"]["tile"] =
      fs::absolute(shipped.parent_path() / scene["textures"]["tile"].get<std::string>()).string();
  return scene;
}

fs::path write_scene(const nlohmann::json& scene, const fs::path& file) {
  std::ofstream(file) << scene.dump();
  return file;
}

}  // namespace

fs::path write_intersecting_circles_scene(const fs::path& dir) {
  nlohmann::json scene = single_square_scene();
  scene["polygons"] = nlohmann::json::array();
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> centre(-0.2, 0.2);
  // 60 circles: within the scene engine's memory limit at 640 x 480 (566 MiB), so the BSP
  // vertex cap is what refuses them.
  for (int i = 0; i < 60; ++i) {
    const Vec3 n = glm::normalize(Vec3(normal(rng), normal(rng), normal(rng)));
    const Vec3 u =
        glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 v = glm::cross(n, u), c(centre(rng), centre(rng), centre(rng));
    nlohmann::json vertices = nlohmann::json::array();
    for (int k = 0; k < 2000; ++k) {
      const double a = 2.0 * 3.141592653589793 * k / 2000.0;
      const Vec3 p = c + 0.5 * std::cos(a) * u + 0.5 * std::sin(a) * v;
      vertices.push_back({p.x, p.y, p.z});
    }
    scene["polygons"].push_back({{"name", "circle " + std::to_string(i)}, {"vertices", vertices}});
  }
  return write_scene(scene, dir / "intersecting-circles.json");
}

fs::path write_detailed_impostor_scene(const fs::path& dir) {
  nlohmann::json scene = single_square_scene();
  nlohmann::json square = scene["polygons"][0];
  square["content"] = "impostor";
  scene["content_quality"] = 256;
  scene["polygons"] = nlohmann::json::array();
  for (int i = 0; i < 20; ++i) scene["polygons"].push_back(square);
  return write_scene(scene, dir / "detailed-impostors.json");
}

fs::path write_repeated_polygon_scene(const fs::path& dir, int copies) {
  nlohmann::json scene = single_square_scene();
  const nlohmann::json square = scene["polygons"][0];
  scene["polygons"] = nlohmann::json::array();
  for (int i = 0; i < copies; ++i) scene["polygons"].push_back(square);
  const fs::path file = dir / ("repeated-polygon-" + std::to_string(copies) + ".json");
  std::ofstream(file) << scene.dump(2);
  return file;
}

fs::path write_large_obj(const fs::path& dir) {
  const int n = 175;
  const fs::path file = dir / "large.obj";
  std::ofstream out(file);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      out << "v " << double(i) / n - 0.5 << ' ' << double(j) / n - 0.5 << ' '
          << 0.01 * std::sin(0.3 * i + 0.2 * j) << '\n';
    }
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i + 1, b = a + 1, c = a + n, d = c + 1;
      out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
    }
  }
  return file;
}

fs::path write_cube_grid_scene(const fs::path& dir) {
  Scene scene = make_cube_grid(20000);
  scene.texture_names = {"tile"};
  const std::string tile = single_square_scene()["textures"]["tile"];
  return write_scene(scene_to_json(scene, {tile}), dir / "cubes-20000.json");
}

fs::path write_random_squares_scene(const fs::path& dir) {
  nlohmann::json scene = single_square_scene();
  const nlohmann::json square = scene["polygons"][0];
  scene["polygons"] = nlohmann::json::array();
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> position(-1.0, 1.0);
  for (int i = 0; i < 3000; ++i) {
    const Vec3 n = glm::normalize(Vec3(normal(rng), normal(rng), normal(rng)));
    const Vec3 up = std::abs(n.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    nlohmann::json p = square;
    p["name"] = "square " + std::to_string(i);
    p["centre"] = {position(rng), position(rng), position(rng)};
    p["normal"] = {n.x, n.y, n.z};
    p["up"] = {up.x, up.y, up.z};
    scene["polygons"].push_back(p);
  }
  return write_scene(scene, dir / "random-squares.json");
}

fs::path write_shared_texture_scene(const fs::path& dir) {
  const fs::path image = fs::absolute(dir / "4096.png");
  write_png(image.string(), Image(4096, 4096, Pixel{32, 64, 128, 255}), Overwrite::kReplace);
  nlohmann::json scene = single_square_scene();
  const nlohmann::json square = scene["polygons"][0];
  scene["textures"] = nlohmann::json::object();
  scene["polygons"] = nlohmann::json::array();
  for (int i = 0; i < 10; ++i) {
    const std::string name = "t" + std::to_string(i);
    scene["textures"][name] = image.string();
    nlohmann::json p = square;
    p["name"] = "square " + std::to_string(i);
    p["texture"] = name;
    p["centre"] = {1.1 * i, 0.0, 0.0};
    scene["polygons"].push_back(p);
  }
  scene["texture"] = "t0";
  return write_scene(scene, dir / "shared-texture.json");
}

fs::path write_large_camera_viewer_script(const fs::path& dir) {
  nlohmann::json script =
      nlohmann::json::parse(std::ifstream(resolve_viewer_script_path("train-sideways")));
  script["camera"] = {{"focal_px", 400}, {"image", {4096, 4096}}};
  const fs::path file = dir / "train-sideways-4096.json";
  std::ofstream(file) << script.dump();
  return file;
}

}  // namespace oflab::testing
