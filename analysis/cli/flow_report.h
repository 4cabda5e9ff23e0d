// `oflab-cli flow`'s report without its files: the planar flow coefficients of a plane and
// its motion seen by a camera, the planar basis and, with --dt, the Taylor and exact
// homographies and the corner errors of each approximation level; with --explain, the round
// trip of the coefficients back to planes and motions (explain_report.h). `oflab-cli flow`
// prints it (and writes --vtk); the Python module returns it (python/, manual/python.md).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_args.h"
#include "flow/camera.h"
#include "flow/flow_field.h"

namespace oflab {

// The report of the options of flow_options(): --image W H (limits::kImageSize), --focal F
// (limits::kFocalLength), --plane-point, --plane-normal, optionally --plane-up with
// --plane-size (the plane's extent), --velocity and --omega (per unit time), --motion, --dt
// and --explain. `json` is `oflab-cli flow --json`'s object: "units", "motion",
// "coefficients" {tx, ty, j11, j12, j21, j22, px, py}, "basis" {tx, ty, scale, squash,
// shear, rotation, px, py}, with --dt "dt", "homography_taylor" and "homography_exact" (3 x 3
// rows) and, with the extent, "corner_error_px"; with --explain "explain". The coefficients
// are about the principal point, in centred pixels per unit time. Throws UsageError naming
// the option for a bad value (a pose's field by its option, a plane corner behind the camera).
struct FlowReport {
  Camera camera;
  PlanarFlowCoefficients coefficients;
  nlohmann::json json;
};
FlowReport flow_report(const CliArgs& args);

// The options flow_report reads, name (with "--") -> number of values; `oflab-cli flow` adds
// its outputs (--vtk, --vtk-step, --force, --json).
const std::map<std::string, int>& flow_options();

}  // namespace oflab
