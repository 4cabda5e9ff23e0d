#include "formats/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

// Systems without Linux's renameat2 (a WebAssembly build's memory file system, web/) get a
// stand-in that supports no flag (ENOSYS), so rename_with takes its portable fallbacks.
#if !defined(RENAME_NOREPLACE)
#define RENAME_NOREPLACE (1u << 0)
#define RENAME_EXCHANGE (1u << 1)
static int renameat2(int, const char*, int, const char*, unsigned) {
  errno = ENOSYS;
  return -1;
}
#endif

namespace oflab {

namespace fs = std::filesystem;

namespace {

// The process's umask, read once (umask can only be read by setting it).
mode_t process_umask() {
  static const mode_t mask = [] {
    const mode_t m = ::umask(022);
    ::umask(m);
    return m;
  }();
  return mask;
}

std::string in_quotes(const std::string& path) { return "'" + path + "'"; }

[[noreturn]] void fail(const std::string& shown, const std::string& what, int error) {
  throw FileWriteError(in_quotes(shown) + ": " + what + " (" + std::strerror(error) + ")");
}

// `path` with a symbolic link as its last part replaced by the path it names, when that
// exists; otherwise `path`.
std::string follow_link(const std::string& path) {
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(path, ec))) return path;
  const fs::path real = fs::canonical(path, ec);
  return ec ? path : real.string();
}

// `path` without trailing slashes ("out/" -> "out"; "/" stays).
std::string without_trailing_slashes(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return path;
}

// The folder that holds `path` ("." for a bare name).
std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// The template of a temporary beside `target`: ".NAME.tmp-XXXXXX", NAME cut to keep the
// file name within the usual 255 bytes; terminated, for mkostemp and mkdtemp to fill in.
std::vector<char> temp_template(const std::string& target) {
  std::string name = fs::path(target).filename().string();
  if (name.size() > 200) name.resize(200);
  const std::string text = (fs::path(folder_of(target)) / ("." + name + ".tmp-XXXXXX")).string();
  std::vector<char> chars(text.begin(), text.end());
  chars.push_back('\0');
  return chars;
}

// Creates the missing folders above `target`. Throws FileWriteError naming `shown`.
void create_folder_of(const std::string& target, const std::string& shown) {
  const std::string folder = folder_of(target);
  std::error_code ec;
  if (fs::is_directory(folder, ec)) return;
  fs::create_directories(folder, ec);
  if (ec) {
    throw FileWriteError(in_quotes(shown) + ": cannot create the folder " + in_quotes(folder) +
                         " (" + ec.message() + ")");
  }
}

// The folder's entry changes (a rename) flushed to the disk; errors are ignored, as some
// file systems do not sync directories.
void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// renameat2 with `flags`; falls back to what the file system supports when it refuses the
// flag (EINVAL): for RENAME_NOREPLACE a hard link and an unlink, then a checked rename.
int rename_with(const std::string& from, const std::string& to, unsigned flags) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), flags) == 0) return 0;
  if (errno != EINVAL && errno != ENOSYS) return -1;
  if (flags == RENAME_NOREPLACE) {
    if (::link(from.c_str(), to.c_str()) == 0) {
      ::unlink(from.c_str());
      return 0;
    }
    if (errno == EEXIST) return -1;
    struct stat st;
    if (::lstat(to.c_str(), &st) == 0) {
      errno = EEXIST;
      return -1;
    }
    return ::rename(from.c_str(), to.c_str());
  }
  errno = EINVAL;
  return -1;
}

// Writes all `size` bytes of `data` to `fd`, retrying short and interrupted writes. Returns 0,
// or the errno of the failure (ENOSPC for a write that wrote nothing).
int write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return 0;
}

// Whether `dir` is the root, the home folder, the current folder or one of its ancestors.
std::string protected_folder_reason(const std::string& dir) {
  std::error_code ec;
  const fs::path real = fs::canonical(dir, ec);
  if (ec) return "";
  if (real == real.root_path()) return "the file system's root";
  if (const char* home = std::getenv("HOME")) {
    const fs::path h = fs::canonical(home, ec);
    if (!ec && h == real) return "the home folder";
  }
  const fs::path cwd = fs::canonical(fs::current_path(ec), ec);
  if (ec) return "";
  const std::string r = real.string() + "/";
  const std::string c = cwd.string() + "/";
  if (c.compare(0, r.size(), r) == 0) return "the current folder or one that holds it";
  return "";
}

}  // namespace

void check_output_file(const std::string& path, Overwrite overwrite) {
  if (path.empty()) throw FileWriteError("'': an empty file name");
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::exists(st)) {
    if (fs::is_directory(st)) throw FileWriteError(in_quotes(path) + " is a directory");
    if (!fs::is_regular_file(st)) {
      throw FileWriteError(in_quotes(path) +
                           " is not a regular file (a device, FIFO or socket is never written)");
    }
    if (overwrite == Overwrite::kRefuse) {
      throw FileWriteError(in_quotes(path) + " exists (add --force to overwrite it)");
    }
  } else if (fs::is_symlink(fs::symlink_status(path, ec)) && overwrite == Overwrite::kRefuse) {
    throw FileWriteError(in_quotes(path) + " exists (add --force to overwrite it)");
  }
  const std::string folder = folder_of(follow_link(path));
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw FileWriteError(in_quotes(path) + ": " + in_quotes(folder) + " is not a directory");
  }
}

AtomicFile::AtomicFile(const std::string& target, Overwrite overwrite)
    : target_(follow_link(target)), shown_(target), overwrite_(overwrite) {
  check_output_file(target, overwrite);
  std::vector<char> name = temp_template(target_);
  fd_ = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd_ < 0) fail(shown_, "cannot write a file in " + in_quotes(folder_of(target_)), errno);
  temp_ = name.data();
  if (::fchmod(fd_, 0666 & ~process_umask()) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    ::unlink(temp_.c_str());
    fail(shown_, "cannot set the file's mode", error);
  }
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
}

void AtomicFile::write(const void* data, std::size_t size) {
  if (fd_ < 0) throw FileWriteError(in_quotes(shown_) + ": written after it was completed");
  if (const int error = write_all(fd_, data, size)) fail(shown_, "cannot write the file", error);
}

void AtomicFile::commit() {
  if (committed_) return;
  try {
    if (fd_ < 0) throw FileWriteError(in_quotes(shown_) + ": the file is incomplete");
    if (::fsync(fd_) != 0) fail(shown_, "cannot write the file to the disk", errno);
    const int closed = ::close(fd_);
    fd_ = -1;
    if (closed != 0) fail(shown_, "cannot close the file", errno);
    if (overwrite_ == Overwrite::kReplace) {
      if (::rename(temp_.c_str(), target_.c_str()) != 0) {
        fail(shown_, "cannot replace the file", errno);
      }
    } else if (rename_with(temp_, target_, RENAME_NOREPLACE) != 0) {
      if (errno == EEXIST) {
        throw FileWriteError(in_quotes(shown_) +
                             " was created meanwhile, by another run? (not overwritten; add "
                             "--force to overwrite it)");
      }
      fail(shown_, "cannot create the file", errno);
    }
  } catch (const FileWriteError&) {
    ::unlink(temp_.c_str());
    temp_.clear();
    throw;
  }
  committed_ = true;
  sync_folder(folder_of(target_));
}

void write_file_atomically(const std::string& path, const std::string& bytes, Overwrite overwrite) {
  AtomicFile file(path, overwrite);
  file.write(bytes);
  file.commit();
}

void write_file_inside(const std::string& path, const std::string& bytes,
                       const std::string& shown) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(shown, "cannot create the file", errno);
  if (const int error = write_all(fd, bytes.data(), bytes.size())) {
    ::close(fd);
    fail(shown, "cannot write the file", error);
  }
  if (::close(fd) != 0) fail(shown, "cannot close the file", errno);
}

void check_output_dir(const std::string& path, Overwrite overwrite) {
  if (path.empty()) throw FileWriteError("'': an empty directory name");
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) throw FileWriteError(in_quotes(path) + " is not a directory");
    const std::string reason = protected_folder_reason(path);
    if (!reason.empty()) {
      throw FileWriteError(in_quotes(path) + " is " + reason +
                           "; the outputs need a folder of their own");
    }
    if (overwrite == Overwrite::kRefuse && !fs::is_empty(path, ec)) {
      throw FileWriteError(in_quotes(path) + " is not empty (add --force to replace it)");
    }
  }
  const std::string folder = folder_of(without_trailing_slashes(follow_link(path)));
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw FileWriteError(in_quotes(path) + ": " + in_quotes(folder) + " is not a directory");
  }
}

AtomicDir::AtomicDir(const std::string& target, Overwrite overwrite)
    : target_(without_trailing_slashes(follow_link(without_trailing_slashes(target)))),
      shown_(target),
      overwrite_(overwrite) {
  check_output_dir(target, overwrite);
  if (fs::path(target_).filename() == "." || fs::path(target_).filename() == "..") {
    target_ = fs::absolute(target_).lexically_normal().string();
    target_ = without_trailing_slashes(target_);
  }
  create_folder_of(target_, shown_);
  std::vector<char> name = temp_template(target_);
  if (!::mkdtemp(name.data())) {
    fail(shown_, "cannot create a directory in " + in_quotes(folder_of(target_)), errno);
  }
  temp_ = name.data();
  if (::chmod(temp_.c_str(), 0777 & ~process_umask()) != 0) {
    const int error = errno;
    ::rmdir(temp_.c_str());
    temp_.clear();
    fail(shown_, "cannot set the directory's mode", error);
  }
}

AtomicDir::~AtomicDir() {
  if (committed_ || temp_.empty()) return;
  std::error_code ec;
  fs::remove_all(temp_, ec);
}

void AtomicDir::commit() {
  if (committed_) return;
  try {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(temp_, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (!it->is_regular_file(ec)) {
        if (it->is_directory(ec)) sync_folder(it->path().string());
        continue;
      }
      const int fd = ::open(it->path().c_str(), O_RDONLY | O_CLOEXEC);
      if (fd < 0 || ::fsync(fd) != 0) {
        const int error = errno;
        if (fd >= 0) ::close(fd);
        fail(shown_, "cannot write " + in_quotes(it->path().filename().string()) + " to the disk",
             error);
      }
      ::close(fd);
    }
    if (ec) fail(shown_, "cannot list the outputs", ec.value());
    sync_folder(temp_);
    bool placed = rename_with(temp_, target_, RENAME_NOREPLACE) == 0;
    if (!placed && errno == EEXIST) {
      // Something is there: rename replaces an empty directory, and only that.
      placed = ::rename(temp_.c_str(), target_.c_str()) == 0;
      if (!placed && (errno == ENOTEMPTY || errno == EEXIST)) {
        if (overwrite_ == Overwrite::kRefuse) {
          throw FileWriteError(in_quotes(shown_) +
                               " was filled meanwhile, by another run? (not replaced; add "
                               "--force to replace it)");
        }
        if (::renameat2(AT_FDCWD, temp_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
          fail(shown_, "cannot replace the directory", errno);
        }
        committed_ = true;  // the old directory is now at temp_
        fs::remove_all(temp_, ec);
      } else if (!placed) {
        fail(shown_, "cannot replace the directory", errno);
      }
    } else if (!placed) {
      fail(shown_, "cannot create the directory", errno);
    }
  } catch (const FileWriteError&) {
    if (!committed_) {
      std::error_code ec;
      fs::remove_all(temp_, ec);
      temp_.clear();
    }
    throw;
  }
  committed_ = true;
  sync_folder(folder_of(target_));
}

}  // namespace oflab
