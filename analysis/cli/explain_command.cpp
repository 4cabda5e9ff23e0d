// `oflab-cli explain`: the planes and motions that make a given planar flow (the eight
// coefficients of `flow`), with the degenerate case if any (core/flow/inverse_flow.h).
#include <ostream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "cli/explain_report.h"

namespace oflab {

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_explain_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  std::map<std::string, int> options = explain_options();
  options.insert({"--json", 0});
  const CliArgs a(args, options);
  const nlohmann::json j = explain_report(a);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_explain_text(j, out);
  }
  return 0;
}

}  // namespace oflab
