// BSP tree of a static polygon scene (dissertation section 5.5.1): construction with
// polygon splitting, and the back-to-front traversal for any eye position.
#include "scene/bsp_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace oflab {
namespace {

enum class Side { kFront, kBack, kCoplanar, kStraddle };

constexpr int kMaxCandidates = 24;
constexpr int kSplitPenalty = 8;  // one split costs as much as this much imbalance

Side classify(const BspFragment& f, const Vec3& normal, double offset, double eps) {
  bool front = false, back = false;
  for (const Vec3& v : f.vertices) {
    const double d = glm::dot(normal, v) - offset;
    if (d > eps) front = true;
    if (d < -eps) back = true;
  }
  if (front && back) return Side::kStraddle;
  if (front) return Side::kFront;
  if (back) return Side::kBack;
  return Side::kCoplanar;
}

// Splits a straddling fragment by the plane; vertices within eps of it go to both halves.
void split(const BspFragment& f, const Vec3& normal, double offset, double eps, BspFragment& front,
           BspFragment& back) {
  front = BspFragment{f.polygon, {}, {}, false};
  back = BspFragment{f.polygon, {}, {}, false};
  const std::size_t n = f.vertices.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = (k + 1) % n;
    const double dk = glm::dot(normal, f.vertices[k]) - offset;
    const double dj = glm::dot(normal, f.vertices[j]) - offset;
    if (dk >= -eps) {
      front.vertices.push_back(f.vertices[k]);
      front.uv.push_back(f.uv[k]);
    }
    if (dk <= eps) {
      back.vertices.push_back(f.vertices[k]);
      back.uv.push_back(f.uv[k]);
    }
    if ((dk > eps && dj < -eps) || (dk < -eps && dj > eps)) {
      const double t = dk / (dk - dj);
      const Vec3 p = f.vertices[k] + t * (f.vertices[j] - f.vertices[k]);
      const Vec2 uv = f.uv[k] + t * (f.uv[j] - f.uv[k]);
      front.vertices.push_back(p);
      front.uv.push_back(uv);
      back.vertices.push_back(p);
      back.uv.push_back(uv);
    }
  }
}

}  // namespace

BspTree::BspTree(const std::vector<ScenePolygon>& polygons, int max_fragments,
                 std::int64_t max_vertices)
    : max_fragments_(max_fragments), max_vertices_(max_vertices) {
  double scale = 1.0;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    BspFragment f;
    f.polygon = static_cast<int>(i);
    f.uv = polygon_outline(polygons[i]);
    f.vertices = polygon_vertices(polygons[i]);
    for (const Vec3& v : f.vertices) {
      scale = std::max({scale, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    }
    vertices_ += static_cast<std::int64_t>(f.vertices.size());
    fragments_.push_back(std::move(f));
    planes_.push_back({polygons[i].front, glm::dot(polygons[i].front, polygons[i].centre)});
  }
  if (vertices_ > max_vertices_) fail_vertex_limit();
  epsilon_ = 1e-9 * scale;
  std::vector<int> ids(fragments_.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
  if (!ids.empty()) root_ = build(std::move(ids), 1);
  stats_.nodes = static_cast<int>(nodes_.size());
  stats_.fragments = static_cast<int>(fragments_.size());
  stats_.vertices = vertices_;
}

void BspTree::fail_vertex_limit() const {
  throw std::invalid_argument("the scene's " + std::to_string(planes_.size()) +
                              " polygons need BSP fragments of more than " +
                              std::to_string(max_vertices_) +
                              " vertices in all (the limit): polygons with many vertices, or "
                              "polygons that intersect each other");
}

void BspTree::fail_fragment_limit() const {
  throw std::invalid_argument(
      "the scene's " + std::to_string(planes_.size()) + " polygons cut each other into more than " +
      std::to_string(max_fragments_) +
      " BSP fragments (the limit): polygons that intersect each other split without end");
}

int BspTree::choose_splitter(const std::vector<int>& ids) const {
  // Candidates spread evenly over the list, so large scenes stay O(n) per node.
  const std::size_t n = ids.size();
  const std::size_t candidates = std::min<std::size_t>(n, kMaxCandidates);
  int best = ids[0];
  long best_score = -1;
  for (std::size_t c = 0; c < candidates; ++c) {
    const int candidate = ids[c * n / candidates];
    const Plane& plane = planes_[fragments_[candidate].polygon];
    long front = 0, back = 0, splits = 0;
    for (int id : ids) {
      switch (classify(fragments_[id], plane.normal, plane.offset, epsilon_)) {
        case Side::kFront:
          ++front;
          break;
        case Side::kBack:
          ++back;
          break;
        case Side::kStraddle:
          ++splits;
          break;
        case Side::kCoplanar:
          break;
      }
    }
    const long score = kSplitPenalty * splits + std::labs(front - back);
    if (best_score < 0 || score < best_score) {
      best_score = score;
      best = candidate;
    }
  }
  return best;
}

int BspTree::build(std::vector<int> ids, int depth) {
  stats_.depth = std::max(stats_.depth, depth);
  const int splitter = choose_splitter(ids);
  Node node;
  // Every fragment lies in its polygon's plane, so the plane comes from the polygon and
  // stays exact however thin a fragment gets.
  node.normal = planes_[fragments_[splitter].polygon].normal;
  node.offset = planes_[fragments_[splitter].polygon].offset;
  std::vector<int> front_ids, back_ids;
  for (int id : ids) {
    const Side side = classify(fragments_[id], node.normal, node.offset, epsilon_);
    if (id == splitter || side == Side::kCoplanar) {
      node.coplanar.push_back(id);
    } else if (side == Side::kFront) {
      front_ids.push_back(id);
    } else if (side == Side::kBack) {
      back_ids.push_back(id);
    } else {
      if (fragments_.size() >= size_t(max_fragments_)) fail_fragment_limit();
      // A cut adds at most four vertices: the two where the plane crosses the outline, in
      // both halves.
      if (vertices_ + 4 > max_vertices_) fail_vertex_limit();
      BspFragment f, b;
      split(fragments_[id], node.normal, node.offset, epsilon_, f, b);
      vertices_ += static_cast<std::int64_t>(f.vertices.size() + b.vertices.size()) -
                   static_cast<std::int64_t>(fragments_[id].vertices.size());
      ++stats_.splits;
      // The original slot keeps the front half; the back half is a new fragment.
      fragments_[id] = std::move(f);
      fragments_.push_back(std::move(b));
      front_ids.push_back(id);
      back_ids.push_back(static_cast<int>(fragments_.size()) - 1);
    }
  }
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(std::move(node));
  if (!front_ids.empty()) {
    const int child = build(std::move(front_ids), depth + 1);
    nodes_[index].front = child;
  }
  if (!back_ids.empty()) {
    const int child = build(std::move(back_ids), depth + 1);
    nodes_[index].back = child;
  }
  return index;
}

void BspTree::traverse(int index, const Vec3& eye, std::vector<int>& order) const {
  if (index < 0) return;
  const Node& node = nodes_[index];
  // Whatever lies on the far side of the plane cannot hide anything on the eye's side or in
  // the plane, so it is painted first.
  const bool eye_in_front = glm::dot(node.normal, eye) - node.offset >= 0.0;
  traverse(eye_in_front ? node.back : node.front, eye, order);
  order.insert(order.end(), node.coplanar.begin(), node.coplanar.end());
  traverse(eye_in_front ? node.front : node.back, eye, order);
}

void BspTree::back_to_front(const Vec3& eye, std::vector<int>& order) const {
  order.clear();
  order.reserve(fragments_.size());
  traverse(root_, eye, order);
}

}  // namespace oflab
