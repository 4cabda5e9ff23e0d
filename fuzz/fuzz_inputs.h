// The fuzz targets of oflab's readers: each feeds one input (the bytes of a file, or a command
// line as NUL- or newline-separated arguments) to one reader. A target returns normally when
// the reader accepts the input or refuses it with its own documented error; anything else (a
// crash, a sanitizer report, any other exception) escapes and is a finding. Used by the
// libFuzzer harnesses (fuzz_main.cpp, built with OFLAB_FUZZ=ON) and by the regression test
// that replays every committed crash input (fuzz/fuzz_regressions_test.cpp).
#pragma once

#include <map>
#include <string>

namespace oflab::fuzz {

using Target = void (*)(const std::string& bytes);

// The targets by name: motion-script, viewer-script, scene, session, obj, image, command-line.
// Each name is also the folder of its seeds' extension rules and of its regression inputs
// (fuzz/regressions/NAME/).
const std::map<std::string, Target>& targets();

}  // namespace oflab::fuzz
