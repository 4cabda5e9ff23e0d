// The planes and motions behind a planar flow (core/flow/inverse_flow.h) as the output of
// `oflab-cli explain` and of `oflab-cli flow --explain`: one JSON object and its text form.
#pragma once

#include <iosfwd>
#include <map>
#include <nlohmann/json.hpp>

#include "cli/cli_args.h"
#include "flow/inverse_flow.h"

namespace oflab {

// The JSON object of `explain`: {"solutions": [{"omega": [3], "normal": [3] or null,
// "v_over_d": [3], "v_over_z0": [3] or null, "depth_over_d": number or null,
// "slopes": [dZ/dX, dZ/dY] or null}, ...], "degenerate": case name or null (general case),
// "front_pixel": [x, y], "mirror_candidates_behind_eye": count, "edge_on_at_front_pixel":
// count (candidate planes parallel to the line of sight through front_pixel, left out: see
// InverseFlowSolutions::edge_on), "units": text}.
// Frame: the viewer frame (X right, Y down, Z forward); rates per unit time; normal unit,
// oriented so that d = N.R > 0; v_over_z0 = V/Z0 with Z0 = d/N3 the depth where the plane
// meets the optical axis; slopes -N1/N3, -N2/N3 (null when N3 = 0). `front_pixel` is the
// centred pixel at which every listed plane is in front of the eye (solve_inverse_flow's).
nlohmann::json explain_json(const InverseFlowSolutions& result, const Vec2& front_pixel);

// The object of `oflab-cli explain`'s options (explain_options()): --coefficients tx ty j11
// j12 j21 j22 px py (each within limits::kFlowCoefficient), --focal F (limits::kFocalLength)
// and --at x y (front_pixel; default the principal point). Throws UsageError naming the option.
nlohmann::json explain_report(const CliArgs& args);
// The options explain_report reads, name (with "--") -> number of values.
const std::map<std::string, int>& explain_options();

// The same object as lines of text: the number of solutions and the case, what was left
// out, and for each solution its structure (normal, angle to the optical axis, slopes,
// depth up to scale) and motion (V/d, V/Z0, Omega).
void print_explain_text(const nlohmann::json& j, std::ostream& out);

}  // namespace oflab
