#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/fuzz/FuzzInput.h"
#include "tests/support/Support.h"

using namespace hemirad;

// Each file in tests/fuzz/regressions/ (fuzzer crashers, minimised, and hand-made nasty inputs)
// goes through the fuzz target's own path. Its extension says what must happen: `.loads` loads,
// `.refused` is refused with an InputError. A crash, sanitizer report (ci/sanitize) or any other
// exception fails the test.
TEST_CASE("Fuzzer crashers and nasty OBJ+MTL inputs load or are refused with InputError, never crash", "[cpu]") {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(test::sourcePath("tests/fuzz/regressions"))) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 4);
  for (const auto& f : files) {
    INFO(f.filename().string());
    REQUIRE((f.extension() == ".loads" || f.extension() == ".refused"));
    std::ostringstream text;
    text << std::ifstream(f, std::ios::binary).rdbuf();
    fuzz::Outcome o;
    REQUIRE_NOTHROW(o = fuzz::loadFuzzInput(text.str()));
    INFO(o.error);
    CHECK(o.loaded == (f.extension() == ".loads"));
    CHECK(o.loaded == o.error.empty());
  }
}
