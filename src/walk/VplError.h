// `hemirad compare-vpls`: instant radiosity's image error against a converged progressive solve
// of the same scene and camera, per VPL count (seed 002's validation, issue 16): the mean
// relative luminance error per region (scene object) and over the image (and in the CSV its signed
// mean, the bias), as a CSV, a log-log SVG
// and a markdown table, plus the two images side by side at the largest count.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/VplTracer.h"

namespace hemirad {

struct VplErrorOptions {
  std::string scene = "scenes/cornell/cornell.obj";
  LoadOptions load;
  Discretisation discretisation;  // the reference's elements
  std::vector<unsigned> vpls{64, 128, 256, 512, 1024, 2048, 4096};
  InstantSettings instant;
  double referenceConvergence = 0.999;
  std::optional<std::string> camera;
  int width = 96, height = 96;
  std::string out;         // --out-dir; empty: a fresh ./hemirad-COMMAND folder (freshFolder)
  std::string figureSize;  // --figure-size (parseFigureSize)
  std::string sideBySide;  // a PNG: instant (largest count) | progressive
  gl::BackendOptions backend;
};

int runVplError(VplErrorOptions options);

}  // namespace hemirad
