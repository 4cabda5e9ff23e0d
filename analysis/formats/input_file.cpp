#include "formats/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace oflab {

namespace {

InputFile problem(InputProblem p, int error = 0) {
  InputFile file;
  file.problem = p;
  if (error) file.reason = std::strerror(error);
  return file;
}

InputFile kind_problem(mode_t mode) {
  return problem(S_ISDIR(mode) ? InputProblem::kDirectory : InputProblem::kNotRegular);
}

}  // namespace

InputFile read_input_file(const std::string& path, std::int64_t max_bytes) {
  struct stat st;
  // Looked at before it is opened: opening a FIFO waits for a writer, a device may act.
  if (::stat(path.c_str(), &st) != 0) return problem(InputProblem::kCannotOpen, errno);
  if (!S_ISREG(st.st_mode)) return kind_problem(st.st_mode);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return problem(InputProblem::kCannotOpen, errno);
  InputFile file;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {  // replaced in between
    file = kind_problem(st.st_mode);
  } else if (st.st_size > max_bytes) {
    file = problem(InputProblem::kTooLarge);
  } else {
    file.bytes.resize(static_cast<std::size_t>(st.st_size));
    std::size_t size = 0;
    for (;;) {
      if (size == file.bytes.size()) {  // room for more than the file claimed, up to the limit
        if (static_cast<std::int64_t>(size) > max_bytes) {
          file = problem(InputProblem::kTooLarge);
          break;
        }
        file.bytes.resize(size + 65536);
      }
      const ssize_t n = ::read(fd, file.bytes.data() + size, file.bytes.size() - size);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        file = problem(InputProblem::kReadError, errno);
        break;
      }
      if (n == 0) {
        if (static_cast<std::int64_t>(size) > max_bytes) {
          file = problem(InputProblem::kTooLarge);
        } else {
          file.bytes.resize(size);
        }
        break;
      }
      size += static_cast<std::size_t>(n);
    }
  }
  ::close(fd);
  return file;
}

std::string input_problem_text(const InputFile& file) {
  switch (file.problem) {
    case InputProblem::kCannotOpen:
      return "cannot open the file (" + file.reason + ")";
    case InputProblem::kDirectory:
      return "is a directory";
    case InputProblem::kNotRegular:
      return "is not a regular file (a FIFO, device or socket)";
    case InputProblem::kReadError:
      return "cannot read the file (" + file.reason + ")";
    case InputProblem::kTooLarge:
    case InputProblem::kNone:
      break;
  }
  return "";
}

}  // namespace oflab
