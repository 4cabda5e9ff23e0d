// A small command-line reader for oflab-cli subcommands: named options with a fixed
// number of values, errors that name the argument, and nothing positional.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/geometry.h"
#include "flow/limits.h"
#include "formats/atomic_file.h"

namespace oflab {

// Thrown for bad command-line input; what() is one line that names the argument.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CliArgs {
 public:
  // Declares the options a command accepts: name (with the leading "--") -> number of
  // values (0 for a flag). Parsing fails on an unknown option, a missing value, or a repeat.
  CliArgs(const std::vector<std::string>& args, const std::map<std::string, int>& arity);

  bool has(const std::string& name) const;
  // The values of an option as strings; throws UsageError when absent.
  const std::vector<std::string>& values(const std::string& name) const;

  // Numeric readers: throw UsageError naming the option when absent (required forms) or
  // when a value is not a finite decimal number / not an integer ("0x10" is refused; a
  // subnormal such as 1e-310 is a finite number).
  double number(const std::string& name) const;
  double number_or(const std::string& name, double fallback) const;
  std::optional<double> optional_number(const std::string& name) const;
  int integer(const std::string& name) const;
  int integer_or(const std::string& name, int fallback) const;
  // Vectors (positions, directions, sizes): each value also at most kMaxCoordinate in
  // magnitude, as in oflab's data files.
  static constexpr double kMaxCoordinate = 1e6;
  Vec2 vec2(const std::string& name) const;
  Vec3 vec3(const std::string& name) const;
  std::string text_or(const std::string& name, const std::string& fallback) const;

  // The values of option `name` (required) checked against `limit` (core/flow/limits.h,
  // the one rule for each kind of value): throws UsageError naming the option, the value and
  // the range, "--threshold: 1e+06 is outside 0..100 px", or "--focal: 'x' is not a finite
  // number" for text that is not a number. number_in reads the first value; integer_in
  // needs a whole-number limit whose range fits an int; vec2_in and vec3_in check each
  // component.
  std::vector<double> numbers_in(const std::string& name, const Limit& limit) const;
  double number_in(const std::string& name, const Limit& limit) const;
  int integer_in(const std::string& name, const Limit& limit) const;
  Vec2 vec2_in(const std::string& name, const Limit& limit) const;
  Vec3 vec3_in(const std::string& name, const Limit& limit) const;

 private:
  double parse_number(const std::string& name, const std::string& text) const;
  double coordinate(const std::string& name, const std::string& text) const;
  std::map<std::string, std::vector<std::string>> values_;
};

// The output directory of --out DIR (or of `option`), written whole
// (formats/atomic_file.h): checked at once (a non-empty DIR needs `force`, which then
// replaces it whole when the run succeeds; nothing but a directory may be there), then a
// temporary directory beside DIR receives the outputs (AtomicDir::path) until
// AtomicDir::commit renames it into place. Throws UsageError naming the option for a
// refusal known up front, FileWriteError when the temporary cannot be created.
std::shared_ptr<AtomicDir> open_out_dir(const std::string& dir, bool force,
                                        const char* option = "--out");
// The check of open_out_dir alone, creating nothing: how DIR may be written. Throws
// UsageError naming the option.
Overwrite check_out_dir(const char* option, const std::string& dir, bool force);

// The file of an output option (`option`: "--out", "--video", ...) checked before any work:
// refused when it exists without `force`, or is a directory, device or FIFO. Returns how it
// may be written. Throws UsageError naming the option.
Overwrite check_out_file(const char* option, const std::string& path, bool force);

}  // namespace oflab
