// A test helper of the lesson reader: writes a lesson "x.json" in a fresh folder and reads
// it back with read_lesson_file.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lessons/lessons.h"
#include "state/window_state_file.h"

namespace oflab::test {

// The error of reading the lesson "x.json" whose text after its `"state": {},` is `rest`
// (JSON text closing the object); "" when it reads. `tag` names the scratch folder.
inline std::string lesson_read_error(const std::string& tag, const std::string& rest) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("oflab-" + tag + "-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "x.json";
  std::ofstream(file) << R"({"format": "oflab-lesson", "version": 1, "name": "x", "order": 1,
    "title": "X", "narrative": "n", "state": {}, )"
                      << rest;
  std::string error;
  try {
    read_lesson_file(file.string());
  } catch (const SessionError& e) {
    error = e.what();
  }
  fs::remove_all(dir);
  return error;
}

}  // namespace oflab::test
