// Layer contents: a re-render through the engine draws exactly what render_content draws (the
// exact view's renderer), the impostor's depth order and lighting on hand-checked pixels, and
// the photometric error: zero for an unlit texture, growing as a lit plane turns.
#include "content/layer_content.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "engine/script.h"
#include "flow/motion.h"
#include "image/composite.h"
#include "image/image_compare.h"

namespace oflab {
namespace {

PlanePose facade_pose() {
  PlanePose p;
  p.point = Vec3(0.0, 0.0, 6.0);
  p.size = Vec2(3.0, 2.0);
  p.texture_size = glm::ivec2(300, 200);
  return p;
}

Layer blank_texture(glm::ivec2 size) {
  return make_layer(Image(size.x, size.y, Pixel{0, 0, 0, 255}));
}

// The engine's frame 0 (a re-render) against render_content called directly.
void expect_engine_draws_content(const LayerContent& content, const char* policy) {
  const Camera camera = make_camera(400.0, 640, 480);
  PlanePose pose = facade_pose();
  pose.normal = Vec3(0.3, -0.1, 1.0);
  EngineSettings settings;
  settings.content = content;
  settings.policy = &reuse_policy(policy);
  PlaneEngine engine(camera, blank_texture(pose.texture_size), settings);
  const FrameReport r = engine.start(pose);
  ASSERT_EQ(r.level, Level::kRerender);
  WarpedLayer direct;
  const Layer texture = blank_texture(pose.texture_size);
  const ContentStats stats =
      render_content(content, camera, pose, texture.polygon,
                     transform(texture.polygon, exact_texture_warp(camera, pose)), direct);
  const PlacedLayer& shown = engine.displayed();
  EXPECT_EQ(shown.offset_x, direct.offset_x);
  EXPECT_EQ(shown.offset_y, direct.offset_y);
  ASSERT_EQ(shown.layer.image.width(), direct.layer.image.width());
  ASSERT_EQ(shown.layer.image.height(), direct.layer.image.height());
  EXPECT_TRUE(shown.layer.image.pixels() == direct.layer.image.pixels());
  EXPECT_EQ(r.pixels_written, stats.pixels_written);
  EXPECT_GT(stats.pixels_written, 10000);
  EXPECT_DOUBLE_EQ(r.model_work, stats.work_units * content_unit_cost(content.kind));
}

TEST(LayerContent, EngineRerenderDrawsWhatTheExactViewDraws) {
  for (const char* policy : {"rerender", "perspective"}) {
    expect_engine_draws_content({ContentKind::kShaded, 4, Vec3(-0.4, -0.6, -1.0)}, policy);
    expect_engine_draws_content({ContentKind::kImpostor, 2, Vec3(-0.4, -0.6, -1.0)}, policy);
  }
}

TEST(LayerContent, NamesParseAndBadSettingsAreNamed) {
  ContentKind k = ContentKind::kTexture;
  EXPECT_TRUE(parse_content("impostor", &k));
  EXPECT_EQ(k, ContentKind::kImpostor);
  EXPECT_FALSE(parse_content("brick", &k));
  EXPECT_EQ(content_name_list(), "texture, shaded, impostor");
  LayerContent c;
  c.quality = 0;
  EXPECT_NE(content_problem(c).find("quality"), std::string::npos);
  c.quality = 1;
  c.light = Vec3(0.0);
  EXPECT_NE(content_problem(c).find("light"), std::string::npos);
}

// Pixel of plane point (s, t, h) of facade_pose seen head-on by make_camera(400, 640, 480).
Pixel facade_pixel(const Image& frame, double s, double t, double h) {
  const double z = 6.0 - h;
  return frame.at(static_cast<int>(std::floor(320.0 + 400.0 * s / z)),
                  static_cast<int>(std::floor(240.0 - 400.0 * t / z)));
}

Image render_facade(const Vec3& light) {
  const Camera camera = make_camera(400.0, 640, 480);
  const PlanePose pose = facade_pose();
  const Layer texture = blank_texture(pose.texture_size);
  WarpedLayer out;
  render_content({ContentKind::kImpostor, 1, light}, camera, pose, texture.polygon,
                 transform(texture.polygon, exact_texture_warp(camera, pose)), out);
  Image frame(camera.width, camera.height);
  for (int y = 0; y < out.layer.image.height(); ++y) {
    for (int x = 0; x < out.layer.image.width(); ++x) {
      frame.at(x + out.offset_x, y + out.offset_y) = out.layer.image.at(x, y);
    }
  }
  return frame;
}

// A pixel lit as albedo (ambient 0.25 + diffuse 0.75 cos) plus a white specular highlight
// of at most `specular`: the excess over the diffuse colour is the same grey on all channels.
void expect_lit(const Pixel& p, const Vec3& albedo, double cosine, double specular) {
  const double d = 0.25 + 0.75 * cosine;
  const double er = p.r - 255.0 * albedo.r * d, eg = p.g - 255.0 * albedo.g * d,
               eb = p.b - 255.0 * albedo.b * d;
  EXPECT_NEAR(er, eg, 1.5);
  EXPECT_NEAR(er, eb, 1.5);
  EXPECT_GE(er, -1.0);
  EXPECT_LE(er, 255.0 * specular + 1.0);
  EXPECT_EQ(p.a, 255);
}

// Quality 1 on a 3 x 2 facade: storeys 2, bays 3, 1 x 1 cells. The middle window of the
// ground storey has its glass over s in [-0.25, 0.25], t in [-0.8, -0.2] and its sill below;
// the upper storey has a balcony whose middle rail post (s = 0, from t = 0.08 to 0.37, 0.39 to
// 0.45 in front of the wall) stands in front of that storey's glass.
TEST(LayerContent, ImpostorDepthOrderAndLightingOnHandCases) {
  const Image head_on = render_facade(Vec3(0.0, 0.0, -1.0));
  const Vec3 wall(0.80, 0.68, 0.52), glass(0.15, 0.22, 0.30), stone(0.70, 0.70, 0.68),
      rail(0.20, 0.20, 0.22);
  expect_lit(facade_pixel(head_on, -1.0, 0.9, 0.0), wall, 1.0, 0.10);     // wall, above all
  expect_lit(facade_pixel(head_on, 0.1, -0.5, 0.0), glass, 1.0, 0.60);    // glass over wall
  expect_lit(facade_pixel(head_on, 0.0, -0.89, 0.15), stone, 1.0, 0.10);  // sill
  expect_lit(facade_pixel(head_on, 0.0, 0.3, 0.45), rail, 1.0, 0.40);     // post before glass
  expect_lit(facade_pixel(head_on, 0.1, 0.3, 0.0), glass, 1.0, 0.60);     // glass beside it
  // A light 60 degrees to the right: the front faces get half the diffuse light.
  const Image side = render_facade(Vec3(std::sqrt(3.0), 0.0, -1.0));
  expect_lit(facade_pixel(side, -1.0, 0.9, 0.0), wall, 0.5, 0.10);
  expect_lit(facade_pixel(side, 0.1, -0.5, 0.0), glass, 0.5, 0.60);
}

TEST(LayerContent, ShadedEdgesAreAntiAliasedBySupersampling) {
  const Camera camera = make_camera(400.0, 640, 480);
  PlanePose pose = facade_pose();
  pose.normal = Vec3(0.0, 0.0, 1.0);
  pose.up = Vec3(0.3, -1.0, 0.0);  // tilted edges
  const Layer texture = blank_texture(pose.texture_size);
  const ConvexPolygon region = transform(texture.polygon, exact_texture_warp(camera, pose));
  int partial_1 = 0, partial_16 = 0;
  for (int q : {1, 16}) {
    WarpedLayer out;
    const ContentStats s = render_content({ContentKind::kShaded, q, Vec3(-0.4, -0.6, -1.0)}, camera,
                                          pose, texture.polygon, region, out);
    EXPECT_EQ(s.work_units % q, 0);
    int& partial = q == 1 ? partial_1 : partial_16;
    for (const Pixel& p : out.layer.image.pixels()) partial += (p.a > 0 && p.a < 255) ? 1 : 0;
  }
  EXPECT_EQ(partial_1, 0);
  EXPECT_GT(partial_16, 100);
}

PlanePose turned(const PlanePose& p, double degrees) {
  PlanePose q = p;
  const Mat3 r = rotation_matrix(Vec3(0.0, degrees * M_PI / 180.0, 0.0));
  q.normal = r * p.normal;
  q.up = r * p.up;
  return q;
}

TEST(LayerContent, ShadingChangeIsZeroUnlitAndGrowsAsALitPlaneTurns) {
  const PlanePose p = facade_pose();
  EXPECT_EQ(shading_change(LayerContent{}, p, turned(p, 30.0)), 0.0);
  for (ContentKind kind : {ContentKind::kShaded, ContentKind::kImpostor}) {
    LayerContent lit{kind, 1, Vec3(-0.4, -0.6, -1.0)};
    EXPECT_EQ(shading_change(lit, p, p), 0.0);
    double last = 0.0;
    for (double deg : {2.0, 5.0, 10.0, 20.0}) {
      const double e = shading_change(lit, p, turned(p, deg));
      EXPECT_GT(e, last) << content_name(kind) << " at " << deg;
      last = e;
    }
  }
}

// The impostor's shading change against the definition computed here on its own (Blinn-Phong
// of a white surface with std::pow, every facade material, every facing, the 5 x 5 grid):
// agreement to 1e-9 grey levels over turns, tilts and moves.
TEST(LayerContent, ShadingChangeOfTheImpostorIsTheLargestChangeOfAWhiteSurfacesLight) {
  const Vec3 light = glm::normalize(Vec3(-0.4, -0.6, -1.0));
  const auto white_grey = [&](const PlanePose& pose, const Vec3& facing, const ContentMaterial& m,
                              double s, double t) {
    const PlaneAxes axes = plane_axes(pose);
    const Vec3 n = facing.x * axes.right + facing.y * axes.up - facing.z * axes.normal;
    const Vec3 x = pose.point + s * axes.right + t * axes.up;
    const Vec3 h = glm::normalize(light + glm::normalize(-x));
    const double diffuse = std::max(0.0, glm::dot(n, light));
    const double spec = diffuse > 0.0 ? std::pow(std::max(0.0, glm::dot(n, h)), m.shininess) : 0.0;
    return 255.0 *
           std::clamp(kContentAmbient + kContentDiffuse * diffuse + m.specular * spec, 0.0, 1.0);
  };
  const std::vector<Vec3> facings = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0),
                                     Vec3(0, -1, 0)};
  const PlanePose p = facade_pose();
  PlanePose tilted = turned(p, 12.0);
  tilted.normal = glm::normalize(tilted.normal + Vec3(0.0, 0.2, 0.0));
  PlanePose moved = turned(p, -7.0);
  moved.point += Vec3(1.5, -0.5, 2.0);
  const LayerContent impostor{ContentKind::kImpostor, 1, Vec3(-0.4, -0.6, -1.0)};
  for (const PlanePose& now : {turned(p, 3.0), turned(p, 25.0), tilted, moved}) {
    double worst = 0.0;
    for (int i = 0; i < 5; ++i) {
      for (int j = 0; j < 5; ++j) {
        const double s = (i / 4.0 - 0.5) * p.size.x, t = (j / 4.0 - 0.5) * p.size.y;
        for (const Vec3& facing : facings) {
          for (FacadePart part : kFacadeParts) {
            const ContentMaterial m = facade_material(part);
            worst = std::max(
                worst, std::abs(white_grey(p, facing, m, s, t) - white_grey(now, facing, m, s, t)));
          }
        }
      }
    }
    EXPECT_GT(worst, 0.5);
    EXPECT_NEAR(shading_change(impostor, p, now), worst, 1e-9);
  }
}

// A plane turning about its vertical axis, 0.5 degrees a frame, animated by the perspective
// policy: reused frames report the stale shading, which is 0 for the texture.
std::vector<FrameReport> turning_run(ContentKind kind) {
  const Camera camera = make_camera(400.0, 640, 480);
  MotionScript script;
  script.camera = camera;
  ScriptSegment turn;
  turn.frames = 20;
  turn.omega = Vec3(0.0, 0.5 * M_PI / 180.0, 0.0);
  PlanePose start = facade_pose();
  start.texture_size = glm::ivec2(96, 64);
  std::vector<ScriptFrame> frames = expand_segments(start, MotionModel::kSpinAboutCentre, {turn});
  EngineSettings settings;
  settings.content.kind = kind;
  settings.thresholds = {4.0, 4.0, 4.0, 4.0};
  PlaneEngine engine(camera, blank_texture(start.texture_size), settings);
  std::vector<FrameReport> out{engine.start(frames[0].pose)};
  for (std::size_t k = 1; k < frames.size(); ++k) {
    out.push_back(engine.advance(frames[k - 1].pose, frames[k - 1].motion, frames[k].pose));
  }
  return out;
}

TEST(LayerContent, EngineReportsStaleShadingOfReusedLitLayers) {
  for (const FrameReport& r : turning_run(ContentKind::kTexture))
    EXPECT_EQ(r.photometric_error, 0.0);
  const std::vector<FrameReport> lit = turning_run(ContentKind::kShaded);
  int reused = 0;
  for (std::size_t k = 1; k < lit.size(); ++k) {
    if (lit[k].level == Level::kRerender) {
      EXPECT_EQ(lit[k].photometric_error, 0.0);
      continue;
    }
    ++reused;
    EXPECT_GT(lit[k].photometric_error, 0.0);
    if (lit[k - 1].level != Level::kRerender) {
      EXPECT_GT(lit[k].photometric_error, lit[k - 1].photometric_error);
    }
  }
  EXPECT_GT(reused, 5);
}

// A cadence outside the registry: a re-render, then two perspective updates, and again.
int g_cadence_choices = 0;
Level rerender_then_perspective(const ReusePolicy&, const FrameInputs&) {
  return g_cadence_choices++ % 3 == 0 ? Level::kRerender : Level::kPerspective;
}

// The frame of an engine's displayed layer over a clear camera-sized image.
Image shown_frame(const PlaneEngine& engine, const Camera& camera) {
  Image frame(camera.width, camera.height);
  const PlacedLayer& shown = engine.displayed();
  composite_over(frame, shown.layer, shown.offset_x, shown.offset_y);
  return frame;
}

// The perspective level of a lit content warps its last render, which the engine keeps where
// it is shown until the displayed layer is replaced (no copy): right after a re-render, and
// again after a perspective update, the frame is the exact render's to within resampling and
// the stale shading of a half-degree turn: 21 to 27 dB here, where warping the render of the
// cycle before (or none) gives 4 to 19 dB right after a re-render.
TEST(LayerContent, PerspectiveUpdatesOfALitLayerWarpItsLastRender) {
  const Camera camera = make_camera(400.0, 640, 480);
  ScriptSegment turn;
  turn.frames = 12;
  turn.omega = Vec3(0.0, 0.5 * M_PI / 180.0, 0.0);
  const PlanePose start = facade_pose();
  const auto frames = expand_segments(start, MotionModel::kSpinAboutCentre, {turn});
  ReusePolicy cadence = reuse_policy("perspective");
  cadence.choose = rerender_then_perspective;
  EngineSettings settings;
  settings.content.kind = ContentKind::kShaded;
  settings.policy = &cadence;
  EngineSettings exact = settings;
  exact.policy = &reuse_policy("rerender");
  PlaneEngine engine(camera, blank_texture(start.texture_size), settings);
  PlaneEngine truth(camera, blank_texture(start.texture_size), exact);
  g_cadence_choices = 0;
  engine.start(frames[0].pose);
  truth.start(frames[0].pose);
  int perspective = 0;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const FrameReport r = engine.advance(frames[k - 1].pose, frames[k - 1].motion, frames[k].pose);
    truth.advance(frames[k - 1].pose, frames[k - 1].motion, frames[k].pose);
    if (r.level != Level::kPerspective) continue;
    ++perspective;
    EXPECT_GT(psnr_db(shown_frame(engine, camera), shown_frame(truth, camera)), 20.0) << k;
  }
  EXPECT_GE(perspective, 6);
}

// Hand count of the facade (layer_content.h): a window is glass (1 face), four frame bars
// and a sill (5 boxes of 5 faces); a balcony a slab, a rail and five posts (7 boxes); the
// wall is one face. Detail d: (1 + d) storeys of (1 + 2d) bays, balconies on the odd storeys.
TEST(LayerContent, FacadeFacesMatchAHandCount) {
  const auto expected = [](int d) {
    const int storeys = 1 + d, bays = 1 + 2 * d, balcony_storeys = storeys / 2;
    return 1 + storeys * bays * (1 + 5 * 5) + balcony_storeys * bays * (7 * 5);
  };
  EXPECT_EQ(facade_faces(Vec2(4.0, 3.0), 1).size(), 262u);  // 1 + 6 * 26 + 3 * 35
  for (int d : {1, 2, 3, 4}) {
    const std::vector<FacadeFace> faces = facade_faces(Vec2(10.0, 8.0), d);
    EXPECT_EQ(faces.size(), static_cast<std::size_t>(expected(d))) << d;
    EXPECT_EQ(faces.capacity(), faces.size()) << d;  // reserved whole, never grown
  }
}

// Every face is a planar quadrilateral with its unit normal across its edges, stands on or
// in front of the wall and lies within the plane's rectangle.
TEST(LayerContent, FacadeFacesArePlanarQuadsInFrontOfTheWall) {
  const Vec2 size(10.0, 8.0);
  for (const FacadeFace& f : facade_faces(size, 2)) {
    EXPECT_NEAR(glm::length(f.normal), 1.0, 1e-12);
    const Vec3 edge_normal = glm::cross(f.corners[1] - f.corners[0], f.corners[2] - f.corners[0]);
    EXPECT_NEAR(std::abs(glm::dot(glm::normalize(edge_normal), f.normal)), 1.0, 1e-9);
    for (const Vec3& c : f.corners) {
      EXPECT_NEAR(glm::dot(c - f.corners[0], f.normal), 0.0, 1e-12);
      EXPECT_GE(c.z, 0.0);
      EXPECT_LE(std::abs(c.x), 0.5 * size.x + 1e-9);
      EXPECT_LE(std::abs(c.y), 0.5 * size.y + 1e-9);
    }
  }
}

// The bond laid out by hand: joints at multiples of 0.07 down and of 0.2 across (shifted by
// half a brick on odd rows), bevels sloping towards the nearest joint.
TEST(LayerContent, BrickHasMortarAtTheJointsAndBevelsSlopingTowardsThem) {
  const ContentMaterial mortar = brick_at(0.0, 0.0).material;
  EXPECT_EQ(brick_at(0.2, 0.035).material.albedo, mortar.albedo);  // vertical joint, row 0
  EXPECT_EQ(brick_at(0.1, 0.07).material.albedo, mortar.albedo);   // horizontal joint
  EXPECT_EQ(brick_at(0.3, 0.105).material.albedo, mortar.albedo);  // row 1: joint at 0.3
  EXPECT_NE(brick_at(0.2, 0.105).material.albedo, mortar.albedo);  // row 1: a brick's middle
  const BrickSample middle = brick_at(0.1, 0.035);
  EXPECT_NE(middle.material.albedo, mortar.albedo);
  EXPECT_EQ(middle.slope, Vec2(0.0));
  EXPECT_GT(brick_at(0.015, 0.035).slope.x, 0.0);  // left edge of a brick
  EXPECT_LT(brick_at(0.185, 0.035).slope.x, 0.0);  // right edge
  EXPECT_GT(brick_at(0.1, 0.015).slope.y, 0.0);    // top edge
  EXPECT_LT(brick_at(0.1, 0.055).slope.y, 0.0);    // bottom edge
}

TEST(LayerContent, KindsListEveryNameOnce) {
  const std::vector<ContentKind> kinds = content_kinds();
  ASSERT_EQ(kinds.size(), 3u);
  std::string joined;
  for (ContentKind k : kinds) {
    ContentKind parsed = ContentKind::kTexture;
    EXPECT_TRUE(parse_content(content_name(k), &parsed));
    EXPECT_EQ(parsed, k);
    joined += (joined.empty() ? "" : ", ") + std::string(content_name(k));
  }
  EXPECT_EQ(joined, content_name_list());
}

// The specular factor against the power in long double (an independent computation): by
// squarings for the materials' shininesses 8 to 64 within (2^k - 1) 2^-53 relative, and
// std::pow's value for a shininess that is not a power of two (the control: 12 and 2.5).
TEST(LayerContent, SpecularPowerIsThePowerWithinItsRoundingBound) {
  for (double shininess : {1.0, 2.0, 8.0, 16.0, 32.0, 64.0, 256.0}) {
    const double bound = (shininess - 1.0) * std::ldexp(1.0, -53) * 1.0001;
    for (int k = 0; k <= 1000; ++k) {
      const double c = k / 1000.0;
      const long double exact = std::pow(static_cast<long double>(c), shininess);
      const double got = specular_power(c, shininess);
      EXPECT_LE(std::abs(static_cast<long double>(got) - exact), bound * exact + 1e-300L)
          << "c " << c << ", shininess " << shininess;
    }
  }
  for (double shininess : {12.0, 2.5, 512.0}) {
    for (double c : {0.0, 0.3, 0.9, 1.0}) {
      EXPECT_EQ(specular_power(c, shininess), std::pow(c, shininess)) << shininess;
    }
  }
}

// Shaded content samples quality times the layer's pixels a re-render, the other kinds
// none; a plane engine whose camera-sized layer would take more than the limit is refused
// when it is made, and the largest quality within it is accepted (the control).
TEST(LayerContent, ShadedSamplesAreQualityTimesPixelsAndTheLimitRefusesAnEngine) {
  LayerContent shaded;
  shaded.kind = ContentKind::kShaded;
  shaded.quality = 7;
  EXPECT_DOUBLE_EQ(shaded_samples(shaded, 1000.0), 7000.0);
  LayerContent impostor = shaded;
  impostor.kind = ContentKind::kImpostor;
  EXPECT_DOUBLE_EQ(shaded_samples(impostor, 1000.0), 0.0);
  EXPECT_DOUBLE_EQ(shaded_samples(LayerContent{}, 1000.0), 0.0);
  // 8192 x 8192 px: quality 2 is exactly 2^27 samples, the limit; quality 3 is over it.
  const Camera camera = make_camera(8000.0, 8192, 8192);
  EngineSettings settings;
  settings.content = shaded;
  settings.content.quality = 2;
  EXPECT_EQ(plane_shaded_samples_problem(settings.content, camera), "");
  EXPECT_NO_THROW(PlaneEngine(camera, make_layer(Image(4, 4)), settings));
  settings.content.quality = 3;
  try {
    PlaneEngine engine(camera, make_layer(Image(4, 4)), settings);
    FAIL() << "quality 3 at 8192 x 8192 px was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "content: shaded content at quality 3 on a 8192 x 8192 px camera may take "
                 "201326592 shaded samples a frame, more than 134217728 (the shaded samples "
                 "limit)");
  }
}

}  // namespace
}  // namespace oflab
