// One libFuzzer harness: OFLAB_FUZZ_TARGET names the target of fuzz_inputs.h it drives.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const oflab::fuzz::Target target = oflab::fuzz::targets().at(OFLAB_FUZZ_TARGET);
  target(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
