// Planar flow coefficients from the velocity gradient B (manual/flow-math.md section 2).
#include "flow/flow_field.h"

namespace oflab {
namespace {

// a b^T, written by rows so the index order is the printed one.
Mat3 outer(const Vec3& a, const Vec3& b) { return mat3_from_rows(a.x * b, a.y * b, a.z * b); }

}  // namespace

Mat3 velocity_gradient(const PlanePose& pose, const RigidMotion& motion) {
  return cross_matrix(motion.omega) + outer(eye_velocity(motion, pose), plane_vector(pose));
}

PlanarFlowCoefficients planar_flow_coefficients(const Camera& camera, const PlanePose& pose,
                                                const RigidMotion& motion) {
  const Mat3 b = velocity_gradient(pose, motion);
  const double f = camera.focal_px;
  PlanarFlowCoefficients c;
  c.tx = f * entry(b, 0, 2);
  c.ty = f * entry(b, 1, 2);
  c.j11 = entry(b, 0, 0) - entry(b, 2, 2);
  c.j12 = entry(b, 0, 1);
  c.j21 = entry(b, 1, 0);
  c.j22 = entry(b, 1, 1) - entry(b, 2, 2);
  c.px = -entry(b, 2, 0) / f;
  c.py = -entry(b, 2, 1) / f;
  return c;
}

Vec2 flow_at(const PlanarFlowCoefficients& c, const Vec2& p) {
  const double x = p.x - c.origin.x;
  const double y = p.y - c.origin.y;
  const double q = c.px * x + c.py * y;
  return Vec2(c.tx + c.j11 * x + c.j12 * y + q * x, c.ty + c.j21 * x + c.j22 * y + q * y);
}

PlanarFlowCoefficients reexpand(const PlanarFlowCoefficients& c, const Vec2& origin) {
  const Vec2 d = origin - c.origin;
  PlanarFlowCoefficients r = c;
  const Vec2 v = flow_at(c, origin);
  r.tx = v.x;
  r.ty = v.y;
  r.j11 = c.j11 + 2.0 * c.px * d.x + c.py * d.y;
  r.j12 = c.j12 + c.py * d.x;
  r.j21 = c.j21 + c.px * d.y;
  r.j22 = c.j22 + c.px * d.x + 2.0 * c.py * d.y;
  r.origin = origin;
  return r;
}

Vec2 exact_flow_at(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                   const Vec2& p) {
  const Vec3 r = plane_point_at_pixel(pose, camera.focal_px, p);
  const Vec3 dr = eye_velocity(motion, pose) + glm::cross(motion.omega, r);
  const double f = camera.focal_px;
  return Vec2(f * (dr.x * r.z - r.x * dr.z) / (r.z * r.z),
              f * (dr.y * r.z - r.y * dr.z) / (r.z * r.z));
}

Vec2 image_acceleration(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                        const Vec2& p) {
  // rho = R / Z = (x/f, y/f, 1); w = B rho; c = [Omega]x (B - V_ref n^T) rho;
  // rho'' = c - 2 w w3 - rho c3 + 2 rho w3^2.
  const double f = camera.focal_px;
  const Vec3 rho(p.x / f, p.y / f, 1.0);
  const Mat3 b = velocity_gradient(pose, motion);
  const Mat3 b_ref = b - outer(acceleration_reference_velocity(motion, pose), plane_vector(pose));
  const Vec3 w = b * rho;
  const Vec3 c = cross_matrix(motion.omega) * (b_ref * rho);
  const Vec3 acc = c - 2.0 * w * w.z - rho * c.z + 2.0 * rho * w.z * w.z;
  return Vec2(f * acc.x, f * acc.y);
}

}  // namespace oflab
