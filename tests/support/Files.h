// Shared helpers for the tests that go through files and the command line: scene files written
// into the test temp folder, reports read back, and what a run printed.
#pragma once
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "src/output/Image.h"

namespace hemirad::test {

// Writes OBJ_FILE and MTL_FILE (s.obj and m.mtl unless named) into the fresh temp folder
// `folder`; returns the OBJ's path.
std::string writeScene(const std::string& folder, const std::string& obj, const std::string& mtl,
                       const std::string& objFile = "s.obj", const std::string& mtlFile = "m.mtl");
// OBJ lines (v, then f) of a UV sphere's stacks from `firstStack` to the south pole, of `slices` x
// `stacks` (theta = pi j / stacks from the north pole, so 0: the whole sphere, stacks / 2: the lower
// hemisphere), facing out or in, its first vertex numbered `firstVertex`; triangles at the poles.
std::string uvSphereObj(glm::dvec3 centre, double radius, int slices, int stacks, int firstStack = 0,
                        int firstVertex = 1, bool inward = false);
// Writes `text` to the fresh temp path `name`; returns the path.
std::string writeTempFile(const std::string& name, const std::string& text);
nlohmann::json readJson(const std::string& path);  // a report, a bench or validation JSON
std::string readText(const std::string& path);     // a whole file ("" if missing)
// `hemirad solve ARGS --quiet --report TEMP`, required to succeed: the report's mean B (red) of `object`.
double solvedObjectB(const std::string& args, const std::string& object);
double reportObjectB(const nlohmann::json& report, const std::string& object);  // a solve report's, as above

int count(const std::string& text, const std::string& what);  // non-overlapping occurrences
// The `hemirad: error:` lines in a run's output: bad input must give exactly one.
inline int errorLines(const std::string& output) { return count(output, "hemirad: error:"); }

double meanPixel(const Image& image);  // over every pixel and channel

}  // namespace hemirad::test
