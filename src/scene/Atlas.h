// The atlas: every polygon gets a rectangular chart of square texels of side `texelSize`;
// each texel cut by its polygon is one radiosity element, with the true area of the cut
// (partial texels at edges keep only what lies inside) and its centre at the cut's centroid.
// Charts are packed with a one-texel gutter; lookups also mask by polygon id, so filtering
// never mixes charts.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "src/base/Polygon.h"
#include "src/scene/Scene.h"

namespace hemirad {

constexpr std::uint32_t kNoPolygon = 0xFFFFFFFFu;

struct Chart {
  int polygon = 0;
  glm::ivec2 origin{0};  // atlas texel of cell (0, 0)
  glm::ivec2 size{0};    // cells
  PlaneFrame frame;      // plane coordinates of the polygon
  glm::dvec2 corner{0};  // plane coordinates of cell (0, 0)'s lower-left corner
};

// A block of 2^k x 2^k cells of one chart that shoots as one element (substructuring).
struct ShooterBlock {
  glm::ivec4 rect;  // atlas x, y, width, height
};

class Atlas {
 public:
  double texelSize = 0;
  int width = 0, height = 0;
  std::vector<Chart> charts;                // index = polygon id
  std::vector<glm::vec4> positionArea;      // per atlas texel: centre xyz, area (0: no element)
  std::vector<std::uint32_t> polygonOf;     // per atlas texel: polygon id or kNoPolygon
  std::size_t elements = 0;

  // Continuous atlas coordinates of point p on polygon `polygon` (texel (i, j) spans [i, i+1)).
  glm::dvec2 atlasCoord(int polygon, const glm::dvec3& p) const;
  // The element cut of texel (x, y) as a polygon in 3D (empty if none). Used by outputs and tests.
  Poly3 elementShape(const Scene& scene, int x, int y) const;
  // The part of the polygon under an atlas rectangle of one chart (x, y, w, h): what a shooter
  // block emits from (convex for a convex polygon; elementShape for a 1 x 1 block).
  Poly3 blockShape(const Scene& scene, glm::ivec4 rect) const;
  std::vector<ShooterBlock> shooterBlocks(int level) const;
  // Blocks of 2^polygonLevel[p] texels a side on polygon p's chart.
  std::vector<ShooterBlock> shooterBlocks(const std::vector<int>& polygonLevel) const;
  // Bilinear lookup of per-texel `values` at atlas coordinate `coord`, weighing only texels of
  // `polygon` (the CPU twin of shaders/camera.frag).
  glm::vec3 sample(const std::vector<glm::vec4>& values, int polygon, glm::dvec2 coord) const;
};

// Builds the atlas; throws InputError, naming the limit and a texel size that fits, if it would
// exceed maxSize texels on a side or need more than maxBytes of memory (0: this machine's).
Atlas buildAtlas(const Scene& scene, double texelSize, int maxSize = 16384, std::size_t maxBytes = 0);
// The texel size that gives about `elements` elements (partial texels counted).
double texelSizeForElements(const Scene& scene, std::size_t elements);

// The discretisation the user asked for: a texel size, or about a number of elements.
struct Discretisation {
  std::optional<double> texelSize;         // scene units
  std::optional<std::size_t> elements;     // or: about this many elements
  static constexpr std::size_t kDefaultElements = 10000;
};
// Texel size from the flags: --texel-size, else --elements, else about 10,000 elements.
double chooseTexelSize(const Scene& scene, const Discretisation& d);

}  // namespace hemirad
