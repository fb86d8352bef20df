// libFuzzer target: OBJ+MTL loading, the atlas and validateSolvable (see FuzzInput.h). A refusal
// with InputError is expected; a crash, a sanitizer report or any other exception is a bug.
// Built by ci/fuzz (HEMIRAD_FUZZ=ON, clang); a crasher goes to tests/fuzz/regressions/.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hemirad::fuzz::loadFuzzInput(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
