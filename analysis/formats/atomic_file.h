// Outputs written whole or not at all. Every file oflab-cli writes goes first into a temporary
// file (or, for an --out directory, a temporary directory) beside its target, in the same
// folder; every write is checked, the data is flushed to the disk (fsync) and closed, and only
// then is the temporary renamed over the target. A failure at any point removes the temporary
// and leaves what was at the target before untouched; a reader never sees half a file. Two
// runs writing the same target leave the output of the last one to finish, whole. New files
// and directories get the modes the umask gives (0666 and 0777 masked), like any program's.
// Linux (renameat2, fsync).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace oflab {

// A write that failed: what() names the path and the reason, "'out/a.png': cannot write the
// file (No space left on device)".
class FileWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether an existing target may be replaced (the commands' --force).
enum class Overwrite { kRefuse, kReplace };

// Checks, before any work, that the file `path` may be written: it is not a directory, a
// device, a FIFO or a socket (after following links), its folder is not a file, and
// with Overwrite::kRefuse nothing exists at `path`. Throws FileWriteError naming the path and
// the reason ("'x.gif' exists (add --force to overwrite it)"). Creates nothing. A missing
// folder is found when the file is created: "cannot write a file in 'DIR' (No such file or
// directory)".
void check_output_file(const std::string& path, Overwrite overwrite);

// One file written through a temporary beside `target`.
class AtomicFile {
 public:
  // Runs check_output_file and creates the temporary file ".NAME.tmp-XXXXXX" in the target's
  // folder (which must exist) with mode 0666 less the umask. A symbolic
  // link at `target` is followed: the file it names is replaced and the link kept. Throws
  // FileWriteError naming the path.
  AtomicFile(const std::string& target, Overwrite overwrite);
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends `size` bytes; a short write is retried, any error throws FileWriteError naming
  // the target and the reason (errno's text).
  void write(const void* data, std::size_t size);
  void write(const std::string& bytes) { write(bytes.data(), bytes.size()); }

  // Flushes the data to the disk, closes the temporary and renames it over the target
  // (with Overwrite::kRefuse: only if nothing appeared at the target meanwhile). Throws
  // FileWriteError naming the target on any failure; the temporary is then removed and the
  // target unchanged. Calling it again does nothing.
  void commit();

  // The temporary file, for writers that open the file themselves (libavformat): what they
  // write there is flushed and renamed by commit().
  const std::string& temp_path() const { return temp_; }
  // The file that commit() replaces (a link at the target resolved).
  const std::string& target() const { return target_; }

 private:
  std::string target_;
  std::string shown_;  // the target as the caller named it, for messages
  std::string temp_;
  Overwrite overwrite_;
  int fd_ = -1;
  bool committed_ = false;
};

// Writes `bytes` to `path` through an AtomicFile. Throws FileWriteError naming the path.
void write_file_atomically(const std::string& path, const std::string& bytes, Overwrite overwrite);

// Writes `bytes` to `path`, a new file inside an AtomicDir's path(), checking every write and
// the close (the directory's commit flushes it to the disk and makes it appear). Throws
// FileWriteError naming `shown` (the file as the user will find it) and the reason.
void write_file_inside(const std::string& path, const std::string& bytes, const std::string& shown);

// Checks, before any work, that the directory `path` may be written as a whole: nothing but a
// directory is there (after following links), and with Overwrite::kRefuse it is missing or
// empty. With Overwrite::kReplace it must not be the file system's root, the home folder, the
// current folder or one of its ancestors (they are never replaced whole). Throws
// FileWriteError naming the path and the reason, "'out' is not empty (add --force to
// replace it)". Creates nothing.
void check_output_dir(const std::string& path, Overwrite overwrite);

// A directory of outputs (an --out DIR) written whole: the files go into a temporary sibling
// directory, which commit() renames into place. With Overwrite::kReplace an old directory is
// swapped out in one step and then removed, so no file of an earlier run survives beside the
// new ones.
class AtomicDir {
 public:
  // Runs check_output_dir, creates the target's missing parent folders and the temporary
  // directory ".NAME.tmp-XXXXXX" beside it with mode 0777 less the umask. A symbolic link at
  // `target` is followed. Throws FileWriteError naming the path.
  AtomicDir(const std::string& target, Overwrite overwrite);
  // Removes the temporary directory and everything in it unless commit() succeeded.
  ~AtomicDir();
  AtomicDir(const AtomicDir&) = delete;
  AtomicDir& operator=(const AtomicDir&) = delete;

  // Where the outputs are written until commit().
  const std::string& path() const { return temp_; }
  // The directory that commit() creates or replaces.
  const std::string& target() const { return target_; }

  // Flushes every file in the temporary directory to the disk and renames the directory into
  // place: over a missing or empty target; with Overwrite::kReplace also over a non-empty one,
  // which is then removed. Throws FileWriteError naming the target on any failure (for
  // kRefuse: when another run filled the target meanwhile); the temporary directory is then
  // removed and the target unchanged. Calling it again does nothing.
  void commit();

 private:
  std::string target_;
  std::string shown_;
  std::string temp_;
  Overwrite overwrite_;
  bool committed_ = false;
};

}  // namespace oflab
