// What `hemirad solve` writes: images, atlas, PLY mesh and report, checked by reading them back.
#include <fmt/format.h>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/output/ImageFile.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

TEST_CASE("solve writes the EXR, PNG, atlas, PLY and report it is asked for", "[gl][cli]") {
  std::string dir = test::tempPath("outputs");
  std::filesystem::create_directories(dir);
  test::Run run =
      test::hemirad("solve " + test::sourcePath("scenes/analytic/parallel_squares.obj") +
                    " --texel-size 0.1 --converge 0.5 --width 64 --height 48 --camera eye=0.5,0.5,3,target=0.5,0.5,0"
                    " --out " +
                    dir + "/v.exr --image " + dir + "/v.png --atlas " + dir + "/a.exr --ply " + dir +
                    "/m.ply --report " + dir + "/r.json");
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  nlohmann::json r = test::readJson(dir + "/r.json");
  for (const char* key : {"backend", "renderer", "algorithm", "elements", "shots", "convergence", "item_subdivision",
                          "timings_ms", "objects"})
    CHECK(r.contains(key));
  CHECK(r["backend"] == "osmesa");
  CHECK(r["algorithm"] == "progressive");
  CHECK(r["elements"] == 200);
  CHECK(r["convergence"].get<double>() >= 0.5);
  for (const char* key : {"total", "item_buffer", "gather", "select", "readback"}) CHECK(r["timings_ms"].contains(key));
  REQUIRE(r["objects"].size() == 2);
  CHECK(r["objects"][1]["name"] == "receiver");
  CHECK(r["objects"][1]["area"].get<double>() == Approx(1.0));
  double receiverB = r["objects"][1]["mean_radiosity"][0];
  CHECK(receiverB > 0);

  Image view = readImage(dir + "/v.exr"), png = readImage(dir + "/v.png");
  CHECK(view.width == 64);
  CHECK(view.height == 48);
  CHECK(png.width == 64);
  // The camera looks at the receiver's back through the emitter... from z = 3 it sees the
  // receiver's back face (z = 1 plane): its pixels carry the receiver's B.
  float centre = view.rgb[(24 * 64 + 32) * 3];
  CHECK(centre > 0);

  Image atlas = readImage(dir + "/a.exr");
  CHECK(atlas.width == r["atlas"]["width"].get<int>());
  CHECK(atlas.height == r["atlas"]["height"].get<int>());

  std::ifstream ply(dir + "/m.ply", std::ios::binary);
  std::string line;
  size_t vertices = 0, faces = 0;
  while (std::getline(ply, line) && line != "end_header") {
    std::istringstream ss(line);
    std::string a, b;
    size_t n = 0;
    ss >> a >> b >> n;
    if (a == "element" && b == "vertex") vertices = n;
    if (a == "element" && b == "face") faces = n;
  }
  CHECK(faces == 200);             // one face per element
  CHECK(vertices == 2 * 11 * 11);  // a 10 x 10 grid of elements per square, corners shared
}

TEST_CASE("The shipped Cornell box has about 10,000 elements at the default texel size", "[cpu][cli]") {
  test::Run run = test::hemirad("info " + test::sourcePath("scenes/cornell/cornell.obj"));
  REQUIRE(run.exitCode == 0);
  std::istringstream out(run.output);
  std::string line;
  size_t elements = 0;
  while (std::getline(out, line))
    if (line.rfind("elements", 0) == 0) elements = std::stoul(line.substr(8));
  CHECK(elements == Approx(10000).epsilon(0.02));
  CHECK_THAT(run.output, Contains("warnings     0"));
}

TEST_CASE("validate --hemisphere all compares the four projections in one table, errors in significant digits",
          "[gl][cli]") {
  std::string report = test::tempPath("validate_all.json");
  test::Run v =
      test::hemirad("validate " + test::sourcePath("scenes/cornell/cornell.obj") +
                    " --elements 300 --levels 0,1 --shooters 2 --item-res 64 --hemisphere all --report " + report);
  INFO(v.output);
  REQUIRE(v.exitCode == 0);
  nlohmann::json r = test::readJson(report);
  REQUIRE(r["levels"].size() == 8);  // four projections x two levels, in allProjections() order
  const char* names[] = {"orthographic", "hemicube", "conformal", "equal-area"};
  for (std::size_t k = 0; k < 8; ++k) CHECK(r["levels"][k]["hemisphere"] == names[k / 2]);
  CHECK_THAT(v.output, Contains("| equal-area 64^2 | 1 |"));
  CHECK_THAT(v.output, !Contains("0.0000 |"));  // a small error is printed as 1.97e-05, not as zero
}

TEST_CASE("validate writes its report and figures, and bench its table and JSON", "[heavy][gl][cli]") {
  std::string dir = test::tempPath("validate");
  test::Run v = test::hemirad("validate " + test::sourcePath("scenes/cornell/cornell.obj") +
                              " --elements 1500 --levels 0,2 --shooters 4 --hemisphere stereographic,hemicube"
                              " --report " +
                              dir + ".json --figures " + dir);
  INFO(v.output);
  REQUIRE(v.exitCode == 0);
  nlohmann::json r = test::readJson(dir + ".json");
  REQUIRE(r["levels"].size() == 4);  // two projections x two levels
  for (const char* key :
       {"item_subdivision", "texel_pairs", "visibility_agreement", "false_visible", "false_hidden",
        "ff_rel_error_median", "ff_rel_error_mean", "ff_rel_error_p95", "ff_rel_error_max", "item_triangles", "gpu_ms"})
    CHECK(r["levels"][0].contains(key));
  CHECK(r["levels"][0]["hemisphere"] == "orthographic");  // asked for by its old name, stereographic
  CHECK(r["levels"][3]["hemisphere"] == "hemicube");
  // Every object holding a shooter, to each of the 8 objects.
  CHECK(r["object_form_factors"].size() % 8 == 0);
  CHECK(r["object_form_factors"].size() >= 8);
  for (const char* f : {"index.html", "levels.csv", "agreement_vs_level.svg", "ff_error_vs_level.pdf",
                        "atlas_visibility_L0.svg", "view_visibility_L2.png", "atlas_ff_error_L2.pdf"})
    CHECK(std::filesystem::exists(dir + "/" + f));
  // Provenance, the same in the report and in every figure's metadata: what --version says, the
  // command line as run, the backend.
  const std::string version = test::hemirad("--version").output;
  const nlohmann::json& p = r["provenance"];
  CHECK(version ==
        fmt::format("hemirad {} (git {})\n", p["version"].get<std::string>(), p["git_hash"].get<std::string>()));
  CHECK(p["git_hash"].get<std::string>().size() >= 7);
  CHECK_THAT(p["command_line"].get<std::string>(), Contains("validate ") && Contains(" --figures " + dir));
  CHECK(p["backend"] == r["backend"]);
  CHECK(p["renderer"] == r["renderer"]);
  const std::string svg = test::readText(dir + "/ff_error_vs_level.svg");
  CHECK_THAT(svg, Contains(fmt::format("<dc:description>hemirad {} (git {}), {} (", p["version"].get<std::string>(),
                                       p["git_hash"].get<std::string>(), p["backend"].get<std::string>())));
  CHECK_THAT(svg, Contains(" --figures " + dir + "</dc:description>"));
  CHECK_THAT(test::readText(dir + "/atlas_ff_error_L2.svg"), Contains("relative error of F"));  // the colour bar

  std::string json = test::tempPath("bench.json");
  test::Run b = test::hemirad("bench --scenes " + test::sourcePath("scenes/analytic/parallel_squares.obj") +
                              " --elements 400 --split-shots 8 --ceiling --json " + json);
  INFO(b.output);
  REQUIRE(b.exitCode == 0);
  CHECK_THAT(b.output, Contains("| time to 90% (ms) |"));
  nlohmann::json bj = test::readJson(json);
  REQUIRE(bj["rows"].size() == 1);
  CHECK(bj["rows"][0]["convergence"].get<double>() >= 0.9);
  CHECK(bj["rows"][0]["shots"].get<int>() > 0);
  CHECK(bj["ceilings"]["load_store_invocations_per_s"].get<double>() > 0);
  CHECK(bj["ceilings"]["item_buffer_triangles_per_s"].get<double>() > 0);
  CHECK(bj["ceilings"]["item_buffer_fragments_per_s"].get<double>() > 0);
  CHECK(bj["preset"] == "fast");  // the default: hemicube, item resolution planned from the elements
  CHECK(bj["projection"] == "hemicube");
  CHECK(bj["rows"][0]["item_resolution"].get<int>() >= 16);
  CHECK(bj["rows"][0]["item_pixels"].get<int>() > 0);
  CHECK(bj["rows"][0]["shooter_blocks"].get<int>() > 0);
  CHECK(bj["rows"][0]["gpu_memory_mib"].is_null());  // llvmpipe does not say
  CHECK_THAT(b.output, Contains("gather / ceiling"));
  CHECK(bj["rows"][0]["radiosity_hash"].get<std::string>().size() == 16);
  // Comparing a run with its own earlier JSON: same backend, bitwise the same objects.
  test::Run c = test::hemirad("bench --scenes " + test::sourcePath("scenes/analytic/parallel_squares.obj") +
                              " --elements 400 --split-shots 8 --compare " + json);
  INFO(c.output);
  REQUIRE(c.exitCode == 0);
  CHECK_THAT(c.output, Contains("| receiver | "));
  CHECK_THAT(c.output, Contains("| 0.00e+00 |"));
}
