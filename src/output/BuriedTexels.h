// Buried texels: an element's sample point (its centre on its polygon's plane) that sees the back
// of the scene's surfaces over much of its hemisphere lies inside other geometry: under a couch's
// open base, inside interpenetrating cushions, under a block on the floor. It receives what that
// point does, too little for the texel's visible part, and a bilinear lookup carries its dark
// into the pixels around it (real_20k's furnace at 10k elements: 10 % of the area in elements
// that see back faces, B 1.29 to 1.85 where every point seen has 2). What is shown takes a buried
// texel's value from its unburied neighbours on its chart instead, as lightmap bakers do (Unity's
// "backface tolerance", Bakery's texel validity); the solution keeps its own.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

// A texel is buried where more than this share of its rays (kBuriedRays, cosine-distributed over
// its polygon's hemisphere) first meet a surface's back. Against the path-traced reference
// (real_20k, 9,916 elements, unrefined, 0.99; mean |error| / bias of the whole image, %): none
// 5.79 / -3.00, 0.1 (Unity's default) 5.85 / -2.06, 0.25 5.72 / -2.20, 0.5 5.69 / -2.24: at 0.1
// texels beside contacts, truly darker, took their brighter neighbours' light.
inline constexpr double kBuriedShare = 0.5;
inline constexpr int kBuriedRays = 64;

class BuriedFill {
 public:
  // Traces every element's rays (Embree): found once per layout.
  BuriedFill(const Scene& scene, const Atlas& atlas);
  // `values` with each buried texel's replaced by the mean of its nearest unburied texels of the
  // same chart (within kReach texels; none there: its own kept).
  std::vector<glm::vec4> operator()(std::vector<glm::vec4> values) const;
  bool empty() const { return fills_.empty(); }
  std::size_t buried() const { return buried_; }
  const std::vector<float>& backShare() const { return share_; }  // per atlas texel (0 without element)

  static constexpr int kReach = 4;

 private:
  struct Fill {
    std::size_t texel;
    std::vector<std::size_t> from;  // its nearest unburied texels, one ring
  };
  std::vector<float> share_;
  std::vector<Fill> fills_;
  std::size_t buried_ = 0;
};

}  // namespace hemirad
