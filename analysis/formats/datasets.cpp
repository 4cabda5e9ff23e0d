#include "formats/datasets.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace oflab {

namespace fs = std::filesystem;

std::string installed_datasets_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const fs::path dir = (exe.parent_path() / OFLAB_INSTALL_DATASETS_RELATIVE).lexically_normal();
  return fs::is_directory(dir, ec) ? dir.string() : "";
}

std::string datasets_dir() {
  if (const char* env = std::getenv("OFLAB_DATASETS"); env && *env) return env;
  static const std::string installed = installed_datasets_dir();
  if (!installed.empty()) return installed;
  return OFLAB_SOURCE_DATASETS_DIR;
}

std::vector<std::string> shipped_names(const std::string& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(datasets_dir()) / folder, ec)) {
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

namespace {

// `name_or_file` when it is a file, else datasets/FOLDER/NAME.EXTENSION when that is one,
// else "".
std::string existing_or_shipped_file(const std::string& name_or_file, const std::string& folder,
                                     const std::string& extension) {
  std::error_code ec;
  if (fs::is_regular_file(name_or_file, ec)) return name_or_file;
  const fs::path shipped = fs::path(datasets_dir()) / folder / (name_or_file + extension);
  return fs::is_regular_file(shipped, ec) ? shipped.string() : std::string();
}

}  // namespace

std::string resolve_shipped_path(const std::string& name_or_file, const std::string& folder,
                                 const std::string& what) {
  const std::string file = existing_or_shipped_file(name_or_file, folder, ".json");
  if (!file.empty()) return file;
  std::string names;
  for (const std::string& n : shipped_names(folder)) names += (names.empty() ? "" : ", ") + n;
  throw std::runtime_error("'" + name_or_file + "' is neither a file nor a shipped " + what + " (" +
                           (names.empty() ? "none found in " + datasets_dir() : names) + ")");
}

std::vector<std::string> shipped_script_names() { return shipped_names("scripts"); }

std::string resolve_script_path(const std::string& name_or_file) {
  return resolve_shipped_path(name_or_file, "scripts", "script");
}

std::string default_texture_path() {
  return (fs::path(datasets_dir()) / "textures" / "butterfly.png").string();
}

std::string resolve_texture_path(const std::string& name_or_file) {
  if (name_or_file.empty()) return name_or_file;
  const std::string file = existing_or_shipped_file(name_or_file, "textures", ".png");
  return file.empty() ? name_or_file : file;
}

}  // namespace oflab
