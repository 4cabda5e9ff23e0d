#include "flow/camera.h"

#include <cmath>

namespace oflab {

Camera make_camera(double focal_px, int width, int height) {
  Camera c;
  c.focal_px = focal_px;
  c.width = width;
  c.height = height;
  c.cx = width / 2.0;
  c.cy = height / 2.0;
  return c;
}

const char* camera_problem(const Camera& camera) {
  if (!std::isfinite(camera.focal_px) || camera.focal_px <= 0.0) {
    return "focal length must be a positive number of pixels";
  }
  if (camera.width <= 0 || camera.height <= 0) return "image size must be positive";
  if (!std::isfinite(camera.cx) || !std::isfinite(camera.cy)) {
    return "principal point must be finite";
  }
  return "";
}

Mat3 centred_intrinsics(const Camera& camera) {
  return mat3_from_rows({camera.focal_px, 0.0, 0.0}, {0.0, camera.focal_px, 0.0}, {0.0, 0.0, 1.0});
}

Mat3 centred_to_pixel_homography(const Camera& camera, const Mat3& h_centred) {
  return translation_matrix(camera.cx, camera.cy) * h_centred *
         translation_matrix(-camera.cx, -camera.cy);
}

}  // namespace oflab
