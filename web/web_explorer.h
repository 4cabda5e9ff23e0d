// The basis explorer on the page (manual/web.md): the eight planar terms of the page's state
// (basis.terms), what they do forwards and what core makes of them backwards, as JSON for
// web/explorer_view.js. Every number comes from session/basis/basis_explorer.h, the code the
// desktop's explorer shows; the page only draws.
//
// Frames and units as the explorer's: centred pixels (Y down) about the principal point of
// the state's camera, seconds; rates per second.
#pragma once

#include <string>

namespace oflab {

class WebSession;

// The explorer of `session`'s state, computed now:
// {"camera": {"width", "height", "focal_px"},
//  "terms": [{"key", "description", "unit", "value", "span" (the slider's half range),
//             "decimals", "minimum", "maximum"}] in the gallery's order,
//  "coefficients": {"tx", "ty", "j11", "j12", "j21", "j22", "px", "py"} (about the
//                  principal point, px/s, 1/s, 1/(px s)),
//  "case": explorer_case_text, "dropped_behind", "edge_on",
//  "solutions": [{"normal", "normal_known", "v_over_d", "omega", "depth_over_d", "facing",
//                 "sketch": null (pure rotation) or explorer_sketch's points {"corners",
//                 "centre", "normal_tip", "velocity_tip", "spin_tip"} with one arrow scale
//                 for both (explorer_arrow_scale)}],
//  "deformation": {"seconds", "rect": the texture rectangle's 4 corners, "quad": where the
//                  flow carries them, "grid": 18 deformed lines of an 8 x 8 grid on it as
//                  [x0, y0, x1, y1], "behind_eye": true when a corner passes behind the eye
//                  (quad and grid then empty), "change": {"shift_px", "area", "turn_deg",
//                  "keystone"}},
//  "futures": {"played", "note", "frames", "first_frame_apart", "threshold_px",
//              "distance_px": [per frame], "corners": [per frame [solution A, B] [4 corners
//              as [x, y]]]},
//  "from_scene": the eight values of the flow of the scene shown (explorer_terms_of), null
//                when the flow views cannot draw it}.
// Throws nothing for states the session reader accepted (their terms are within limits).
std::string explorer_json(const WebSession& session);

}  // namespace oflab
