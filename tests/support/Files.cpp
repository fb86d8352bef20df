#include "tests/support/Files.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "tests/support/Support.h"

namespace hemirad::test {

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
  const nlohmann::json json = readJson(report);  // kept: a temporary's ["objects"] would dangle
  for (const auto& o : json["objects"])
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
