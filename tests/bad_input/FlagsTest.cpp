// Bad flags (docs/errors.md): flags that exclude each other, values out of range or not
// numbers, unknown flags: one error line naming the flag, exit code 2, no output.
#include <catch2/catch.hpp>
#include <string>

#include "tests/bad_input/BadInput.h"
#include "tests/support/Support.h"

using namespace hemirad;
using namespace hemirad::test::bad_input;
using Catch::Contains;

// ---- flags

TEST_CASE("Bad input: --texel-size with --elements is one error naming both flags", "[cli][bad-input]") {
  std::string obj = writeScene("both", kQuad + "f 1 2 3 4\n");
  expectRefused("both", solve(obj) + " --texel-size 0.1 --elements 100", {"--texel-size", "--elements", "excludes"});
}

TEST_CASE("Bad input: --converge outside (0, 1) is one error naming the flag", "[cli][bad-input]") {
  std::string obj = writeScene("converge", kQuad + "f 1 2 3 4\n");
  for (std::string c : {"0", "1", "1.5", "-0.1", "nan"})
    expectRefused("converge" + c, "solve " + obj + " --converge " + c, {"--converge"});
}

TEST_CASE("Bad input: an unknown flag is one error naming it", "[cli][bad-input]") {
  std::string obj = writeScene("unknown-flag", kQuad + "f 1 2 3 4\n");
  expectRefused("unknown-flag", solve(obj) + " --frobnicate 3", {"--frobnicate"});
}

TEST_CASE("Bad input: a non-numeric or out-of-range flag value is one error naming the flag", "[cli][bad-input]") {
  std::string obj = writeScene("values", kQuad + "f 1 2 3 4\n");
  for (std::string flag :
       {"--shots many", "--texel-size big", "--texel-size inf", "--texel-size -1", "--elements lots", "--elements 0",
        "--width abc", "--exposure x", "--item-res 8", "--shooters-per-pass 65", "--gpu -1"})
    expectRefused("values", solve(obj) + " " + flag, {flag.substr(0, flag.find(' '))});
}

TEST_CASE(
    "Bad input: a flag of the other method, a seed that is not a number, or stochastic iteration without "
    "--shots is one error naming the flag",
    "[cli][bad-input]") {
  std::string obj = writeScene("method-flags", kQuad + "f 1 2 3 4\n");
  const std::string stochastic = solve(obj) + " --method stochastic";
  for (std::string flag : {"--converge 0.5", "--shoot-level 1", "--algorithm importance", "--fov-decay 8"})
    expectRefused("method-flags", stochastic + " " + flag,
                  {flag.substr(0, flag.find(' ')), "is for --method progressive, not stochastic"});
  for (std::string flag : {"--seed 3", "--transport mean"})
    expectRefused("method-flags", solve(obj) + " " + flag,
                  {flag.substr(0, flag.find(' ')), "is for --method stochastic"});
  for (std::string flag : {"--seed abc", "--seed -1", "--seed 4294967296", "--transport average"})
    expectRefused("method-flags", stochastic + " " + flag, {flag.substr(0, flag.find(' '))});
  expectRefused("method-flags", "solve " + obj + " --quiet --method stochastic", {"--method stochastic needs --shots"});
}

TEST_CASE("Bad input: a bad preset name is one error line naming the presets, exit 2", "[cli][bad-input][preset]") {
  std::string obj = writeScene("preset", kQuad + "f 1 2 3 4\n");
  for (std::string name : {"fastest", "Seed003", "''"})
    expectRefused("preset", solve(obj) + " --preset " + name,
                  {"--preset", "is not a preset; the presets are fast, refined, seed003, reference (the default: fast)"});
  expectRefused("preset", solve(obj) + " --method stochastic --preset seed003",
                {"--preset is for --method progressive, not stochastic"});
}

TEST_CASE("Bad input: --chart-angle over 60 is one error, and stochastic iteration takes a chart of many polygons",
          "[cli][bad-input]") {
  // Two coplanar quads sharing an edge: one chart at any --chart-angle (a refusal before issue 29's curved charts).
  const std::string obj = writeScene("stochastic_charts", kQuad + "v 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n");
  expectRefused("chart_angle_range", solve(obj) + " --chart-angle 61", {"--chart-angle"});
  CHECK(test::hemirad(solve(obj) + " --method stochastic --chart-angle 30").exitCode == 0);
  CHECK(test::hemirad(solve(obj) + " --method stochastic").exitCode == 0);
}
