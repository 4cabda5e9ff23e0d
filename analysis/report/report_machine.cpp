#include "report/report_machine.h"

#include <sys/utsname.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

namespace oflab {
namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? "unknown" : line.substr(start);
  }
  return "unknown";
}

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown";
#endif
}

// First line of a shell command's output ("" when it fails or prints nothing).
std::string first_line_of(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "";
  std::array<char, 256> buffer{};
  std::string line;
  if (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) line = buffer.data();
  pclose(pipe);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line;
}

std::string git_commit() {
  const std::string dir = OFLAB_SOURCE_DIR;
  const std::string head =
      first_line_of("git -C '" + dir + "' rev-parse --short=12 HEAD 2>/dev/null");
  if (head.empty()) return "not available";
  const std::string dirty =
      first_line_of("git -C '" + dir + "' status --porcelain --untracked-files=no 2>/dev/null");
  return dirty.empty() ? head : head + " + local changes";
}

std::string local_date() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  localtime_r(&now, &tm);
  char text[64];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%S%z", &tm);
  return text;
}

}  // namespace

MachineInfo collect_machine_info() {
  MachineInfo info;
  info.cpu_model = cpu_model();
  info.cores = static_cast<int>(std::thread::hardware_concurrency());
  utsname u{};
  if (uname(&u) == 0) info.os = std::string(u.sysname) + " " + u.release + " " + u.machine;
  info.compiler = compiler();
  info.build_type = OFLAB_BUILD_TYPE[0] ? OFLAB_BUILD_TYPE : "unspecified";
  info.date = local_date();
  info.git_commit = git_commit();
  return info;
}

std::vector<std::pair<std::string, std::string>> machine_facts(const MachineInfo& info) {
  return {
      {"CPU", info.cpu_model},        {"cores", std::to_string(info.cores)}, {"system", info.os},
      {"compiler", info.compiler},    {"build type", info.build_type},       {"date", info.date},
      {"git commit", info.git_commit}};
}

}  // namespace oflab
