#include "cli/cli_args.h"

#include <cmath>
#include <cstdlib>

namespace oflab {

CliArgs::CliArgs(const std::vector<std::string>& args, const std::map<std::string, int>& arity) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& name = args[i];
    const auto it = arity.find(name);
    if (it == arity.end()) {
      throw UsageError(name.rfind("--", 0) == 0 ? "unknown option " + name
                                                : "unexpected argument '" + name + "'");
    }
    if (values_.count(name)) throw UsageError(name + ": given more than once");
    std::vector<std::string> vals;
    for (int k = 0; k < it->second; ++k) {
      if (i + 1 >= args.size() || (args[i + 1].rfind("--", 0) == 0 && arity.count(args[i + 1]))) {
        throw UsageError(name + ": expects " + std::to_string(it->second) + " value" +
                         (it->second > 1 ? "s" : "") + ", got " + std::to_string(k));
      }
      vals.push_back(args[++i]);
    }
    values_[name] = vals;
  }
}

bool CliArgs::has(const std::string& name) const { return values_.count(name) > 0; }

const std::vector<std::string>& CliArgs::values(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw UsageError(name + ": required");
  return it->second;
}

double CliArgs::parse_number(const std::string& name, const std::string& text) const {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const bool read_whole = !text.empty() && end == text.c_str() + text.size();
  // strtod also reads hexadecimal ("0x10" as 16): a number on the command line is decimal.
  if (read_whole && text.find_first_of("xX") != std::string::npos) {
    throw UsageError(name + ": '" + text + "' is not a decimal number");
  }
  // A value too large for a double reads as infinity; one too small for a normal double
  // (1e-310) reads as the nearest subnormal or 0, which is finite and kept (the option's
  // Limit then judges it).
  if (!read_whole || !std::isfinite(v)) {
    throw UsageError(name + ": '" + text + "' is not a finite number");
  }
  return v;
}

double CliArgs::number(const std::string& name) const {
  return parse_number(name, values(name).at(0));
}

double CliArgs::number_or(const std::string& name, double fallback) const {
  return has(name) ? number(name) : fallback;
}

std::optional<double> CliArgs::optional_number(const std::string& name) const {
  if (!has(name)) return std::nullopt;
  return number(name);
}

int CliArgs::integer(const std::string& name) const {
  const double v = number(name);
  if (v != std::floor(v)) {
    throw UsageError(name + ": '" + values(name).at(0) + "' is not a whole number");
  }
  if (std::abs(v) > 1e9) {
    throw UsageError(name + ": '" + values(name).at(0) + "' is larger than 1e9 in magnitude");
  }
  return static_cast<int>(v);
}

int CliArgs::integer_or(const std::string& name, int fallback) const {
  return has(name) ? integer(name) : fallback;
}

double CliArgs::coordinate(const std::string& name, const std::string& text) const {
  const double v = parse_number(name, text);
  if (std::abs(v) > kMaxCoordinate) {
    throw UsageError(name + ": '" + text + "' is larger than 1e6 in magnitude (the limit)");
  }
  return v;
}

Vec2 CliArgs::vec2(const std::string& name) const {
  const auto& v = values(name);
  return Vec2(coordinate(name, v.at(0)), coordinate(name, v.at(1)));
}

Vec3 CliArgs::vec3(const std::string& name) const {
  const auto& v = values(name);
  return Vec3(coordinate(name, v.at(0)), coordinate(name, v.at(1)), coordinate(name, v.at(2)));
}

std::string CliArgs::text_or(const std::string& name, const std::string& fallback) const {
  return has(name) ? values(name).at(0) : fallback;
}

std::vector<double> CliArgs::numbers_in(const std::string& name, const Limit& limit) const {
  std::vector<double> numbers;
  for (const std::string& text : values(name)) {
    const double v = parse_number(name, text);
    if (!limit.allows(v)) throw UsageError(name + ": " + limit.problem(v));
    numbers.push_back(v);
  }
  return numbers;
}

double CliArgs::number_in(const std::string& name, const Limit& limit) const {
  return numbers_in(name, limit).at(0);
}

int CliArgs::integer_in(const std::string& name, const Limit& limit) const {
  return static_cast<int>(number_in(name, limit));
}

Vec2 CliArgs::vec2_in(const std::string& name, const Limit& limit) const {
  const std::vector<double> v = numbers_in(name, limit);
  return Vec2(v.at(0), v.at(1));
}

Vec3 CliArgs::vec3_in(const std::string& name, const Limit& limit) const {
  const std::vector<double> v = numbers_in(name, limit);
  return Vec3(v.at(0), v.at(1), v.at(2));
}

std::shared_ptr<AtomicDir> open_out_dir(const std::string& dir, bool force, const char* option) {
  return std::make_shared<AtomicDir>(dir, check_out_dir(option, dir, force));
}

Overwrite check_out_dir(const char* option, const std::string& dir, bool force) {
  const Overwrite overwrite = force ? Overwrite::kReplace : Overwrite::kRefuse;
  try {
    check_output_dir(dir, overwrite);
  } catch (const FileWriteError& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
  return overwrite;
}

Overwrite check_out_file(const char* option, const std::string& path, bool force) {
  const Overwrite overwrite = force ? Overwrite::kReplace : Overwrite::kRefuse;
  try {
    check_output_file(path, overwrite);
  } catch (const FileWriteError& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
  return overwrite;
}

}  // namespace oflab
