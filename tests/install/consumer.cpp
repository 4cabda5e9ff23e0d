// A user's program linking the installed core library: the flow coefficients of a tilted
// plane translating in front of the camera, and a warp of a small image, each checked
// against values worked out by hand. Prints one line per check; exit status 1 on a mismatch.
#include <cmath>
#include <cstdio>

#include "flow/camera.h"
#include "flow/flow_field.h"
#include "flow/homography.h"
#include "flow/plane.h"
#include "image/layer.h"
#include "image/warp.h"

namespace {

int failures = 0;

void check(const char* what, double got, double want, double tolerance) {
  const bool ok = std::abs(got - want) <= tolerance;
  std::printf("%-28s %14.8g (expected %.8g) %s\n", what, got, want, ok ? "ok" : "MISMATCH");
  if (!ok) ++failures;
}

// Plane through (0, 0, 2) with normal (0.2, -0.1, 1): plane vector n = N / (N.P) =
// (a, b, c) = (0.1, -0.05, 0.5), so 1/Z = a x/f + b y/f + c at centred pixel (x, y).
// A translation V = (0.1, -0.2, 0.3) without rotation moves every plane point by V, and
// the image point x = f X/Z moves by v_x = (f Vx - x Vz) / Z (likewise y). Expanding:
//   tx = f Vx c = 25          ty = f Vy c = -50
//   j11 = Vx a - Vz c = -0.14 j12 = Vx b = -0.005
//   j21 = Vy a = -0.02        j22 = Vy b - Vz c = -0.14
//   px = -Vz a / f = -6e-5    py = -Vz b / f = 3e-5
void check_flow() {
  const oflab::Camera camera = oflab::make_camera(500.0, 640, 480);
  oflab::PlanePose pose;
  pose.point = {0.0, 0.0, 2.0};
  pose.normal = {0.2, -0.1, 1.0};
  oflab::RigidMotion motion;
  motion.velocity = {0.1, -0.2, 0.3};
  const oflab::PlanarFlowCoefficients c = oflab::planar_flow_coefficients(camera, pose, motion);
  check("tx (px per unit time)", c.tx, 25.0, 1e-9);
  check("ty", c.ty, -50.0, 1e-9);
  check("j11", c.j11, -0.14, 1e-12);
  check("j12", c.j12, -0.005, 1e-12);
  check("j21", c.j21, -0.02, 1e-12);
  check("j22", c.j22, -0.14, 1e-12);
  check("px", c.px, -6e-5, 1e-15);
  check("py", c.py, 3e-5, 1e-15);
  // The first-order homography over dt = 0.01 moves the principal point by (tx, ty) dt.
  const oflab::Vec2 moved = oflab::apply_homography(oflab::taylor_homography(c, 0.01), {0.0, 0.0});
  check("Taylor homography x(0,0)", moved.x, 0.25, 1e-12);
  check("Taylor homography y(0,0)", moved.y, -0.5, 1e-12);
}

// A 4 x 3 image whose pixel (x, y) has red 10 x + 50 y + 5, shifted by (2, 1) into an
// 8 x 6 output: output pixel (x + 2, y + 1) is source pixel (x, y); 12 pixels written.
void check_warp() {
  oflab::Image source(4, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      source.at(x, y) = oflab::Pixel{static_cast<std::uint8_t>(10 * x + 50 * y + 5), 0, 0, 255};
    }
  }
  oflab::Image output(8, 6);
  const oflab::WarpStats stats = oflab::warp_layer_into(
      oflab::make_layer(source), oflab::translation_matrix(2.0, 1.0), output, 0, 0);
  check("warp pixels written", static_cast<double>(stats.pixels_written), 12.0, 0.0);
  check("warp output (5, 3) red", output.at(5, 3).r, 10 * 3 + 50 * 2 + 5, 0.0);
  check("warp output (2, 1) red", output.at(2, 1).r, 5, 0.0);
  check("warp output (1, 1) alpha", output.at(1, 1).a, 0, 0.0);
}

}  // namespace

int main() {
  check_flow();
  check_warp();
  std::printf("%s\n", failures == 0 ? "oflab consumer: all checks passed"
                                    : "oflab consumer: checks FAILED");
  return failures == 0 ? 0 : 1;
}
