// What a layer shows, and so what a re-render costs: the content a plane's layer is drawn
// from. Warps reuse the layer image whatever the content; only a re-render (and the exact
// view beside the animation) draws the content again, through render_content.
//
//  - texture: the plane's bitmap, one perspective warp per re-render (the dissertation's
//    case, and the engine's own path: core/engine/engine.h warps the texture itself);
//  - shaded: a procedural brick material with a normal map (bevelled mortar joints), lit
//    per sample by a directional light (Blinn-Phong), anti-aliased by `quality` samples per
//    pixel: its cost grows linearly with quality;
//  - impostor: the plane is a proxy for a building facade in front of it (windows with
//    frames and sills, balconies with railings): boxes rasterised by core's scan converter
//    (core/image/scan_conversion.h) with a depth buffer, back faces culled, each face lit
//    (Blinn-Phong at its centre). `quality` is the detail: storeys 1 + quality and bays
//    1 + 2 quality, so the polygon count grows quadratically with it.
//
// Frames. Poses are in the viewer frame (core/flow/plane.h); the light is a direction in the
// same frame, fixed to the viewer (a lamp over the viewer's shoulder), so a plane that turns
// or moves relative to the viewer changes its shading. Texel (u, v) of the plane is its
// texture point (core/flow/plane.h); the texture grid gives the valid region, while the
// patterns are laid out in world units (bricks 0.2 x 0.07; the facade divides the plane).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/limits.h"
#include "flow/plane.h"
#include "image/polygon.h"
#include "image/warp.h"

namespace oflab {

enum class ContentKind { kTexture, kShaded, kImpostor };

// "texture", "shaded", "impostor".
const char* content_name(ContentKind kind);
// Parses a name above; false (and *kind untouched) for anything else.
bool parse_content(const std::string& text, ContentKind* kind);
// Every kind, in the order above (the registry the CLI, the GUI and help texts read).
std::vector<ContentKind> content_kinds();
// The names joined by `separator`, in the order above.
std::string content_name_list(const std::string& separator = ", ");

// Largest quality accepted (samples per pixel of shaded, detail of impostor): the maximum of
// limits::kContentQuality (core/flow/limits.h), where the range is stated.
constexpr int kMaxContentQuality = static_cast<int>(limits::kContentQuality.maximum);

struct LayerContent {
  ContentKind kind = ContentKind::kTexture;
  // shaded: samples per pixel; impostor: detail (see above). 1 .. kMaxContentQuality.
  int quality = 1;
  // Direction towards the light, viewer frame (Y down, Z forward), any non-zero length:
  // by default up, left and behind the viewer.
  Vec3 light{-0.4, -0.6, -1.0};
};

// A Blinn-Phong material of the lit contents. The linear colour of a surface point x
// (viewer frame) with unit normal N, seen from the eye at the origin under the unit light
// direction L, is albedo (kContentAmbient + kContentDiffuse (N.L)+) + specular (N.H)^shininess
// with H = normalize(L - x / |x|), the specular term only where N.L > 0.
struct ContentMaterial {
  Vec3 albedo{1.0};  // linear RGB, 0 .. 1
  double specular = 0.0;
  double shininess = 1.0;
};
// The specular factor c^shininess of a material, for c = (N.H)+ in [0, 1]: by k squarings
// where the shininess is 2^k with k <= 8 (every material of the lit contents: 8 to 64), each
// rounding once, so within (2^k - 1) 2^-53 relative of the exact power (7e-15 at 64, far
// below the 1/510 on which a byte's rounding turns), else std::pow. The lit contents'
// hottest call: a shaded wall lights every sample.
double specular_power(double c, double shininess);

constexpr double kContentAmbient = 0.25;
constexpr double kContentDiffuse = 0.75;

// The shaded content's brick at (x, y), world units right and down from the plane's top-left
// corner: a running bond of 0.2 x 0.07 bricks with 0.016 wide mortar joints, each brick's
// albedo tinted by a hash of its row and column and a finer grain, and 0.02 wide bevels
// whose slope tilts the normal towards the joint. `slope` is the surface's rise along +x and
// +y (dimensionless, |slope| <= 0.8 per axis): the shading normal is
// normalize(front - slope.x right + slope.y up) in the plane's axes.
struct BrickSample {
  ContentMaterial material;
  Vec2 slope{0.0};
};
BrickSample brick_at(double x, double y);

// The parts of the facade impostor, each with its material.
enum class FacadePart { kWall, kGlass, kFrame, kStone, kRail };
constexpr std::array<FacadePart, 5> kFacadeParts = {FacadePart::kWall, FacadePart::kGlass,
                                                    FacadePart::kFrame, FacadePart::kStone,
                                                    FacadePart::kRail};
ContentMaterial facade_material(FacadePart part);

// One quadrilateral face of the facade impostor, in plane coordinates (s, t, h): world
// units right and up from the plane's centre and out of its front (h >= 0; the wall is
// h = 0). Corners in order around the face, either winding; `normal` is unit and outward
// (the face is seen only from the side it points to).
struct FacadeFace {
  std::array<Vec3, 4> corners;
  Vec3 normal;
  FacadePart part;
};

// The geometry the impostor content draws for a plane of `size` (world units, both > 0) at
// detail `detail` (1 .. kMaxContentQuality): the wall, then per cell of 1 + detail storeys
// and 1 + 2 detail bays a window (glass, four frame bars, a stone sill) and on every second
// storey a balcony (a stone slab, a rail and five posts); boxes are five faces (their back
// lies on the wall). The same faces render_content rasterises, for other renderers to draw.
std::vector<FacadeFace> facade_faces(const Vec2& size, int detail);

// Empty when the content can be rendered; else a one-line reason naming the field
// ("quality" out of 1 .. kMaxContentQuality, "light" zero or not finite).
std::string content_problem(const LayerContent& content);

// The samples one re-render of `content` may take for a layer of `layer_pixels` pixels:
// quality per pixel for shaded content, 0 for the other kinds (whose cost the impostor
// detail limit bounds).
double shaded_samples(const LayerContent& content, double layer_pixels);
// "" when `samples` is within limits::kShadedSamples; otherwise one phrase naming the figure
// and the limit: "<subject> may take N shaded samples a frame, more than 134217728 (the
// shaded samples limit)".
std::string shaded_samples_problem(double samples, const std::string& subject);
// shaded_samples_problem of one plane's layer as large as `camera`'s image: "shaded content
// at quality 256 on a 8192 x 8192 px camera may take ... (the shaded samples limit)".
std::string plane_shaded_samples_problem(const LayerContent& content, const Camera& camera);

// True when a re-render lights the content (shaded, impostor): its shading depends on the
// pose, so a warped image of it can go stale.
bool content_is_lit(const LayerContent& content);

// What a content render did: the pixels it wrote and its work units, the shaded samples or
// the impostor's rasterised fragments (both deterministic for a given pose).
struct ContentStats {
  std::int64_t pixels_written = 0;
  std::int64_t work_units = 0;
};

// Renders a lit content (shaded or impostor) of the plane at `pose` into `out`, reusing its
// memory: out.layer covers the pixels (top-left image pixels) whose centre lies in
// `image_region`, at out.offset_x/y, transparent elsewhere, its polygon the region. Only
// texels inside `texel_region` (texels of pose.texture_size) are drawn, and only where the
// pixel's ray meets the plane in front of the eye: a region clipped to the view frustum
// renders that part alone. Preconditions: content_problem empty, content not texture, the
// pose's axes valid (plane_pose_problem empty but for "point"), the region's box within
// kMaxImageDimension. Throws std::invalid_argument for a texture content or a too large box.
ContentStats render_content(const LayerContent& content, const Camera& camera,
                            const PlanePose& pose, const ConvexPolygon& texel_region,
                            const ConvexPolygon& image_region, WarpedLayer& out);

// Cost of one work unit of render_content, in pixels of a perspective warp (the
// dissertation's cost unit, section 6.4.4): measured with oflab-bench on the development
// machine (bench case content/...; manual/costs.md) and fixed here so that the modelled
// work is deterministic.
double content_unit_cost(ContentKind kind);

// The photometric error a reused image of a lit content shows at pose `now` when it was
// rendered at `rendered`: the largest change, in 8-bit grey levels (0 .. 255), of the lit
// intensity of a white surface over a 5 x 5 grid of plane points, for each facing the
// content has (the plane's front; an impostor's box sides too). 0 for texture content.
// Preconditions: both poses have valid axes and the same size.
double shading_change(const LayerContent& content, const PlanePose& rendered, const PlanePose& now);

}  // namespace oflab
