#include "tests/support/Files.h"

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "tests/support/Support.h"

namespace hemirad::test {

std::string uvSphereObj(glm::dvec3 centre, double radius, int slices, int stacks, int firstStack, int firstVertex,
                        bool inward) {
  std::string obj;
  for (int j = firstStack; j <= stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const double theta = M_PI * j / stacks, phi = 2 * M_PI * i / slices;
      const double r = j == 0 || j == stacks ? 0.0 : std::sin(theta);  // the poles' vertices coincide
      const glm::dvec3 v = centre + radius * glm::dvec3(r * std::cos(phi), std::cos(theta), r * std::sin(phi));
      obj += fmt::format("v {} {} {}\n", v.x, v.y, v.z);
    }
  auto at = [&](int i, int j) { return firstVertex + (j - firstStack) * slices + i % slices; };
  for (int j = firstStack; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      std::vector<int> f = j == 0            ? std::vector<int>{at(i, j), at(i + 1, j + 1), at(i, j + 1)}
                           : j == stacks - 1 ? std::vector<int>{at(i, j), at(i + 1, j), at(i + 1, j + 1)}
                                             : std::vector<int>{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      if (inward) std::reverse(f.begin(), f.end());
      obj += fmt::format("f {}\n", fmt::join(f, " "));
    }
  return obj;
}

std::string writeScene(const std::string& folder, const std::string& obj, const std::string& mtl,
                       const std::string& objFile, const std::string& mtlFile) {
  std::string dir = tempPath(folder);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/" + mtlFile) << mtl;
  std::ofstream(dir + "/" + objFile) << obj;
  return dir + "/" + objFile;
}

std::string writeTempFile(const std::string& name, const std::string& text) {
  std::string path = tempPath(name);
  std::ofstream(path) << text;
  return path;
}

nlohmann::json readJson(const std::string& path) { return nlohmann::json::parse(std::ifstream(path)); }

double solvedObjectB(const std::string& args, const std::string& object) {
  const std::string report = tempPath("solved-object.json");
  const Run run = hemirad("solve " + args + " --quiet --report " + report);
  INFO("solve " << args << "\n" << run.output);
  REQUIRE(run.exitCode == 0);
  return reportObjectB(readJson(report), object);
}

double reportObjectB(const nlohmann::json& report, const std::string& object) {
  for (const auto& o : report["objects"])
    if (o["name"] == object) return o["mean_radiosity"][0].get<double>();
  FAIL("no object " << object << " in the report");
  return 0;
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t p = 0; (p = text.find(what, p)) != std::string::npos; p += what.size()) ++n;
  return n;
}

double meanPixel(const Image& image) {
  double sum = 0;
  for (float v : image.rgb) sum += v;
  return sum / double(image.rgb.size());
}

}  // namespace hemirad::test
