#include "generators/cube_grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace oflab {
namespace {

ScenePolygon face(const std::string& name, const Vec3& centre, const Vec3& front, const Vec3& up,
                  double size) {
  ScenePolygon p;
  p.name = name;
  p.centre = centre;
  p.front = front;
  p.up = up;
  p.size = Vec2(size);
  return p;
}

}  // namespace

Scene make_cube_grid(int cubes) {
  if (cubes < 1 || cubes > 20000) throw std::invalid_argument("cubes must be from 1 to 20000");
  const int k = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(cubes)) - 1e-9));
  const int rows = (cubes + k - 1) / k;
  const double side = 2.0 / k, spacing = 5.0 / k, h = 0.5 * side;
  Scene scene;
  scene.name = "grid-" + std::to_string(cubes);
  scene.description = std::to_string(cubes) + " open cubes (" + std::to_string(5 * cubes) +
                      " polygons) on a grid spanning the four-cubes footprint";
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  for (int n = 0; n < cubes; ++n) {
    const int i = n % k, j = n / k;
    const Vec3 c((i - 0.5 * (k - 1)) * spacing, 0.0, (j - 0.5 * (rows - 1)) * spacing);
    const std::string name = "cube" + std::to_string(n);
    scene.polygons.push_back(face(name + "-front", c + h * z, z, y, side));
    scene.polygons.push_back(face(name + "-back", c - h * z, -z, y, side));
    scene.polygons.push_back(face(name + "-left", c - h * x, -x, y, side));
    scene.polygons.push_back(face(name + "-right", c + h * x, x, y, side));
    scene.polygons.push_back(face(name + "-top", c + h * y, y, -z, side));
  }
  return scene;
}

}  // namespace oflab
