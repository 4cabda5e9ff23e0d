// The flow view's texture: the exact image of the plane of a scene, as the engine's exact
// re-render draws it (core/engine/exact_render.h render_exact), kept while the frame and the
// state stay.
#pragma once

#include "engine/exact_render.h"
#include "flow/plane_scene.h"
#include "image/image.h"
#include "image/layer.h"

namespace oflab {

// The exact image of a plane in a camera of width x height pixels: `placed` is the layer
// render_exact gives (premultiplied RGBA, transparent off the plane) and its top-left pixel
// in the camera image. The camera image is `placed` composited over transparent pixels.
struct PlaneImage {
  PlacedLayer placed;
  int width = 0;
  int height = 0;
};

class PlaneImageCache {
 public:
  // The exact image of `scene`'s plane textured with `texture` (premultiplied RGBA, top row
  // first) and drawn with `sampling`, top-left pixels. Its layer is empty for a scene problem
  // (plane_scene_problem), a plane that cannot be drawn whole (plane_visibility_problem:
  // partly behind the eye), an empty texture, or a plane outside the image. Computed again
  // only when `epoch` (the state's: it may change the scene, the texture and the sampling)
  // or `frame` differ from the last call's.
  const PlaneImage& image(const PlaneScene& scene, const Image& texture, Sampling sampling,
                          int epoch, int frame);

 private:
  Layer texture_;  // `texture` as a layer, at texture_epoch_
  int texture_epoch_ = -1;
  PlaneImage image_;  // the image of frame_ at epoch_
  int epoch_ = -1;
  int frame_ = -1;
};

}  // namespace oflab
