// The hierarchical image cache's nodes and angular metric (core/scene/cache_nodes.h) against
// independent computations: the angle by acos of the normalised dot product, the cached point
// by solving the ray-plane system as a 3 x 3 linear system, a hand-made case in closed form,
// and the safety sphere's promise checked on random eyes inside it, with negative controls.
#include "scene/cache_nodes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "scene/hierarchical_cache.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::random_polygons;
using testing::scene_with;
using testing::square;

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The angle at `eye` between the rays to a and b, by acos (long double).
double acos_angle(const Vec3& eye, const Vec3& a, const Vec3& b) {
  const glm::tvec3<long double> u(a.x - eye.x, a.y - eye.y, a.z - eye.z);
  const glm::tvec3<long double> v(b.x - eye.x, b.y - eye.y, b.z - eye.z);
  long double c =
      (u.x * v.x + u.y * v.y + u.z * v.z) /
      std::sqrt((u.x * u.x + u.y * u.y + u.z * u.z) * (v.x * v.x + v.y * v.y + v.z * v.z));
  c = std::max(-1.0L, std::min(1.0L, c));
  return static_cast<double>(std::acos(c));
}

// Where the ray from quad.eye through p meets the quad's plane, by solving
// eye + s (p - eye) = centre + alpha u + beta v for (s, alpha, beta).
Vec3 solved_point_on_quad(const CacheQuad& quad, const Vec3& p) {
  const Vec3 helper = std::abs(quad.normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 u = glm::normalize(glm::cross(quad.normal, helper));
  const Vec3 v = glm::cross(quad.normal, u);
  const Mat3 system(p - quad.eye, -u, -v);  // columns
  const Vec3 x = glm::inverse(system) * (quad.centre - quad.eye);
  return quad.eye + x.x * (p - quad.eye);
}

CacheNode box_node(const Vec3& lo, const Vec3& hi) {
  CacheNode node;
  node.box_min = lo;
  node.box_max = hi;
  return node;
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(Vec3(g(rng), g(rng), g(rng)));
}

TEST(CacheNodes, AngularErrorEqualsTheAcosOfTheNormalisedDotProduct) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  for (int k = 0; k < 500; ++k) {
    const Vec3 eye(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 a(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 b = a + 0.01 * coordinate(rng) * random_unit(rng);
    EXPECT_NEAR(angular_error(eye, a, b), acos_angle(eye, a, b), 1e-7);
  }
}

TEST(CacheNodes, NodeErrorMatchesTheSolvedQuadPointsOnHandMadeNodes) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Vec3 lo(-1.0 - unit(rng), -1.0 - unit(rng), 8.0 + 4.0 * unit(rng));
    const CacheNode node =
        box_node(lo, lo + Vec3(1.0 + unit(rng), 0.5 + unit(rng), 3.0 * unit(rng)));
    const CacheQuad quad = cache_quad(Vec3(0.0), node.centre());
    const Vec3 eye = 0.8 * unit(rng) * random_unit(rng);
    double expected = 0.0;
    for (const Vec3& c : node.corners()) {
      expected = std::max(expected, acos_angle(eye, c, solved_point_on_quad(quad, c)));
    }
    EXPECT_NEAR(node_angular_error(quad, node.corners(), eye), expected, 1e-7);
  }
}

TEST(CacheNodes, HandMadeCornerBehindTheQuadHasTheClosedFormAngle) {
  // The quad at depth 10 facing the eye at the origin; a corner at depth 20 on the axis is
  // cached at depth 10. An eye moved sideways by 1 sees the two under atan(1/10) - atan(1/20).
  const CacheQuad quad = cache_quad(Vec3(0.0), Vec3(0, 0, 10));
  const Vec3 p(0, 0, 20);
  EXPECT_NEAR(glm::length(point_on_quad(quad, p) - Vec3(0, 0, 10)), 0.0, 1e-12);
  EXPECT_NEAR(angular_error(Vec3(1, 0, 0), p, point_on_quad(quad, p)),
              std::atan(0.1) - std::atan(0.05), 1e-12);
  // A point on the quad is cached where it is: no error from anywhere.
  const Vec3 on(2, -1, 10);
  EXPECT_NEAR(angular_error(Vec3(0.5, 0.3, -2), on, point_on_quad(quad, on)), 0.0, 1e-12);
}

TEST(CacheNodes, NoEyeInsideTheSafetySphereExceedsTheThreshold) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int outside_exceeding = 0;
  for (int k = 0; k < 100; ++k) {
    const Vec3 lo(4.0 * unit(rng) - 2.0, 4.0 * unit(rng) - 2.0, 3.0 + 10.0 * unit(rng));
    const CacheNode node =
        box_node(lo, lo + Vec3(0.2 + unit(rng), 0.2 + unit(rng), 2.0 * unit(rng)));
    const Vec3 e0(0.3 * unit(rng), 0.3 * unit(rng), 0.0);
    const CacheQuad quad = cache_quad(e0, node.centre());
    const double threshold = (0.05 + unit(rng)) * kDegree;
    const double radius = safety_radius(quad, node.corners(), threshold);
    ASSERT_GT(radius, 0.0);
    for (int j = 0; j < 50; ++j) {
      // Inside the sphere (up to its surface): never over the threshold, and the sphere
      // rule never fires.
      const Vec3 inside = e0 + radius * std::cbrt(unit(rng)) * random_unit(rng);
      EXPECT_LE(node_angular_error(quad, node.corners(), inside), threshold * (1.0 + 1e-9));
      EXPECT_EQ(cache_render_cause(quad, node.corners(), radius, inside, threshold),
                CacheRenderCause::kNone);
    }
    // Negative control: far enough outside, some eye does exceed it (the metric can fire).
    for (int j = 0; j < 50; ++j) {
      const Vec3 outside = e0 + 20.0 * radius * random_unit(rng);
      outside_exceeding += node_angular_error(quad, node.corners(), outside) > threshold;
    }
  }
  EXPECT_GT(outside_exceeding, 100);
}

TEST(CacheNodes, TheSphereRuleFiresOutsideItsRadiusEvenWithTheAngleWithin) {
  const CacheNode node = box_node(Vec3(-1, -1, 9), Vec3(1, 1, 11));
  const CacheQuad quad = cache_quad(Vec3(0.0), node.centre());
  const double threshold = 0.5 * kDegree;
  const double radius = safety_radius(quad, node.corners(), threshold);
  const Vec3 eye(0.5 * radius, 0.0, 0.0);  // inside the automatic sphere: angle within
  ASSERT_LE(node_angular_error(quad, node.corners(), eye), threshold);
  EXPECT_EQ(cache_render_cause(quad, node.corners(), radius, eye, threshold),
            CacheRenderCause::kNone);
  // A smaller sphere, given: the same eye is outside it, and that alone re-renders.
  EXPECT_EQ(cache_render_cause(quad, node.corners(), 0.25 * radius, eye, threshold),
            CacheRenderCause::kSphere);
  // A larger sphere, given: an eye inside it but over the angle re-renders by the angle.
  const Vec3 far_eye(0.0, 3.0, 0.0);
  ASSERT_GT(node_angular_error(quad, node.corners(), far_eye), threshold);
  EXPECT_EQ(cache_render_cause(quad, node.corners(), 100.0, far_eye, threshold),
            CacheRenderCause::kAngle);
}

TEST(CacheNodes, GroupingPutsEveryFragmentInOneNodeWithinThePolygonRule) {
  std::mt19937 rng(5);
  const std::vector<ScenePolygon> polygons = random_polygons(rng, 60);
  const BspTree tree(polygons);
  for (int rule : {1, 4, 12}) {
    const std::vector<CacheNode> nodes = group_cache_nodes(tree, rule);
    std::vector<int> node_of(tree.fragments().size(), -1);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (nodes[k].cluster) {
        EXPECT_LE(int(nodes[k].polygons.size()), rule);
      }
      for (int f : nodes[k].fragments) {
        EXPECT_EQ(node_of[f], -1) << "fragment " << f << " in two nodes";
        node_of[f] = int(k);
        for (const Vec3& v : tree.fragments()[f].vertices) {
          EXPECT_TRUE(glm::all(glm::lessThanEqual(nodes[k].box_min, v)) &&
                      glm::all(glm::lessThanEqual(v, nodes[k].box_max)));
        }
      }
    }
    for (int n : node_of) EXPECT_GE(n, 0);
    // Every back-to-front order paints a node's fragments one after the other.
    for (int e = 0; e < 5; ++e) {
      std::vector<int> order;
      tree.back_to_front(12.0 * random_unit(rng), order);
      std::set<int> finished;
      for (std::size_t i = 0; i < order.size(); ++i) {
        const int n = node_of[order[i]];
        EXPECT_EQ(finished.count(n), 0u) << "node " << n << " painted in two runs";
        if (i + 1 == order.size() || node_of[order[i + 1]] != n) finished.insert(n);
      }
    }
  }
  // Control: a rule as large as the scene makes one cluster.
  EXPECT_EQ(group_cache_nodes(tree, 1000).size(), 1u);
  EXPECT_GT(group_cache_nodes(tree, 4).size(), 10u);
}

TEST(HierarchicalCacheEngine, AStillViewerReusesEveryNodeAndShowsTheSameFrame) {
  const Scene scene =
      scene_with({square("far", Vec3(0, 0, -2), Vec3(0, 0, 1), Vec3(0, 1, 0), 2.0),
                  square("near", Vec3(0.3, 0.1, 0.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 0.6)});
  const Camera camera = make_camera(300.0, 160, 120);
  const BspTree tree(scene.polygons);
  CacheSettings settings;
  settings.max_node_polygons = 1;
  HierarchicalCache cache(scene, camera, tree, settings, CacheContext{});
  ASSERT_EQ(cache.nodes().size(), 2u);
  const ViewerPose view = look_at(Vec3(0.2, 0.3, 4.0), Vec3(0, 0, -1), Vec3(0, 1, 0));
  const std::vector<char> culled(2, 0);
  std::vector<Level> levels(2);
  Image first(camera.width, camera.height), second(camera.width, camera.height);
  AnimationFrame a, b;
  cache.frame(view, culled, first, levels, a);
  EXPECT_EQ(a.cache.rendered, 2);
  cache.frame(view, culled, second, levels, b);
  EXPECT_EQ(b.cache.rendered, 0);
  EXPECT_EQ(b.levels[static_cast<int>(Level::kPerspective)], 2);
  EXPECT_EQ(testing::mismatch_fraction(first, second, 0), 0.0);
  EXPECT_NEAR(b.max_measured_error_px, 0.0, 1e-9);
  EXPECT_EQ(b.hole_pixels, 0);
  // Moved far beyond the safety sphere, every node is rendered again by the sphere or angle.
  AnimationFrame c;
  cache.frame(look_at(Vec3(1.5, 0.3, 4.0), Vec3(0, 0, -1), Vec3(0, 1, 0)), culled, second, levels,
              c);
  EXPECT_EQ(c.cache.rendered, 2);
  EXPECT_EQ(c.cache.by_angle + c.cache.by_sphere, 2);
}

TEST(HierarchicalCacheEngine, SettingsOutsideTheirLimitsAreRefusedByName) {
  CacheSettings s;
  s.angle_deg = 0.0;
  EXPECT_NE(cache_settings_problem(s).find("cache angle"), std::string::npos);
  s = CacheSettings{};
  s.max_node_polygons = 0;
  EXPECT_NE(cache_settings_problem(s).find("node polygons"), std::string::npos);
  s = CacheSettings{};
  s.safety_radius = -1.0;
  EXPECT_NE(cache_settings_problem(s).find("safety radius"), std::string::npos);
  EXPECT_EQ(cache_settings_problem(CacheSettings{}), "");
}

}  // namespace
}  // namespace oflab
