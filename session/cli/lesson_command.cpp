#include "cli/lesson_command.h"

#include <iomanip>
#include <ostream>

#include "cli/cli_args.h"
#include "lessons/claim_kinds.h"
#include "lessons/lesson_player.h"
#include "player/engine_claims.h"
#include "player/lab.h"
#include "state/state_fields.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

constexpr const char* kUsage =
    "oflab-cli lesson list | state NAME|FILE [--step K] | check NAME|FILE|all | "
    "fields [--json|--markdown] | kinds [--markdown]";

// The lesson `name_or_file` names; UsageError (exit 2) naming it when it cannot be used.
const Lesson& lesson_argument(const std::string& name_or_file) {
  try {
    return find_or_read_lesson(name_or_file);
  } catch (const SessionError& e) {
    throw UsageError(e.what());
  }
}

// The action's argument after the action: args[1], which must be there and not an option.
std::string operand(const CommandArgs& args, const char* what) {
  if (args.size() < 2 || args[1].rfind("--", 0) == 0) {
    throw UsageError(std::string("lesson ") + args[0] + ": give " + what);
  }
  return args[1];
}

CommandArgs options_after(const CommandArgs& args, size_t first) {
  return CommandArgs(args.begin() + long(std::min(first, args.size())), args.end());
}

int list(std::ostream& out) {
  for (const Lesson& lesson : lessons()) {
    int claims = int(lesson.claims.size());
    for (const LessonStep& step : lesson.steps) claims += int(step.claims.size());
    out << std::left << std::setw(28) << lesson.name << " order " << std::setw(3) << lesson.order
        << " steps " << std::setw(2) << lesson.steps.size() << " claims " << std::setw(3) << claims
        << " " << lesson.title << "\n";
  }
  return 0;
}

int state(const CommandArgs& args, std::ostream& out) {
  const Lesson& lesson = lesson_argument(operand(args, "a lesson's name or file"));
  const CliArgs a(options_after(args, 2), {{"--step", 1}});
  const int step = a.integer_or("--step", 0);
  if (step < 0 || step > int(lesson.steps.size())) {
    throw UsageError("--step: " + std::to_string(step) + " is not a step of " + lesson.name +
                     " (0 .. " + std::to_string(lesson.steps.size()) + ")");
  }
  Lab lab(shipped_default_texture());
  LabStage stage(&lab);
  const std::string problem = go_to_lesson_step(stage, lesson, step);
  if (!problem.empty()) throw UsageError(problem);
  const WindowState shown = lab.state();
  const nlohmann::json j = {{"lesson", lesson.name},
                            {"step", step},
                            {"frame", shown.frame},
                            {"state", window_state_object(shown)}};
  out << j.dump(2) << "\n";
  return 0;
}

int check(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  const std::string name = operand(args, "a lesson's name or file, or all");
  CliArgs(options_after(args, 2), {});
  std::vector<const Lesson*> chosen;
  if (name == "all") {
    for (const Lesson& lesson : lessons()) chosen.push_back(&lesson);
  } else {
    chosen.push_back(&lesson_argument(name));
  }
  int claims = 0, false_claims = 0, screen = 0;
  for (const Lesson* lesson : chosen) {
    try {
      for (const ClaimCheck& c : check_engine_claims(*lesson, &screen)) {
        out << describe(*lesson, c) << "\n";
        ++claims;
        false_claims += !c.holds;
      }
    } catch (const std::runtime_error& e) {
      err << "oflab-cli lesson check: " << e.what() << "\n";
      ++false_claims;
    }
  }
  out << "oflab-cli lesson check: " << claims << " engine claims of " << chosen.size()
      << " lessons: " << (false_claims == 0 ? "all hold" : std::to_string(false_claims) + " false")
      << " (" << screen << " screen claims are checked by oflab --check-lesson)\n";
  return false_claims == 0 ? 0 : 1;
}

int fields(const CommandArgs& args, std::ostream& out) {
  const CliArgs a(options_after(args, 1), {{"--json", 0}, {"--markdown", 0}});
  if (a.has("--markdown")) {
    out << state_fields_markdown();
  } else if (a.has("--json")) {
    out << state_schema().dump(2) << "\n";
  } else {
    for (const StateField& field : state_fields()) {
      out << std::left << std::setw(36) << field.path << " " << field.type << "; " << field.range
          << "\n";
    }
  }
  return 0;
}

int kinds(const CommandArgs& args, std::ostream& out) {
  const CliArgs a(options_after(args, 1), {{"--markdown", 0}});
  if (a.has("--markdown")) {
    out << claim_kinds_markdown();
    return 0;
  }
  for (const ClaimKind& kind : claim_kinds()) {
    out << std::left << std::setw(22) << kind.name << " "
        << (kind.source == ClaimSource::kEngine ? "engine" : "screen") << "  " << kind.measures
        << "\n";
  }
  return 0;
}

}  // namespace

Command lesson_command() {
  return {"lesson", "the lessons headless: list, the state of a step, engine claims, tables",
          kUsage, run_lesson_command};
}

int run_lesson_command(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) throw UsageError(std::string("give an action: ") + kUsage);
  const std::string& action = args[0];
  if (action == "list") {
    CliArgs(options_after(args, 1), {});
    return list(out);
  }
  if (action == "state") return state(args, out);
  if (action == "check") return check(args, out, err);
  if (action == "fields") return fields(args, out);
  if (action == "kinds") return kinds(args, out);
  throw UsageError("unknown action '" + action + "' (list, state, check, fields, kinds)");
}

}  // namespace oflab
