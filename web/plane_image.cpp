#include "plane_image.h"

namespace oflab {

const PlaneImage& PlaneImageCache::image(const PlaneScene& scene, const Image& texture,
                                         Sampling sampling, int epoch, int frame) {
  if (epoch_ == epoch && frame_ == frame) return image_;
  epoch_ = epoch;
  frame_ = frame;
  image_ = PlaneImage{PlacedLayer{}, scene.camera.width, scene.camera.height};
  if (!plane_scene_problem(scene).empty() || !plane_visibility_problem(scene.pose).empty()) {
    return image_;
  }
  if (texture_epoch_ != epoch) {
    texture_ = make_layer(texture);
    texture_epoch_ = epoch;
  }
  if (texture_.empty()) return image_;
  image_.placed = render_exact(scene.camera, texture_, scene.pose, sampling);
  return image_;
}

}  // namespace oflab
