// Discretisations the GPU cannot hold (docs/errors.md): a texel size or element count whose
// atlas is over the texture or memory limit is one error naming the limit and a size that fits.
#include <catch2/catch.hpp>
#include <chrono>
#include <regex>

#include "src/base/Error.h"
#include "src/scene/Atlas.h"
#include "tests/bad_input/BadInput.h"
#include "tests/support/Support.h"

using namespace hemirad;
using namespace hemirad::test::bad_input;
using Catch::Contains;

namespace {

// The `--texel-size X` an error message suggests.
double suggestedTexelSize(const std::string& message) {
  std::smatch m;
  REQUIRE(std::regex_search(message, m, std::regex("use --texel-size ([0-9.e+-]+) or larger")));
  return std::stod(m[1]);
}

Scene unitSquare() {
  Scene scene;
  scene.path = "unit square";
  scene.addObject("square");
  scene.addPolygon(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1), test::material(scene, 0.5, 1.0), 0);
  return scene;
}

}  // namespace

// ---- discretisation: texel size and element count against the GPU's limits

TEST_CASE(
    "Bad input: a texel size whose atlas is over the GPU texture limit is one error naming the limit and a size "
    "that fits",
    "[cli][bad-input]") {
  std::string obj = writeScene("tiny-texels", kQuad + "f 1 2 3 4\n");
  expectRefused("tiny-texels", solve(obj) + " --texel-size 1e-5",
                {"texel size 1e-05 needs a", "GL_MAX_TEXTURE_SIZE", "use --texel-size", "or --elements"});
  expectRefused("absurd-texels", solve(obj) + " --texel-size 1e-12", {"GL_MAX_TEXTURE_SIZE", "use --texel-size"});
}

TEST_CASE("Bad input: an element count over the GPU texture limit is one error within seconds naming the limit",
          "[cli][bad-input]") {
  // A triangle: its 2^28 elements need about twice as many cells (a unit square's would fill
  // exactly 16384 x 16384, the atlas having no gutters).
  std::string obj = writeScene("many-elements", kQuad + "f 1 2 3\n");
  auto start = std::chrono::steady_clock::now();
  expectRefused("many-elements", solve(obj) + " --elements 268435456", {"GL_MAX_TEXTURE_SIZE", "use --texel-size"});
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 30);
  expectRefused("too-many-elements", solve(obj) + " --elements 268435457", {"--elements"});
}

TEST_CASE("An atlas over the texture limit is refused with a suggested texel size that does fit", "[cpu][bad-input]") {
  Scene scene = unitSquare();
  std::string message;
  try {
    buildAtlas(scene, 0.001, 64);
  } catch (const InputError& e) {
    message = e.what();
  }
  INFO(message);
  CHECK_THAT(message, Contains("over the GPU's limit of 64 texels a side"));
  double fit = suggestedTexelSize(message);
  Atlas atlas;
  REQUIRE_NOTHROW(atlas = buildAtlas(scene, fit, 64));
  CHECK(atlas.width <= 64);
  CHECK(atlas.height <= 64);
}

TEST_CASE("An atlas over the memory limit is refused naming the limit and a texel size that fits", "[cpu][bad-input]") {
  Scene scene = unitSquare();
  const std::size_t memory = 1 << 20;  // 1 MiB: about 8,000 texels
  std::string message;
  try {
    buildAtlas(scene, 0.001, 16384, memory);
  } catch (const InputError& e) {
    message = e.what();
  }
  INFO(message);
  CHECK_THAT(message, Contains("of memory, over the memory limit of 1.0 MiB"));
  double fit = suggestedTexelSize(message);
  REQUIRE_NOTHROW(buildAtlas(scene, fit, 16384, memory));
  CHECK_THROWS_AS(buildAtlas(scene, fit / 1.2, 16384, memory), InputError);  // and not far from the smallest
}
