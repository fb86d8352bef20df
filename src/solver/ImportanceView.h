// Importance from the user's view (seed 004 §4.2): the view is rasterised into per-element
// pixel counts, which set each element's directly received importance R (view fraction per
// unit area); the unshot importance dI (alpha of dB) takes the change, so after a camera move
// the importance-driven solver re-shoots only the difference. The alpha of B holds the
// importance received from other surfaces, I - R, which a move leaves as it is.
#pragma once
#include <optional>
#include <utility>

#include "gl/Objects.h"
#include "src/scene/Camera.h"
#include "src/solver/CameraMesh.h"
#include "src/solver/SolverState.h"

namespace hemirad {

class ImportanceView {
 public:
  // `resolution`: pixels of the view's longer side.
  explicit ImportanceView(SolverState& state, int resolution = 256);
  // Looks from `camera` (aspect width / height) and updates R, I and dI. False (and nothing
  // done) for the view it already has: a resumed solve looks again.
  bool look(const Camera& camera, double aspect);
  std::vector<float> readDirect() const;                 // R per atlas texel
  void restoreDirect(const std::vector<float>& direct);  // a checkpoint's R

 private:
  SolverState& state_;
  int resolution_;
  std::optional<std::pair<Camera, double>> looked_;
  CameraMesh mesh_;
  gl::Program view_, update_;
  gl::Texture pixels_, direct_;
};

}  // namespace hemirad
