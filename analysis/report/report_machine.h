// The machine and build a report was produced on: what a reader needs to judge timings.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace oflab {

struct MachineInfo {
  std::string cpu_model;   // "model name" of /proc/cpuinfo ("unknown" if unreadable)
  int cores = 0;           // std::thread::hardware_concurrency()
  std::string os;          // uname: system, release, machine
  std::string compiler;    // compiler name and version oflab was built with
  std::string build_type;  // CMake build type oflab was configured with
  std::string date;        // local date and time of the run, ISO 8601
  std::string git_commit;  // commit of the source tree, "+ local changes" when dirty;
                           // "not available" outside a git checkout
};

MachineInfo collect_machine_info();

// The facts as (label, value) pairs, in the order a report lists them.
std::vector<std::pair<std::string, std::string>> machine_facts(const MachineInfo& info);

}  // namespace oflab
