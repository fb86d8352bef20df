// Seed 004's ambient term (§4.1.6): shown as B + rho_j R S, with S the area-averaged unshot
// radiosity and R = 1 / (1 - rho_avg); a display estimate of the light not yet shot, never in B.
#include <catch2/catch.hpp>
#include <cstring>

#include "src/output/Renderer.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
double rmsDifference(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
  return std::sqrt(sum / double(a.rgb.size()));
}
const Camera kInside{{0.5, 0.5, 0.9}, {0.5, 0.5, 0.0}, {0, 1, 0}, 70.0};
}  // namespace

TEST_CASE("Before the first shot the ambient term shows a furnace box at E / (1 - rho)", "[gl][ambient]") {
  // Every element is alike and all of E is unshot: S = E, and B + rho R S = E + rho E / (1 - rho)
  // is the exact solution with exact form factors.
  test::backend();
  const double rho = 0.6;
  Scene s = test::cube(rho, 1.0);
  Atlas atlas = buildAtlas(s, 0.1);
  SolverState state(s, atlas);
  Renderer renderer(state);
  CHECK(test::meanPixel(renderer.render(kInside, 32, 32, 1)) == Approx(1.0).epsilon(1e-6));
  renderer.setAmbient(true);
  CHECK(renderer.ambientTerm().x == Approx(1.0 / (1.0 - rho)).epsilon(1e-5));
  CHECK(test::meanPixel(renderer.render(kInside, 32, 32, 1)) == Approx(1.0 / (1.0 - rho)).epsilon(1e-5));
}

TEST_CASE("The ambient term brings early images closer to the converged one, fades, and never enters B",
          "[heavy][gl][ambient]") {
  // A grey box (rho 0.5) lit by a black lamp ceiling. After the lamp's shots half the light is
  // still unshot; the ambient term estimates it.
  test::backend();
  Scene s = test::cube(0.5, 0.0, 1);
  Atlas atlas = buildAtlas(s, 0.1);
  SolverState state(s, atlas);
  ProgressiveSettings settings;
  settings.stop.targetConvergence = 0.6;
  ProgressiveSolver solver(state, settings);
  SolveStatus early;
  while (!early.done) early = solver.advance(16);
  Renderer renderer(state);
  const Image plain = renderer.render(kInside, 48, 48, 1);
  renderer.setAmbient(true);
  const std::vector<glm::vec4> before = state.readRadiosity();
  const Image ambient = renderer.render(kInside, 48, 48, 1);
  const std::vector<glm::vec4> after = state.readRadiosity();
  CHECK(std::memcmp(before.data(), after.data(), before.size() * sizeof(glm::vec4)) == 0);

  // S from a readback of dB: the term is R S with R = 1 / (1 - 0.5 * 5/6) (five grey faces, one lamp).
  double unshot = 0, area = 0;
  std::vector<glm::vec4> dB = state.readDeltaB();
  for (std::size_t t = 0; t < dB.size(); ++t)
    if (atlas.polygonOf[t] != kNoPolygon) unshot += dB[t].x * atlas.positionArea[t].w, area += atlas.positionArea[t].w;
  const double R = 1.0 / (1.0 - 0.5 * 5.0 / 6.0);
  CHECK(renderer.ambientTerm().x == Approx(R * unshot / area).epsilon(1e-4));

  SolveStatus late;
  ProgressiveSettings tight = settings;
  tight.stop.targetConvergence = 0.999;
  ProgressiveSolver finish(state, tight);
  while (!late.done) late = finish.advance(64);
  const Image converged = renderer.render(kInside, 48, 48, 1);
  renderer.setAmbient(false);
  const Image convergedPlain = renderer.render(kInside, 48, 48, 1);
  const double errPlain = rmsDifference(plain, convergedPlain), errAmbient = rmsDifference(ambient, convergedPlain);
  INFO("at convergence " << early.convergence << ": rms error " << errPlain << " without, " << errAmbient
                         << " with the ambient term; converged: " << rmsDifference(converged, convergedPlain));
  CHECK(errAmbient < 0.5 * errPlain);
  CHECK(rmsDifference(converged, convergedPlain) < 0.01 * errPlain);
}

TEST_CASE("A solve's own camera images carry no ambient term unless --ambient on asks for it",
          "[heavy][cli][ambient]") {
  // The ambient term is a preview's estimate of the light not yet shot, uniform and tinted by the
  // mean reflectance: on a converged image it is an ad hoc term (issue 31: +1.7 % on a block's dark
  // face at 0.999). So a solve's --out is B alone unless asked; view and walkthrough frames keep it.
  auto render = [](const std::string& flags) {
    const std::string exr = test::tempPath("solve-ambient" + std::to_string(std::hash<std::string>{}(flags)) + ".exr");
    const test::Run run =
        test::hemirad("solve " + test::sourcePath("scenes/cornell/cornell.obj") +
                      " --elements 300 --shots 16 --width 32 --height 32 --quiet --out " + exr + flags);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return test::readText(exr);
  };
  const std::string plain = render(""), off = render(" --ambient off"), on = render(" --ambient on");
  CHECK(plain == off);
  CHECK(plain != on);  // after 16 shots most of the light is unshot: the term is large
}
