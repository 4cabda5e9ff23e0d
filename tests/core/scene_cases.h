// Scenes for the scene tests, built in code, and the per-pixel reference they are checked
// against: a ray caster that shares nothing with the engine but the data model.
#pragma once

#include <random>
#include <vector>

#include "flow/camera.h"
#include "image/image.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab::testing {

// An opaque checkerboard texture (8-texel cells, two colours, a distinct colour per
// quadrant so that mirroring or rotation shows).
Image checker_image(int width, int height);

// A square polygon of side `size` centred at `centre` facing `front`, with up `up`.
ScenePolygon square(const std::string& name, const Vec3& centre, const Vec3& front, const Vec3& up,
                    double size, int texture = 0);

// The five faces of an open cube (bottom missing), outward normals, world Y up.
std::vector<ScenePolygon> open_cube(const std::string& name, const Vec3& centre, double size);

// A scene with one checker texture (64 x 64) and the given polygons.
Scene scene_with(std::vector<ScenePolygon> polygons);

// A near open cube (side 0.8, at the origin) in front of a far one (side 2, at (0.3, 0, -3)):
// seen by a viewer sliding sideways (sliding_past), the near cube uncovers the far one.
Scene cube_past_cube();

// `frames` frames of a viewer starting at (-0.3, 0.8, 3.5) looking down -Z, moving with
// `velocity` and turning with `omega` (world units and radians per frame).
std::vector<ViewerFrame> sliding_past(int frames, const Vec3& velocity, const Vec3& omega);

// Three motions past cube_past_cube, 10 to 12 frames each: a sideways slide, a turn, and
// segments of a slide, a push forward and a turning slide (translate, rotate, compound).
std::vector<std::vector<ViewerFrame>> three_motions_past();

// World point `world` projected into `camera` seen from `view`, top-left pixels.
Vec2 project_world(const Camera& camera, const ViewerPose& view, const Vec3& world);

// `count` random convex polygons (3 to 6 vertices) in random planes, each inside its own
// ball, the balls disjoint, so no two polygons intersect; all within [-6, 6]^3.
std::vector<ScenePolygon> random_polygons(std::mt19937& rng, int count);

// The per-pixel reference: for each pixel centre, the ray from the eye meets every polygon
// facing the eye; hits beyond the near plane inside the polygon's outline are composited
// far to near, each sampling its texture at the texel that contains the hit (nearest).
Image ray_cast_scene(const Scene& scene, const Camera& camera, const ViewerPose& view, double near);

// The world point seen at top-left pixel position (u, v) of `camera` at `view` on `polygon`'s
// plane, found in world coordinates: the eye, the ray's world direction, the plane's world
// centre and normal. Precondition: the ray is not parallel to the plane.
Vec3 world_point_at(const Camera& camera, const ScenePolygon& polygon, const ViewerPose& view,
                    double u, double v);

// A texture whose texels say where they are: red and green the texel's column and row, blue
// 16 x `polygon`. 256 x 256 texels, opaque.
Image coded_texture(int polygon);

// `scene` with every polygon i given its own coded_texture(i) (at most 16 polygons).
Scene with_coded_textures(Scene scene);

// The largest distance, pixels, between an opaque pixel's centre in `frame` and the exact
// projection from `view` of the texel centre its colour names (coded_texture): the error read
// back from the image alone.
double coded_image_error(const Scene& scene, const Camera& camera, const Image& frame,
                         const ViewerPose& view);

// Share of pixels whose colour differs by more than `tolerance` in any channel (0..1),
// counting only pixels that are not transparent in at least one of the images.
double mismatch_fraction(const Image& a, const Image& b, int tolerance = 8);

// Writes a binary PPM next to the test binary for inspection after a failure
// (premultiplied colour over black).
void save_ppm(const std::string& path, const Image& image);

}  // namespace oflab::testing
