// `hemirad validate`: the GPU item buffer and form factors against the exact CPU reference,
// texel by texel, at several item-mesh subdivision levels L.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/output/Provenance.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ItemBuffer.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/SolverState.h"
#include "src/validate/ExactReference.h"
#include "src/validate/FormFactorProbe.h"

namespace hemirad {

struct ValidateOptions {
  std::string scene;
  LoadOptions load;
  Discretisation discretisation;
  std::vector<int> levels{0, 1, 2, 3, 4};
  std::optional<std::size_t> shooters = 16;  // nullopt: every element
  // Every projection at every resolution is one configuration, compared at every level.
  std::vector<int> itemResolutions{512};
  std::vector<Projection> projections{Projection::Orthographic};  // --hemisphere all: allProjections()
  gl::BackendOptions backend;
  std::optional<std::string> camera;  // for the camera-view figures
  std::string report, figures;
  std::string figureSize;  // --figure-size (parseFigureSize)
  bool solution = false;   // also compare a converged GPU solve with the dense solution
  // --visibility bvh: also the traced test of the solver's --visibility bvh (one configuration, `bvh`).
  Visibility visibility = Visibility::ItemBuffer;
  double solutionConvergence = 0.999;
};

struct LevelStats {
  Projection projection = Projection::Orthographic;
  int itemResolution = 0;
  int itemSubdivision = 0;
  bool traced = false;  // the BVH's segment tests, not an item buffer
  std::size_t itemTriangles = 0, texelPairs = 0, falseVisible = 0, falseHidden = 0;
  double visibilityAgreement = 0, ffRelErrorMedian = 0, ffRelErrorMean = 0, ffRelErrorP95 = 0, ffRelErrorMax = 0;
  // The pairs whose receiver sees the shooter element in part (the reference's stratified F has
  // an error bound: occluders cross it), where the GPU's one visibility per pair can be right only
  // on average; and the FF errors over the pairs seen whole, what the form factor itself gets.
  std::size_t partlySeen = 0;
  double wholeRelErrorMedian = 0, wholeRelErrorP95 = 0, wholeRelErrorMax = 0;
  double gpuMs = 0;
};

// F from object to object over the shooter elements validate takes: the exact form factors (CGAL
// visibility, partial occlusion integrated) from those shooters to every receiver element's
// centre, area-weighted. Over a sample of the `from` object's elements (shooters < elements) it
// is a sample's value, not the object's F: evenly spread picks are systematic, so no standard
// error holds (blocked squares, 9 of 121 emitter elements: 18 % off the all-element value). With
// `--shooters all` what is left is the receivers' discretisation (docs/validation.md). The GPU value
// is over the same shooters: GPU against reference is a paired difference.
struct ObjectFormFactor {
  std::string from, to;
  double reference = 0;
  std::size_t shooters = 0, elements = 0;  // of the `from` object: sampled, and all
  double gpu = 0;
};

// GPU radiosity (converged) against the dense exact solution, per object (luminance of B).
struct SolutionError {
  std::string object;
  double meanDense = 0, meanGpu = 0, rmse = 0, maxError = 0;
};

struct Validation {
  std::size_t elements = 0, shooters = 0;
  double exactMs = 0;
  std::vector<LevelStats> levels;
  std::vector<ObjectFormFactor> objectFormFactors;  // gpu: first configuration, highest level
  std::vector<SolutionError> solution;              // with ValidateOptions::solution
  unsigned solutionShots = 0;
  // For the figures: the shooter whose visibility errors misplace the most form factor at the
  // first configuration's lowest level, and its exact and GPU samples at that configuration's lowest and highest level.
  std::size_t figureShooter = 0;
  std::vector<PairSample> figureExact;
  std::vector<std::vector<ProbeSample>> figureGpu;  // [0]: lowest level, [1]: highest
};

// The shooter elements (atlas texels): `count` spread evenly over all elements, or all.
std::vector<std::size_t> chooseShooters(const Atlas& atlas, std::optional<std::size_t> count);
// Runs the comparison on the current GL context.
Validation validate(const Scene& scene, const Atlas& atlas, const ValidateOptions& options);
int runValidate(const ValidateOptions& options);

// The per-level table: its header and a row per level; as printed (markdown) and in index.html.
std::vector<std::vector<std::string>> levelRows(const Validation& v);
std::string levelTable(const Validation& v);
std::string configName(const LevelStats& s);  // "orthographic 512^2"

// validate --figures (src/validate/ValidateFigures.cpp): plots (SVG, PDF) and CSV against L, heat
// maps on the atlas and renders of the camera view for the figure shooter, and index.html showing
// them. prepareFigureFolder fails before any work if the folder or matplotlib is missing.
void prepareFigureFolder(const std::string& dir);
void writeFigures(const std::string& dir, const Scene& scene, const Atlas& atlas, const SolverState& state,
                  const Camera& camera, const ValidateOptions& options, const Validation& v,
                  const Provenance& provenance);
// index.html (src/validate/ValidatePage.cpp): the run's provenance, the tables and the figures.
std::string validationPage(const std::string& title, const Scene& scene, const Atlas& atlas,
                           const ValidateOptions& options, const Validation& v, const Provenance& provenance);

}  // namespace hemirad
