// The hierarchical image cache's nodes, quad and angular metric (Shade et al. 96); the
// bound behind the safety sphere is derived in core/scene/cache_nodes.h.
#include "scene/cache_nodes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace oflab {
namespace {

void collect_fragments(const BspTree& tree, int node, std::vector<int>& out) {
  if (node < 0) return;
  const BspNode& n = tree.nodes()[node];
  collect_fragments(tree, n.back, out);
  out.insert(out.end(), n.coplanar.begin(), n.coplanar.end());
  collect_fragments(tree, n.front, out);
}

CacheNode make_node(const BspTree& tree, std::vector<int> fragments, bool cluster) {
  CacheNode node;
  node.cluster = cluster;
  std::set<int> polygons;
  bool first = true;
  for (int f : fragments) {
    const BspFragment& fragment = tree.fragments()[f];
    polygons.insert(fragment.polygon);
    for (const Vec3& v : fragment.vertices) {
      node.box_min = first ? v : glm::min(node.box_min, v);
      node.box_max = first ? v : glm::max(node.box_max, v);
      first = false;
    }
  }
  node.fragments = std::move(fragments);
  node.polygons.assign(polygons.begin(), polygons.end());
  return node;
}

int distinct_polygons(const BspTree& tree, const std::vector<int>& fragments) {
  std::set<int> polygons;
  for (int f : fragments) polygons.insert(tree.fragments()[f].polygon);
  return static_cast<int>(polygons.size());
}

void group(const BspTree& tree, int node, int max_polygons, std::vector<CacheNode>& out) {
  if (node < 0) return;
  std::vector<int> all;
  collect_fragments(tree, node, all);
  if (distinct_polygons(tree, all) <= max_polygons) {
    out.push_back(make_node(tree, std::move(all), true));
    return;
  }
  const BspNode& n = tree.nodes()[node];
  group(tree, n.back, max_polygons, out);
  out.push_back(make_node(tree, n.coplanar, false));
  group(tree, n.front, max_polygons, out);
}

}  // namespace

std::array<Vec3, 8> CacheNode::corners() const {
  std::array<Vec3, 8> c;
  for (int k = 0; k < 8; ++k) {
    c[k] = Vec3(k & 1 ? box_max.x : box_min.x, k & 2 ? box_max.y : box_min.y,
                k & 4 ? box_max.z : box_min.z);
  }
  return c;
}

std::vector<CacheNode> group_cache_nodes(const BspTree& tree, int max_polygons) {
  std::vector<CacheNode> nodes;
  group(tree, tree.root(), std::max(1, max_polygons), nodes);
  return nodes;
}

CacheQuad cache_quad(const Vec3& eye, const Vec3& centre) {
  return {eye, centre, glm::normalize(centre - eye)};
}

double quad_depth(const CacheQuad& quad, const Vec3& p) {
  return glm::dot(p - quad.eye, quad.normal);
}

Vec3 point_on_quad(const CacheQuad& quad, const Vec3& p) {
  // The ray eye + s (p - eye) meets the plane where its depth equals the centre's.
  const double s = quad_depth(quad, quad.centre) / quad_depth(quad, p);
  return quad.eye + s * (p - quad.eye);
}

double angular_error(const Vec3& eye, const Vec3& p, const Vec3& shown) {
  const Vec3 u = p - eye;
  const Vec3 v = shown - eye;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

double node_angular_error(const CacheQuad& quad, const std::array<Vec3, 8>& corners,
                          const Vec3& eye) {
  double largest = 0.0;
  for (const Vec3& p : corners) {
    largest = std::max(largest, angular_error(eye, p, point_on_quad(quad, p)));
  }
  return largest;
}

double angle_in_pixels(const Camera& camera, const Vec3& p, double angle) {
  const double phi = std::atan2(std::hypot(p.x, p.y), p.z);
  constexpr double kRightAngle = 1.57079632679489661923;
  if (phi + angle >= kRightAngle) return std::numeric_limits<double>::infinity();
  return camera.focal_px * (std::tan(phi + angle) - std::tan(phi));
}

double safety_radius(const CacheQuad& quad, const std::array<Vec3, 8>& corners, double threshold) {
  const double t = std::tan(threshold);
  double radius = -1.0;
  for (const Vec3& p : corners) {
    if (quad_depth(quad, p) <= 0.0) return 0.0;
    const double a = glm::length(point_on_quad(quad, p) - quad.eye);
    const double b = glm::length(p - quad.eye);
    const double d = std::abs(b - a);
    const double q = t * (a + b) + d;
    // The smaller root, written so that it does not cancel when d is small.
    const double discriminant = std::max(0.0, q * q - 4.0 * t * t * a * b);
    const double r = 2.0 * t * a * b / (q + std::sqrt(discriminant));
    radius = radius < 0.0 ? r : std::min(radius, r);
  }
  return std::max(0.0, radius);
}

CacheRenderCause cache_render_cause(const CacheQuad& quad, const std::array<Vec3, 8>& corners,
                                    double radius, const Vec3& eye, double threshold) {
  if (node_angular_error(quad, corners, eye) > threshold) return CacheRenderCause::kAngle;
  if (glm::length(eye - quad.eye) > radius) return CacheRenderCause::kSphere;
  return CacheRenderCause::kNone;
}

}  // namespace oflab
