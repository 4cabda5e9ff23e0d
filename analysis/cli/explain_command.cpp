// `oflab-cli explain`: the planes and motions that make a given planar flow (the eight
// coefficients of `flow`), with the degenerate case if any (core/flow/inverse_flow.h).
#include <ostream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "cli/explain_report.h"

namespace oflab {

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_explain_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  const CliArgs a(args, {{"--coefficients", 8}, {"--focal", 1}, {"--at", 2}, {"--json", 0}});
  const std::vector<double> k = a.numbers_in("--coefficients", limits::kFlowCoefficient);
  const double focal = a.number_in("--focal", limits::kFocalLength);
  const Vec2 at = a.has("--at") ? a.vec2("--at") : Vec2(0.0, 0.0);
  PlanarFlowCoefficients c;
  c.tx = k[0];
  c.ty = k[1];
  c.j11 = k[2];
  c.j12 = k[3];
  c.j21 = k[4];
  c.j22 = k[5];
  c.px = k[6];
  c.py = k[7];
  const nlohmann::json j = explain_json(solve_inverse_flow(c, focal, at), at);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_explain_text(j, out);
  }
  return 0;
}

}  // namespace oflab
