#include "lessons/claim_kinds.h"

#include <algorithm>
#include <cstdlib>

#include "basis/basis_catalog.h"
#include "basis/basis_explorer.h"
#include "display/flow_parts.h"
#include "engine/decision.h"
#include "engine/reuse_policy.h"
#include "formats/datasets.h"
#include "lessons/lessons.h"
#include "state/window_state.h"

namespace oflab {
namespace {

std::string one_of(const std::string& value, const std::vector<std::string>& names) {
  if (std::find(names.begin(), names.end(), value) != names.end()) return "";
  return "'" + value + "' is not one of " + joined_names(names);
}

std::string coefficient_name(const std::string& v) {
  return one_of(v, {"tx", "ty", "j11", "j12", "j21", "j22", "px", "py"});
}

std::string flow_part(const std::string& v) {
  FlowPart part;
  return parse_flow_part(v, &part) ? "" : "'" + v + "' is not a flow part";
}

// "engine" or a reuse policy (a compared run).
std::string run_name(const std::string& v) {
  if (v == "engine" || find_reuse_policy(v)) return "";
  return "'" + v + "' is neither engine nor a reuse policy (" + reuse_policy_names() + ")";
}

std::string policy_name(const std::string& v) {
  return find_reuse_policy(v) ? "" : "'" + v + "' is not a reuse policy";
}

std::string term_symbol(const std::string& v) {
  std::vector<std::string> symbols;
  for (const ExplorerTerm& term : explorer_terms()) symbols.push_back(term.key);
  return one_of(v, symbols);
}

std::string grid_field(const std::string& v) {
  double value = 0.0;
  return grid_change_field(GridChange(), v, &value)
             ? ""
             : one_of(v, {"shift_px", "area", "turn_deg", "keystone"});
}

std::string study_name(const std::string& v) { return one_of(v, shipped_names("studies")); }

// A simulated observer's threshold: a number of pixels within 0.01..100.
std::string observer_px(const std::string& v) {
  char* end = nullptr;
  const double px = std::strtod(v.c_str(), &end);
  if (!v.empty() && *end == '\0' && px >= 0.01 && px <= 100.0) return "";
  return "'" + v + "' is not a threshold in pixels from 0.01 to 100";
}

std::string error_end(const std::string& v) { return one_of(v, {"min", "max"}); }

ClaimKind engine(std::string name, std::string measures, bool of = false, bool over = false,
                 bool level = false, std::string (*check)(const std::string&) = nullptr) {
  return {std::move(name), std::move(measures), ClaimSource::kEngine, of, over, level, check};
}

ClaimKind screen(std::string name, std::string measures, bool of = false, bool level = false,
                 std::string (*check)(const std::string&) = nullptr) {
  return {std::move(name), std::move(measures), ClaimSource::kScreen, of, false, level, check};
}

// A screen kind that times the machine (ClaimKind::timed).
ClaimKind timed_screen(std::string name, std::string measures) {
  ClaimKind kind = screen(std::move(name), std::move(measures));
  kind.timed = true;
  return kind;
}

std::vector<ClaimKind> make_kinds() {
  return {
      engine("coefficient",
             "|coefficient `of`| of the plane's flow now (tx ty j11 j12 j21 j22 px py), px/s, "
             "1/s or 1/(px s) as core's planar_flow_coefficients",
             true, false, false, coefficient_name),
      engine("flow_ratio",
             "the largest |flow| of part `of` over that of part `over` on the plane's image", true,
             true, false, flow_part),
      engine("level_share",
             "the share (0..1) of drawn layer-frames at `level` over frames 1 .. now, of the "
             "engine (`of` engine) or of a compared policy (`of` its name)",
             true, false, true, run_name),
      engine("max_error", "the largest measured error (px) over frames 1 .. now, same `of`", true,
             false, false, run_name),
      engine("frame_error", "the measured error (px) of the frame shown now, same `of`", true,
             false, false, run_name),
      engine("photometric_error",
             "the largest photometric error (grey levels, 0..255) of a layer of the frame shown "
             "now, same `of`: shading kept from the layer's last render",
             true, false, false, run_name),
      screen("exact_drawn", "the share (0..1) of the exact panel's pixels the exact frame covers"),
      screen("active_tiles", "tiles of the basis gallery with a non-zero coefficient"),
      screen("heat_map_width",
             "the narrowest heat map of the comparison layout as drawn: the width of what it "
             "shows (the exact outlines' bounding box) on it, in pixels of the 1920 x 1080 "
             "look: screen pixels over presentation mode's scale (0.711 at 1366 x 768, 1 at "
             "1920 x 1080 and in the normal look)"),
      screen("panel_fill",
             "the share (percent) of its panel that what a view in front shows now covers, the "
             "smallest over the views in front: the animation view's exact panel inside the "
             "exact outlines (the plane's or the polygons' images) at the panels' shared "
             "framing and zoom; the flow view's picture inside the plane's image; the world "
             "view's picture between its legend and caption inside the hull of the plane or the "
             "scene, the eye and its image plane; the basis gallery's tile inside its deformed "
             "square (the smallest of the 12 tiles) or, with the explorer, its deformation's "
             "picture under the caption inside the deformed texture rectangle"),
      engine("hole_pixels",
             "the holes of the frame shown now of the engine (`of` engine) or of a compared "
             "policy (`of` its name), pixels",
             true, false, false, run_name),
      screen("hole_map_pixels",
             "the hole pixels marked on the comparison's heat maps as drawn now, pixels"),
      engine("near_far_error",
             "the mean measured error of the nearer half of the layers drawn now over that of "
             "the farther half, of `of` (engine or a compared policy)",
             true, false, false, run_name),
      screen("threshold_crossings",
             "how often the analysis view's budget chart of `level` crosses its dashed "
             "threshold upwards over the frames it charts",
             false, true),
      screen("cut_texts",
             "texts elided, off their canvas or overlapping another, or labels cut short: of "
             "the world view, the basis view's explorer or the analysis view when in front, "
             "else of the animation view"),
      screen("labels_over_content",
             "the world view's labels (shown in front or in the cause-and-effect layout) "
             "that cover the image plane's picture or the textured plane as drawn now (their "
             "projected outlines)"),
      engine("view", "1 when the view in front is `of`, else 0", true),
      engine("run_pixels_ratio",
             "the pixels compared policy `of` has written over frames 0 .. now over those of "
             "compared policy `over`",
             true, true, false, policy_name),
      engine("frame_pixels_p95_ratio",
             "the 95th percentile (nearest rank) of the pixels `of` (engine or a compared "
             "policy) wrote per frame over frames 1 .. now, as `oflab-cli compare`'s "
             "pixels_written_p95, over that of `over`",
             true, true, false, run_name),
      engine("max_error_gap",
             "|the largest measured error (px) over frames 1 .. now of `of` - that of `over`| "
             "(engine or compared policies), px",
             true, true, false, run_name),
      engine("pixels_warped_share",
             "the pixels `of` (engine or a compared policy) has warped over frames 0 .. now "
             "(those its warps computed: a visible-only warp, `animation.warp` visible, leaves "
             "out what the frame does not show) over the pixels it has written (0..1)",
             true, false, false, run_name),
      engine("whole_warp_difference",
             "the pixels, summed over frames 0 .. now, in which the frames of `of` (engine or a "
             "compared policy) differ from those of the same run with every layer warped whole "
             "(`animation.warp` whole), both played from frame 0",
             true, false, false, run_name),
      screen("caption_cut", "1 when the lesson caption's banner is shorter than its text needs"),
      screen("tile_active", "1 when the gallery's tile of term `of` is lit, else 0", true, false,
             term_symbol),
      engine("solution_count", "planes and motions in front of the eye that make the dialled flow"),
      engine("futures_apart_frame",
             "the first frame at which the explorer's two solutions are more than 1 px apart "
             "(-1 when never within the second played)"),
      engine("futures_first_px", "how far apart the two solutions are after one frame, px"),
      timed_screen("frame_rate",
                   "frames per second the window plays the part's state at: the engine advanced "
                   "and the view in front drawn frame by frame for 60 frames, as `oflab "
                   "--benchmark` (timed: only with `--time-claims`)"),
      engine("grid_change",
             "what the explorer's deformation does to the grid in 1 s: `of` shift_px (px), area "
             "(ratio), turn_deg (degrees) or keystone (fraction)",
             true, false, false, grid_field),
      engine("error_over_threshold",
             "the largest measured error over frames 1 .. now of `of` (engine or a compared "
             "policy) over the largest of the four reuse thresholds it plays with",
             true, false, false, run_name),
      engine("study_errors",
             "the smallest (`of` min) or largest (`of` max) error the engine shows in the "
             "study the state opens (`study.open`): its ladders' measured errors over every "
             "condition, px",
             true, false, false, error_end),
      engine("study_recovery",
             "the median threshold fitted to 100 simulated observers of threshold `of` px (the "
             "study's slope and lapse, seeds from the study's) run through the study the state "
             "opens with its method and the engine's shown errors, over `of`: the condition "
             "farthest from 1",
             true, false, false, observer_px),
      screen("study_setup",
             "1 when the study window shows its set-up page with study `of` chosen, else 0", true,
             false, study_name),
      screen("study_results",
             "the conditions for which the study window's results page shows a threshold with "
             "its 95 % interval (0 on its other pages)"),
      screen("study_threshold_gap",
             "the largest difference (px) between the window's four reuse thresholds as their "
             "fields show them and the threshold the study window's results offer (its *Use X "
             "px*, as shown)"),
      engine("sampling_psnr_gain",
             "mipmap sampling's mean PSNR over bilinear's (dB) against an exact render of 16 "
             "samples per pixel, on the reused frames minified more than 1.5x, of the plane "
             "script the state plays with its texture and engine settings: the whole script, "
             "as `oflab-cli experiments --only sampling` measures it, to 0.01 dB"),
  };
}

// "" or "FIELD: problem" for the presence and value of one of the claim's fields.
std::string field_problem(const char* field, const std::string& value, bool needed,
                          std::string (*check)(const std::string&)) {
  if (needed && value.empty()) return std::string(field) + ": this kind needs it";
  if (!needed && !value.empty()) return std::string(field) + ": this kind takes none";
  const std::string problem = needed && check ? check(value) : "";
  return problem.empty() ? "" : std::string(field) + ": " + problem;
}

}  // namespace

const std::vector<ClaimKind>& claim_kinds() {
  static const std::vector<ClaimKind> kinds = make_kinds();
  return kinds;
}

const ClaimKind* find_claim_kind(const std::string& name) {
  for (const ClaimKind& kind : claim_kinds()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

std::vector<std::string> claim_kind_names() {
  std::vector<std::string> names;
  for (const ClaimKind& kind : claim_kinds()) names.push_back(kind.name);
  return names;
}

std::string claim_kinds_markdown() {
  std::string table = "| kind | fields | measured by | what it measures |\n|---|---|---|---|\n";
  for (const ClaimKind& kind : claim_kinds()) {
    std::string fields;
    for (const auto& [needed, name] : {std::pair<bool, const char*>{kind.needs_of, "of"},
                                       {kind.needs_over, "over"},
                                       {kind.needs_level, "level"}}) {
      if (needed) fields += (fields.empty() ? "`" : ", `") + std::string(name) + "`";
    }
    table += "| `" + kind.name + "` | " + (fields.empty() ? "-" : fields) + " | " +
             (kind.source == ClaimSource::kEngine ? "engine"
              : kind.timed                        ? "screen, timed"
                                                  : "screen") +
             " | " + kind.measures + " |\n";
  }
  return table;
}

std::string claim_problem(const LessonClaim& claim) {
  const ClaimKind* kind = find_claim_kind(claim.claim);
  if (!kind)
    return "claim: '" + claim.claim + "' is not one of " + joined_names(claim_kind_names());
  // "over" names the same kind of thing as "of" (a flow part, a policy).
  for (const std::string& problem :
       {field_problem("of", claim.of, kind->needs_of, kind->check_of),
        field_problem("over", claim.over, kind->needs_over, kind->check_of),
        field_problem("level", claim.level, kind->needs_level, nullptr)}) {
    if (!problem.empty()) return problem;
  }
  Level level;
  if (kind->needs_level && !parse_level(claim.level, &level)) {
    return "level: unknown level '" + claim.level + "'";
  }
  if (claim.at_least > claim.at_most) return "at_least: more than at_most, so it can never hold";
  return "";
}

}  // namespace oflab
