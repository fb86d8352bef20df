// Shared helpers for the tests that go through files and the command line: scene files written
// into the test temp folder, reports read back, and what a run printed.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "src/output/Image.h"

namespace hemirad::test {

// Writes OBJ_FILE and MTL_FILE (s.obj and m.mtl unless named) into the fresh temp folder
// `folder`; returns the OBJ's path.
std::string writeScene(const std::string& folder, const std::string& obj, const std::string& mtl,
                       const std::string& objFile = "s.obj", const std::string& mtlFile = "m.mtl");
// Writes `text` to the fresh temp path `name`; returns the path.
std::string writeTempFile(const std::string& name, const std::string& text);
nlohmann::json readJson(const std::string& path);  // a report, a bench or validation JSON
std::string readText(const std::string& path);     // a whole file ("" if missing)
// `hemirad solve ARGS --quiet --report TEMP`, required to succeed: the report's mean B (red) of `object`.
double solvedObjectB(const std::string& args, const std::string& object);

int count(const std::string& text, const std::string& what);  // non-overlapping occurrences
// The `hemirad: error:` lines in a run's output: bad input must give exactly one.
inline int errorLines(const std::string& output) { return count(output, "hemirad: error:"); }

double meanPixel(const Image& image);  // over every pixel and channel

}  // namespace hemirad::test
