// The claim kinds of lessons as one registry: each kind once, with its name, what it measures
// (and in what unit), which of a claim's fields it needs and what they may name, and whether
// the engine or a screen measures it. The lesson reader (lessons/lessons.h) refuses an
// unknown kind or a bad field at read time through this table; the measures come from the
// front-ends' tables keyed by these names (the desktop's: gui/app/lesson_check.h), and a
// test holds every front-end's table to this one. Plain C++.
//
// Adding a kind: one entry in claim_kinds() (session/lessons/claim_kinds.cpp) and its
// measure in each front-end that checks it.
#pragma once

#include <string>
#include <vector>

namespace oflab {

struct LessonClaim;

// Who measures a kind: the run of the state (the engine, its compared runs, the plane's flow,
// the explorer), or the pixels a front-end draws.
enum class ClaimSource { kEngine, kScreen };

struct ClaimKind {
  std::string name;  // the claim's "claim": "level_share"
  // What it measures and its unit, one or two sentences (for the manual and --help).
  std::string measures;
  ClaimSource source = ClaimSource::kEngine;
  // Which of the claim's "of", "over" and "level" it needs; the others must be absent.
  bool needs_of = false;
  bool needs_over = false;
  bool needs_level = false;
  // "" when `value` may be the claim's "of" ("over" when `over` is true), else what it may
  // be ("one of tx, ty, ..."); null when any text is allowed (checked where it is measured).
  std::string (*check_of)(const std::string& value) = nullptr;
  // A rate of the machine (frames per second): measured only when a check is asked to time
  // (`oflab --check-lesson ... --time-claims`), and left out of other checks, so that a busy
  // machine cannot make a lesson's check fail; the test suite checks such a claim's reading
  // and measure, and `oflab --benchmark` measures the rate itself.
  bool timed = false;
};

// Every kind, in the manual's order.
const std::vector<ClaimKind>& claim_kinds();

// The kind with this name, or nullptr.
const ClaimKind* find_claim_kind(const std::string& name);

// The names of every kind, in order.
std::vector<std::string> claim_kind_names();

// The registry as the Markdown table of manual/lessons.md: "| kind | fields | measured by |
// what it measures |", one row per kind, which a test compares with the page.
std::string claim_kinds_markdown();

// "" when `claim` is a claim of a known kind with exactly the fields that kind needs, each
// naming something the kind measures, and a range that can hold (at_least <= at_most);
// otherwise "FIELD: problem", FIELD the claim's field at fault ("claim", "of", "over",
// "level", "at_least").
std::string claim_problem(const LessonClaim& claim);

}  // namespace oflab
