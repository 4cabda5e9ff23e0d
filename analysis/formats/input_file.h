// Reading an input file whole, safely: only a regular file (after following links) is opened,
// so a FIFO, a device such as /dev/zero or a directory is refused at once instead of blocking
// or reading without end, and the size is checked while reading (not only the size the file
// claims), so a file that grows while it is read still stops at the limit. Shared by the
// readers of data files (JSON, OBJ) and images.
#pragma once

#include <cstdint>
#include <string>

namespace oflab {

// What went wrong reading an input file; kNone when nothing did.
enum class InputProblem { kNone, kCannotOpen, kDirectory, kNotRegular, kTooLarge, kReadError };

struct InputFile {
  std::string bytes;  // the contents when problem is kNone
  InputProblem problem = InputProblem::kNone;
  std::string reason;  // the system's words for kCannotOpen, kReadError
};

// The contents of the file at `path`, at most `max_bytes` bytes, or the problem: kCannotOpen
// (missing, no permission: `reason` says which), kDirectory, kNotRegular (a FIFO, device or
// socket; never opened for reading), kTooLarge (more than max_bytes, by its size or by what
// was read), kReadError. Never blocks on a FIFO and never throws for these.
InputFile read_input_file(const std::string& path, std::int64_t max_bytes);

// One phrase for a problem, for messages: "cannot open the file (No such file or directory)",
// "is a directory", "is not a regular file (a FIFO, device or socket)", "cannot read the file
// (Input/output error)". kTooLarge and kNone give "" (the readers name their own limits).
std::string input_problem_text(const InputFile& file);

}  // namespace oflab
