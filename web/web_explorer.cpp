#include "web_explorer.h"

#include <nlohmann/json.hpp>

#include "basis/basis_catalog.h"
#include "basis/basis_explorer.h"
#include "flow/flow_field.h"
#include "web_session.h"

namespace oflab {
namespace {

using json = nlohmann::json;

json xy(const Vec2& p) { return json::array({p.x, p.y}); }
json xyz(const Vec3& p) { return json::array({p.x, p.y, p.z}); }

json terms_json(const ExplorerTerms& values) {
  json out = json::array();
  for (int k = 0; k < kExplorerTermCount; ++k) {
    const ExplorerTerm& t = explorer_terms()[size_t(k)];
    out.push_back({{"key", t.key},
                   {"description", t.description},
                   {"unit", order_unit(t.order)},
                   {"value", values[size_t(k)]},
                   {"span", t.slider_span},
                   {"decimals", t.decimals},
                   {"minimum", t.limit->minimum},
                   {"maximum", t.limit->maximum}});
  }
  return out;
}

json sketch_json(const PlanarMotionSolution& s, double arrow) {
  if (!s.normal_known) return nullptr;
  const SolutionSketch k = explorer_sketch(s, arrow);
  json corners = json::array();
  for (const Vec2& c : k.corners) corners.push_back(xy(c));
  return {{"corners", corners},
          {"centre", xy(k.centre)},
          {"normal_tip", xy(k.normal_tip)},
          {"velocity_tip", xy(k.velocity_tip)},
          {"spin_tip", xy(k.spin_tip)}};
}

json solutions_json(const InverseFlowSolutions& inverse) {
  const double arrow = explorer_arrow_scale(inverse.solutions);
  json out = json::array();
  for (const PlanarMotionSolution& s : inverse.solutions) {
    out.push_back({{"normal", xyz(s.normal)},
                   {"normal_known", s.normal_known},
                   {"v_over_d", xyz(s.v_over_d)},
                   {"omega", xyz(s.omega)},
                   {"depth_over_d", s.depth_over_d},
                   {"facing", explorer_facing_text(s)},
                   {"sketch", sketch_json(s, arrow)}});
  }
  return out;
}

// Where the homography h carries the centred pixel p, false when p passes behind the eye
// (the homogeneous weight is not positive).
bool carried(const Mat3& h, const Vec2& p, Vec2* out) {
  const Vec3 q = h * Vec3(p.x, p.y, 1.0);
  if (!(q.z > 1e-12)) return false;
  *out = Vec2(q.x / q.z, q.y / q.z);
  return true;
}

json deformation_json(const ExplorerTerms& terms, const ExplorerResult& r, const Camera& camera) {
  const Mat3 h = explorer_deformation(terms);
  json rect = json::array(), quad = json::array(), grid = json::array();
  bool behind = false;
  for (const Vec2& c : r.corners) {
    Vec2 q;
    behind = behind || !carried(h, c, &q);
    rect.push_back(xy(c));
    quad.push_back(xy(q));
  }
  // A homography keeps straight lines straight: each grid line is its two carried ends.
  constexpr int kCells = 8;
  const Vec2 a = r.corners[0], b = r.corners[2];
  for (int i = 0; i <= kCells && !behind; ++i) {
    const double u = double(i) / kCells;
    const Vec2 ends[2][2] = {{Vec2(a.x + u * (b.x - a.x), a.y), Vec2(a.x + u * (b.x - a.x), b.y)},
                             {Vec2(a.x, a.y + u * (b.y - a.y)), Vec2(b.x, a.y + u * (b.y - a.y))}};
    for (const auto& line : ends) {
      Vec2 p, q;
      behind = !carried(h, line[0], &p) || !carried(h, line[1], &q);
      grid.push_back({p.x, p.y, q.x, q.y});
    }
  }
  if (behind) quad = grid = json::array();
  const GridChange change = explorer_grid_change(terms, camera);
  return {{"seconds", kDeformationSeconds},
          {"rect", rect},
          {"quad", quad},
          {"grid", grid},
          {"behind_eye", behind},
          {"change",
           {{"shift_px", change.shift_px},
            {"area", change.area},
            {"turn_deg", change.turn_deg},
            {"keystone", change.keystone}}}};
}

json futures_json(const ExplorerResult& r) {
  json corners = json::array();
  for (const auto& frame : r.futures.corner_images_px) {
    json both = json::array();
    for (const auto& solution : frame) {
      json four = json::array();
      for (const Vec2& c : solution) four.push_back(xy(c));
      both.push_back(four);
    }
    corners.push_back(both);
  }
  return {{"played", r.futures_played},
          {"note", r.futures_note},
          {"frames", r.futures.frames_played},
          {"frame_seconds", kFutureFrameSeconds},
          {"first_frame_apart", r.futures.first_frame_apart},
          {"threshold_px", kFuturesApartPx},
          {"distance_px", r.futures.corner_distance_px},
          {"corners", corners}};
}

}  // namespace

std::string explorer_json(const WebSession& session) {
  const ExplorerTerms& terms = session.values().explorer_terms;
  const Camera camera = session.scene().camera;
  const ExplorerResult r = explore(terms, camera);
  const PlanarFlowCoefficients& c = r.coefficients;
  json out;
  out["camera"] = {
      {"width", camera.width}, {"height", camera.height}, {"focal_px", camera.focal_px}};
  out["terms"] = terms_json(terms);
  out["coefficients"] = {{"tx", c.tx},   {"ty", c.ty},   {"j11", c.j11}, {"j12", c.j12},
                         {"j21", c.j21}, {"j22", c.j22}, {"px", c.px},   {"py", c.py}};
  out["case"] = explorer_case_text(r.inverse);
  out["dropped_behind"] = r.inverse.dropped_behind;
  out["edge_on"] = r.inverse.edge_on;
  out["solutions"] = solutions_json(r.inverse);
  out["deformation"] = deformation_json(terms, r, camera);
  out["futures"] = futures_json(r);
  // The scene's own flow dialled in (the desktop's "From the scene").
  out["from_scene"] = nullptr;
  if (session.scene_problem().empty()) {
    const PlaneScene s = session.scene();
    const ExplorerTerms from =
        explorer_terms_of(planar_flow_coefficients(s.camera, s.pose, s.motion));
    out["from_scene"] = std::vector<double>(from.begin(), from.end());
  }
  return out.dump();
}

}  // namespace oflab
