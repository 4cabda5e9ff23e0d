// Small geometric vocabulary shared by every core file: vectors, 3x3 matrices, homogeneous
// points. Built on GLM (double precision). GLM matrices are column-major: m[col][row].
// Use the helpers below (mat3_from_rows, entry) to write matrices in the row-major order
// of the dissertation and the manual, so no index is ever transposed by hand.
#pragma once

#include <array>
#include <glm/glm.hpp>

namespace oflab {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Mat3 = glm::dmat3;

// Builds a matrix from its rows: mat3_from_rows({a,b,c},{d,e,f},{g,h,i}) is
// [[a,b,c],[d,e,f],[g,h,i]] as printed.
inline Mat3 mat3_from_rows(const Vec3& r0, const Vec3& r1, const Vec3& r2) {
  return glm::transpose(Mat3(r0, r1, r2));
}

// Entry at row r, column c (both 0-based), in the printed (row-major) sense.
inline double entry(const Mat3& m, int r, int c) { return m[c][r]; }
inline double& entry(Mat3& m, int r, int c) { return m[c][r]; }

// Row-major copy of the nine entries, the order used in JSON output and files.
inline std::array<double, 9> row_major(const Mat3& m) {
  return {entry(m, 0, 0), entry(m, 0, 1), entry(m, 0, 2), entry(m, 1, 0), entry(m, 1, 1),
          entry(m, 1, 2), entry(m, 2, 0), entry(m, 2, 1), entry(m, 2, 2)};
}

// The z component of the cross product of 2D vectors a and b (a.x b.y - a.y b.x): twice the
// signed area of the triangle (0, a, b), positive when b turns clockwise from a on screen (y
// down).
inline double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// Applies homography H to the 2D point p (homogeneous w = 1) and divides by the third
// coordinate. Precondition: the denominator is not zero (the point is not sent to
// infinity); callers near the horizon line must check homography_denominator first.
inline Vec2 apply_homography(const Mat3& h, const Vec2& p) {
  const Vec3 q = h * Vec3(p, 1.0);
  return Vec2(q.x / q.z, q.y / q.z);
}

// The third homogeneous coordinate of H*(p, 1): its sign tells on which side of the
// horizon line p lies; zero means p maps to infinity.
inline double homography_denominator(const Mat3& h, const Vec2& p) {
  return entry(h, 2, 0) * p.x + entry(h, 2, 1) * p.y + entry(h, 2, 2);
}

// Scales H so that its (3,3) entry is 1. Precondition: entry (3,3) is not zero.
inline Mat3 normalise_homography(const Mat3& h) { return h * (1.0 / entry(h, 2, 2)); }

// The cross-product matrix [w]x with [w]x * r == cross(w, r).
inline Mat3 cross_matrix(const Vec3& w) {
  return mat3_from_rows({0.0, -w.z, w.y}, {w.z, 0.0, -w.x}, {-w.y, w.x, 0.0});
}

// Translation by (tx, ty) as a 3x3 homogeneous matrix.
inline Mat3 translation_matrix(double tx, double ty) {
  return mat3_from_rows({1.0, 0.0, tx}, {0.0, 1.0, ty}, {0.0, 0.0, 1.0});
}

}  // namespace oflab
