#include "scene_cases.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "image/composite.h"
#include "image/polygon.h"

namespace oflab::testing {

Image checker_image(int width, int height) {
  Image img(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool dark = ((x / 8) + (y / 8)) % 2;
      const int quadrant = (2 * x >= width) + 2 * (2 * y >= height);
      const std::uint8_t tint = static_cast<std::uint8_t>(60 * quadrant);
      img.at(x, y) = dark ? Pixel{40, tint, 160, 255} : Pixel{230, 200, tint, 255};
    }
  }
  return img;
}

ScenePolygon square(const std::string& name, const Vec3& centre, const Vec3& front, const Vec3& up,
                    double size, int texture) {
  ScenePolygon p;
  p.name = name;
  p.centre = centre;
  p.front = glm::normalize(front);
  p.up = glm::normalize(up);
  p.size = Vec2(size);
  p.texture = texture;
  return p;
}

std::vector<ScenePolygon> open_cube(const std::string& name, const Vec3& c, double s) {
  const double h = 0.5 * s;
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  return {square(name + "-front", c + h * z, z, y, s), square(name + "-back", c - h * z, -z, y, s),
          square(name + "-left", c - h * x, -x, y, s), square(name + "-right", c + h * x, x, y, s),
          square(name + "-top", c + h * y, y, -z, s)};
}

Scene scene_with(std::vector<ScenePolygon> polygons) {
  Scene s;
  s.name = "test";
  s.textures.push_back(checker_image(64, 64));
  s.texture_names.push_back("checker");
  s.polygons = std::move(polygons);
  return s;
}

std::vector<ScenePolygon> random_polygons(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::pair<Vec3, double>> balls;
  std::vector<ScenePolygon> out;
  while (static_cast<int>(out.size()) < count) {
    const Vec3 centre(4.5 * u(rng), 4.5 * u(rng), 4.5 * u(rng));
    const double radius = 0.9 + 0.6 * u(rng);
    bool free = true;
    for (const auto& b : balls) free = free && glm::length(b.first - centre) > b.second + radius;
    if (!free) continue;
    balls.emplace_back(centre, radius);
    const Vec3 normal = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3, 0, 0));
    const Vec3 a = glm::normalize(
        glm::cross(normal, std::abs(normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 b = glm::cross(normal, a);
    const int n = 3 + static_cast<int>(out.size() % 4);
    std::vector<Vec3> vertices;
    // Points of one circle in increasing angle: always a convex polygon.
    const double r = radius * (0.75 + 0.2 * u(rng));
    for (int k = 0; k < n; ++k) {
      const double angle = 6.283185307179586 * (k + 0.35 * u(rng)) / n;
      vertices.push_back(centre + r * (std::cos(angle) * a + std::sin(angle) * b));
    }
    out.push_back(
        polygon_from_vertices("random-" + std::to_string(out.size()), vertices, Vec3(0.0), 0));
  }
  return out;
}

Scene cube_past_cube() {
  std::vector<ScenePolygon> polygons = open_cube("far", Vec3(0.3, 0, -3), 2.0);
  for (ScenePolygon& p : open_cube("near", Vec3(0, 0, 0), 0.8)) polygons.push_back(p);
  return scene_with(polygons);
}

std::vector<ViewerFrame> sliding_past(int frames, const Vec3& velocity, const Vec3& omega) {
  const ViewerPose start = look_at(Vec3(-0.3, 0.8, 3.5), Vec3(0, 0, -1), Vec3(0, 1, 0));
  return expand_viewer_segments(start, {ViewerSegment{frames, velocity, omega}});
}

std::vector<std::vector<ViewerFrame>> three_motions_past() {
  return {sliding_past(10, Vec3(0.05, 0, 0), Vec3(0.0)),                         // translate
          sliding_past(10, Vec3(0.0), Vec3(0, 0.02, 0.01)),                      // rotate
          expand_viewer_segments(sliding_past(1, Vec3(0.0), Vec3(0.0))[0].pose,  // compound
                                 {{4, Vec3(0.04, 0, 0), Vec3(0.0)},
                                  {3, Vec3(0, 0, -0.1), Vec3(0.0)},
                                  {4, Vec3(0.02, 0, 0.05), Vec3(0, 0.03, 0)}})};
}

Vec2 project_world(const Camera& camera, const ViewerPose& view, const Vec3& world) {
  return centred_to_pixel(camera, project_centred(camera, to_view(view, world)));
}

Vec3 world_point_at(const Camera& camera, const ScenePolygon& polygon, const ViewerPose& view,
                    double u, double v) {
  const Vec3 eye = eye_position(view);
  const Vec3 ray = glm::transpose(view.rotation) *
                   Vec3((u - camera.cx) / camera.focal_px, (v - camera.cy) / camera.focal_px, 1.0);
  const double s = glm::dot(polygon.front, polygon.centre - eye) / glm::dot(polygon.front, ray);
  return eye + s * ray;
}

Image ray_cast_scene(const Scene& scene, const Camera& camera, const ViewerPose& view,
                     double near) {
  struct Prepared {
    Vec3 centre, front, right, up;
    Vec2 size;
    ConvexPolygon outline;
    const Image* texture;
  };
  std::vector<Prepared> prepared;
  for (const ScenePolygon& p : scene.polygons) {
    Prepared q{to_view(view, p.centre),
               direction_to_view(view, p.front),
               direction_to_view(view, polygon_right(p)),
               direction_to_view(view, p.up),
               p.size,
               ConvexPolygon::from_vertices(polygon_outline(p)),
               &scene.textures[p.texture]};
    if (glm::dot(q.front, -q.centre) <= 0.0) continue;  // seen from behind
    prepared.push_back(q);
  }
  Image out(camera.width, camera.height);
  std::vector<std::pair<double, Pixel>> hits;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const Vec3 ray((x + 0.5 - camera.cx) / camera.focal_px,
                     (y + 0.5 - camera.cy) / camera.focal_px, 1.0);
      hits.clear();
      for (const Prepared& p : prepared) {
        const double denom = glm::dot(p.front, ray);
        if (std::abs(denom) < 1e-15) continue;
        const double t = glm::dot(p.front, p.centre) / denom;  // the hit's depth Z
        if (!(t >= near)) continue;
        const Vec3 d = t * ray - p.centre;
        const Vec2 uv(glm::dot(d, p.right) / p.size.x + 0.5, 0.5 - glm::dot(d, p.up) / p.size.y);
        if (!contains(p.outline, uv)) continue;
        const Image& tex = *p.texture;
        const int tx =
            std::clamp(static_cast<int>(std::floor(uv.x * tex.width())), 0, tex.width() - 1);
        const int ty =
            std::clamp(static_cast<int>(std::floor(uv.y * tex.height())), 0, tex.height() - 1);
        hits.emplace_back(t, tex.at(tx, ty));
      }
      std::sort(hits.begin(), hits.end(),
                [](const auto& a, const auto& b) { return a.first > b.first; });
      Pixel colour{};
      for (const auto& h : hits) colour = over(h.second, colour);
      out.at(x, y) = colour;
    }
  }
  return out;
}

double mismatch_fraction(const Image& a, const Image& b, int tolerance) {
  long covered = 0, different = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Pixel p = a.at(x, y), q = b.at(x, y);
      if (p.a == 0 && q.a == 0) continue;
      ++covered;
      const int d = std::max(
          {std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
      if (d > tolerance) ++different;
    }
  }
  return covered ? static_cast<double>(different) / covered : 0.0;
}

Image coded_texture(int polygon) {
  Image t(256, 256);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      t.pixels()[static_cast<std::size_t>(y) * 256 + x] =
          Pixel{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
                static_cast<std::uint8_t>(polygon * 16), 255};
    }
  }
  return t;
}

Scene with_coded_textures(Scene scene) {
  scene.textures.clear();
  scene.texture_names.clear();
  for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
    scene.polygons[i].texture = static_cast<int>(i);
    scene.textures.push_back(coded_texture(static_cast<int>(i)));
    scene.texture_names.push_back("coded");
  }
  return scene;
}

double coded_image_error(const Scene& scene, const Camera& camera, const Image& frame,
                         const ViewerPose& view) {
  double worst = 0.0;
  for (int y = 0; y < frame.height(); ++y) {
    for (int x = 0; x < frame.width(); ++x) {
      const Pixel p = frame.at(x, y);
      if (p.a != 255) continue;
      const ScenePolygon& polygon = scene.polygons.at(p.b / 16);
      const Vec3 world = polygon_point(polygon, Vec2((p.r + 0.5) / 256.0, (p.g + 0.5) / 256.0));
      const Vec2 q = centred_to_pixel(camera, project_centred(camera, to_view(view, world)));
      worst = std::max(worst, glm::length(q - Vec2(x + 0.5, y + 0.5)));
    }
  }
  return worst;
}

void save_ppm(const std::string& path, const Image& image) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << image.width() << " " << image.height() << "\n255\n";
  for (const Pixel& p : image.pixels()) out.put(p.r).put(p.g).put(p.b);
}

}  // namespace oflab::testing
