// `oflab-cli lesson`: the lessons without a window, through the teaching layer.
//   lesson list                        every lesson: name, order, steps, claims, title
//   lesson state NAME|FILE [--step K]  the state step K shows (0: the narrative), as JSON,
//                                      with its frame, played by the one lesson player
//   lesson check NAME|FILE|all         every engine claim of every part measured on a
//                                      headless lab: one line per claim (says, measured,
//                                      holds); exit 1 when one is false
//   lesson fields [--json|--markdown]  the window state's field table
//   lesson kinds [--markdown]          the claim kinds
// A lesson file that cannot be used is refused at read time (exit 2) naming the file, the
// claim and the field. The desktop's `oflab --check-lesson` adds the screen's claims.
#pragma once

#include <iosfwd>

#include "cli/commands.h"

namespace oflab {

// The command's entry for oflab-cli's table (cli/commands.h add_command).
Command lesson_command();

int run_lesson_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

}  // namespace oflab
