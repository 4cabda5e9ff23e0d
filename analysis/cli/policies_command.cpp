// `oflab-cli policies`: the engine's reuse policies (core/engine/reuse_policy.h), the values
// of `oflab-cli animate --mode`, one per line as "name  summary", or as JSON:
//   {"policies": [{"name": ..., "summary": ...}, ...]} in registry order.
#include <algorithm>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "engine/reuse_policy.h"

namespace oflab {
namespace {

nlohmann::ordered_json policies_json() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ReusePolicy& p : reuse_policies()) {
    nlohmann::ordered_json entry;
    entry["name"] = p.name;
    entry["summary"] = p.summary;
    list.push_back(entry);
  }
  nlohmann::ordered_json report;
  report["policies"] = list;
  return report;
}

void print_text(std::ostream& stream) {
  std::size_t width = 0;
  for (const ReusePolicy& p : reuse_policies()) width = std::max(width, std::string(p.name).size());
  std::ostringstream out;  // keeps the caller's stream formatting untouched
  for (const ReusePolicy& p : reuse_policies()) {
    out << std::left << std::setw(static_cast<int>(width)) << p.name << "  " << p.summary << "\n";
  }
  stream << out.str();
}

}  // namespace

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_policies_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  const CliArgs a(args, {{"--json", 0}});
  if (a.has("--json")) {
    out << policies_json().dump(2) << "\n";
  } else {
    print_text(out);
  }
  return 0;
}

}  // namespace oflab
