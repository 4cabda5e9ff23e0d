// Pinhole camera of the viewer (dissertation section 4.3, in pixel units).
//
// Frame: the eye is at the origin, X right, Y down, Z forward (right-handed), fixed to the
// viewer. A point R = (X, Y, Z) with Z > 0 projects to the continuous pixel position
//   u = cx + f X / Z,   v = cy + f Y / Z,
// where pixel (i, j) covers [i, i+1) x [j, j+1), so its centre is at (i + 0.5, j + 0.5).
// "Centred" pixel coordinates are x = u - cx, y = v - cy; every flow coefficient and
// every frame-to-frame homography in core/ is expressed in centred pixels unless its
// name says otherwise.
#pragma once

#include "flow/geometry.h"

namespace oflab {

struct Camera {
  double focal_px = 256.0;  // focal length f, pixels per unit of X/Z (must be > 0)
  double cx = 128.0;        // principal point, pixels from the left edge
  double cy = 128.0;        // principal point, pixels from the top edge
  int width = 256;          // image size in pixels
  int height = 256;
};

// A camera whose principal point is the image centre (W/2, H/2).
// Preconditions: focal_px > 0, width > 0, height > 0 (checked by camera_problem).
Camera make_camera(double focal_px, int width, int height);

// Empty string when the camera is usable, otherwise a one-line description of what is wrong.
const char* camera_problem(const Camera& camera);

// Centred pixel position of the camera-frame point r. Precondition: r.z > 0. (Inline, as the
// two below: per-pixel loops call them.)
inline Vec2 project_centred(const Camera& camera, const Vec3& r) {
  return Vec2(camera.focal_px * r.x / r.z, camera.focal_px * r.y / r.z);
}

// Conversions between centred and top-left pixel coordinates (same units, shifted origin).
inline Vec2 centred_to_pixel(const Camera& camera, const Vec2& centred) {
  return centred + Vec2(camera.cx, camera.cy);
}
inline Vec2 pixel_to_centred(const Camera& camera, const Vec2& pixel) {
  return pixel - Vec2(camera.cx, camera.cy);
}

// The intrinsic matrix for centred pixels, diag(f, f, 1): maps a camera-frame direction
// (X, Y, Z) to homogeneous centred pixels.
Mat3 centred_intrinsics(const Camera& camera);

// Re-expresses a homography that maps centred pixels to centred pixels as one that maps
// top-left pixels to top-left pixels: T H T^-1 with T the shift by (cx, cy).
Mat3 centred_to_pixel_homography(const Camera& camera, const Mat3& h_centred);

}  // namespace oflab
