// The BSP tree's order is checked by brute force: along rays from the eye through sample
// points of every pair of fragments, the one drawn later must never be the farther one.
#include "scene/bsp_tree.h"

#include <gtest/gtest.h>

#include <random>

#include "image/polygon.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::open_cube;
using testing::random_polygons;
using testing::square;

// Points spread over a convex fragment: vertices pulled slightly inwards, edge midpoints,
// the centroid and random convex combinations.
std::vector<Vec3> sample_points(const BspFragment& f, std::mt19937& rng) {
  std::vector<Vec3> out;
  Vec3 centroid(0.0);
  for (const Vec3& v : f.vertices) centroid += v;
  centroid /= static_cast<double>(f.vertices.size());
  out.push_back(centroid);
  for (std::size_t k = 0; k < f.vertices.size(); ++k) {
    const Vec3& a = f.vertices[k];
    const Vec3& b = f.vertices[(k + 1) % f.vertices.size()];
    out.push_back(centroid + 0.98 * (a - centroid));
    out.push_back(centroid + 0.98 * (0.5 * (a + b) - centroid));
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 12; ++i) {
    Vec3 p(0.0);
    double total = 0.0;
    for (const Vec3& v : f.vertices) {
      const double w = u(rng);
      p += w * v;
      total += w;
    }
    out.push_back(p / total);
  }
  return out;
}

// Where the ray from `eye` through `target` meets fragment f: the ray parameter t (target
// at t = 1), or a negative value when it misses.
double ray_hit(const BspFragment& f, const Vec3& eye, const Vec3& target) {
  const Vec3 n = glm::cross(f.vertices[1] - f.vertices[0], f.vertices[2] - f.vertices[0]);
  const Vec3 d = target - eye;
  const double denom = glm::dot(n, d);
  if (std::abs(denom) < 1e-12) return -1.0;
  const double t = glm::dot(n, f.vertices[0] - eye) / denom;
  if (t <= 0.0) return -1.0;
  const Vec3 p = eye + t * d;
  // Inside the convex fragment: same side of every edge (either orientation).
  int positive = 0, negative = 0;
  for (std::size_t k = 0; k < f.vertices.size(); ++k) {
    const Vec3& a = f.vertices[k];
    const Vec3& b = f.vertices[(k + 1) % f.vertices.size()];
    const double s = glm::dot(glm::cross(b - a, p - a), n);
    if (s > 1e-12) ++positive;
    if (s < -1e-12) ++negative;
  }
  return positive > 0 && negative > 0 ? -1.0 : t;
}

// Counts pairs drawn in the wrong order: fragment `later` (painted after `earlier`) lies
// behind `earlier` along some ray from the eye.
int order_violations(const BspTree& tree, const Vec3& eye, std::mt19937& rng) {
  std::vector<int> order;
  tree.back_to_front(eye, order);
  const auto& fragments = tree.fragments();
  std::vector<std::vector<Vec3>> samples;
  for (const BspFragment& f : fragments) samples.push_back(sample_points(f, rng));
  int violations = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const BspFragment& earlier = fragments[order[i]];
      const BspFragment& later = fragments[order[j]];
      if (earlier.polygon == later.polygon) continue;
      bool bad = false;
      for (const Vec3& p : samples[order[j]]) {  // rays through the later fragment
        const double t = ray_hit(earlier, eye, p);
        if (t > 0.0 && t < 1.0 - 1e-9) bad = true;  // the earlier one is nearer
      }
      for (const Vec3& p : samples[order[i]]) {  // rays through the earlier fragment
        const double t = ray_hit(later, eye, p);
        if (t > 1.0 + 1e-9) bad = true;  // the later one is farther
      }
      violations += bad;
    }
  }
  return violations;
}

TEST(BspTree, OrderIsBackToFrontForRandomPolygonsAndEyes) {
  std::mt19937 rng(20240501);
  int total_splits = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const std::vector<ScenePolygon> polygons = random_polygons(rng, 14);
    const BspTree tree(polygons);
    total_splits += tree.stats().splits;
    EXPECT_EQ(tree.stats().fragments, static_cast<int>(polygons.size()) + tree.stats().splits);
    std::uniform_real_distribution<double> u(-9.0, 9.0);
    for (int e = 0; e < 8; ++e) {
      const Vec3 eye(u(rng), u(rng), u(rng));
      EXPECT_EQ(order_violations(tree, eye, rng), 0) << "scene " << scene << " eye " << e;
    }
  }
  EXPECT_GT(total_splits, 0) << "the random scenes should exercise splitting";
}

TEST(BspTree, EveryFragmentIsListedOnceForAnyEye) {
  std::mt19937 rng(7);
  const BspTree tree(random_polygons(rng, 20));
  std::vector<int> order;
  tree.back_to_front(Vec3(0.5, -8.0, 3.0), order);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(sorted.size(), tree.fragments().size());
  for (std::size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], static_cast<int>(i));
}

TEST(BspTree, SplitPiecesKeepTheTextureMappingAndTheArea) {
  // Two polygons whose planes cut each other while the polygons stay apart: whichever
  // becomes the splitter, the other is cut in two.
  std::vector<ScenePolygon> polygons = {
      square("a", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 2.0),
      square("b", Vec3(0, 2.5, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 2.0)};
  polygons[1].size = Vec2(2.0, 1.0);  // z in [-1, 1], y in [2, 3]
  const BspTree tree(polygons);
  double area = 0.0;
  for (const BspFragment& f : tree.fragments()) {
    for (std::size_t k = 0; k < f.vertices.size(); ++k) {
      EXPECT_LT(glm::length(polygon_point(polygons[f.polygon], f.uv[k]) - f.vertices[k]), 1e-12);
    }
    if (!f.whole) area += ConvexPolygon::from_vertices(f.uv).area();
  }
  ASSERT_EQ(tree.stats().splits, 1);
  EXPECT_EQ(tree.stats().fragments, 3);
  EXPECT_NEAR(area, 1.0, 1e-12);  // the two pieces cover the unit texture square once
}

TEST(BspTree, CubesGiveAnOrderWithoutSplits) {
  std::vector<ScenePolygon> polygons = open_cube("a", Vec3(-1.5, 0, 0), 1.0);
  for (ScenePolygon& p : open_cube("b", Vec3(1.5, 0, 0), 1.0)) polygons.push_back(p);
  const BspTree tree(polygons);
  EXPECT_EQ(tree.stats().splits, 0);
  EXPECT_LE(tree.stats().nodes, static_cast<int>(polygons.size()));
  std::mt19937 rng(3);
  for (const Vec3& eye : {Vec3(0, 2, 6), Vec3(-5, 0.2, -4), Vec3(0.1, 8, 0.2), Vec3(4, -3, 1)}) {
    EXPECT_EQ(order_violations(tree, eye, rng), 0);
  }
}

TEST(BspTree, EmptySceneGivesAnEmptyOrder) {
  const BspTree tree(std::vector<ScenePolygon>{});
  std::vector<int> order{1, 2};
  tree.back_to_front(Vec3(0.0), order);
  EXPECT_TRUE(order.empty());
}

// Large squares through a small box all intersect each other, so every split makes more:
// the fragment count grows much faster than the polygon count, and the cap stops it.
std::vector<ScenePolygon> intersecting_squares(int count) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<ScenePolygon> out;
  for (int i = 0; i < count; ++i) {
    const Vec3 normal = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3, 0, 0));
    const Vec3 up = glm::cross(normal, std::abs(normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    out.push_back(square("s" + std::to_string(i), Vec3(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)),
                         normal, glm::normalize(up), 4.0));
  }
  return out;
}

// No vertex cap, for the fragment cap's test.
constexpr std::int64_t kAnyVertices = std::int64_t(1) << 40;

TEST(BspTree, IntersectingPolygonsStopAtTheFragmentCapWithAClearMessage) {
  const std::vector<ScenePolygon> polygons = intersecting_squares(60);
  const int unlimited =
      BspTree(polygons, BspTree::kMaxBspFragments, kAnyVertices).stats().fragments;
  EXPECT_GT(unlimited, 600) << "60 intersecting squares should split into many fragments";
  try {
    const BspTree capped(polygons, 300, kAnyVertices);
    ADD_FAILURE() << "no error past the cap";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("more than 300 BSP fragments (the limit)"), std::string::npos) << what;
    EXPECT_NE(what.find("60 polygons"), std::string::npos) << what;
  }
  EXPECT_EQ(BspTree(polygons, unlimited, kAnyVertices).stats().fragments, unlimited);
}

// The vertex count of the tree is the sum over its fragments, counted here independently;
// a split adds at most four (the two where the plane crosses the outline, in both halves).
TEST(BspTree, VertexCountIsTheSumOverFragmentsAndSplitsAddAtMostTwo) {
  const std::vector<ScenePolygon> polygons = intersecting_squares(20);
  const BspTree tree(polygons);
  std::int64_t sum = 0;
  for (const BspFragment& f : tree.fragments()) sum += static_cast<std::int64_t>(f.vertices.size());
  EXPECT_EQ(tree.stats().vertices, sum);
  EXPECT_GT(tree.stats().splits, 0);
  EXPECT_LE(sum, 4 * 20 + 4 * tree.stats().splits);
}

// Intersecting squares stop at the vertex cap before the fragment cap, with the limit named;
// polygons with too many vertices are refused before anything is split; at exactly their
// count the tree is built (the control).
TEST(BspTree, VerticesStopAtTheVertexCapWithAClearMessage) {
  const std::vector<ScenePolygon> polygons = intersecting_squares(60);
  const std::int64_t unlimited =
      BspTree(polygons, BspTree::kMaxBspFragments, kAnyVertices).stats().vertices;
  EXPECT_GT(unlimited, 1000);
  try {
    const BspTree capped(polygons, BspTree::kMaxBspFragments, 1000);
    ADD_FAILURE() << "no error past the vertex cap";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("60 polygons need BSP fragments of more than 1000 vertices in all (the "
                        "limit)"),
              std::string::npos)
        << what;
  }
  EXPECT_THROW(BspTree(polygons, BspTree::kMaxBspFragments, 60 * 4 - 1), std::invalid_argument);
  EXPECT_EQ(BspTree(polygons, BspTree::kMaxBspFragments, unlimited).stats().vertices, unlimited);
}

}  // namespace
}  // namespace oflab
