// The atlas: every chart (a set of polygons sharing one plane frame, src/scene/Charts.h) gets a
// rectangular grid of square texels of side `texelSize` (its own `cellSize` on adaptive leaves,
// src/scene/Leaves.h); the pieces of its polygons inside a texel's prism (along the chart's axis)
// are one radiosity element, with their true total area (partial texels at edges keep only what
// lies inside) and its centre at their area centroid.
// Each chart's grid lies along its outline's minimum-area rectangle; charts are packed without
// gutters (src/scene/AtlasPacker.h): every lookup masks by chart, so filtering never mixes charts.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "src/base/Polygon.h"
#include "src/scene/ChartMapping.h"
#include "src/scene/Charts.h"
#include "src/scene/Scene.h"

namespace hemirad {

constexpr std::uint32_t kNoPolygon = 0xFFFFFFFFu;
// Cuts smaller than this fraction of a texel are numerical slivers, not elements.
inline constexpr double kMinCutFraction = 1e-9;

// A chart: its frame, planarity and UVs (ChartMapping.h) say how its surface maps to its grid.
struct Chart : ChartMapping {
  int polygon = 0;            // its seed: the chart's material and object are this polygon's
  std::vector<int> polygons;  // every member (Charts.h)
  std::vector<Poly3> parts;   // what elements are cut from (ChartGroup::parts)
  std::vector<int> partPolygon;
  // Per part: its box in chart coordinates, so blockShape passes over
  // the parts a block misses without projecting them (a refined chart has hundreds).
  std::vector<Box2> partBox;
  glm::ivec2 origin{0};  // atlas texel of cell (0, 0)
  glm::ivec2 size{0};    // cells
  glm::dvec2 corner{0};  // chart coordinates of cell (0, 0)'s lower-left corner
  double cellSize = 0;   // its cells' side: Atlas::texelSize, finer on refined leaves (src/scene/Leaves.h)
};

// A projection chart whose grid the caller lays (refined leaves, src/scene/Leaves.h): cut as
// buildAtlas cuts.
struct ChartSpec {
  ChartGroup group;
  PlaneFrame frame;
  glm::dvec2 corner{0};
  glm::ivec2 size{0};
  double cellSize = 0;
};

// A block of 2^k x 2^k cells of one chart that shoots as one element (substructuring).
struct ShooterBlock {
  glm::ivec4 rect;  // atlas x, y, width, height
};

class Atlas {
 public:
  double texelSize = 0;  // the base cell side (every chart's in a uniform atlas)
  int width = 0, height = 0;
  std::vector<Chart> charts;           // index = chart id
  std::vector<std::uint32_t> chartOf;  // per polygon: its chart
  // Per polygon of a UV chart: its first part there (its parts follow it); empty without UV charts.
  std::vector<std::uint32_t> firstPartOf;
  std::vector<glm::vec4> positionArea;  // per atlas texel: centre xyz, area (0: no element)
  // Per atlas texel: the polygon with the element's largest piece (a cluster's: the member that
  // receives for it, src/scene/Clusters.h), or kNoPolygon (material and object are per chart, so
  // lookups through it are the element's).
  std::vector<std::uint32_t> polygonOf;
  // Per atlas texel: area-weighted mean piece normal (on a curved chart, of the smooth normals at
  // the pieces, src/scene/SmoothNormals.h).
  std::vector<glm::vec3> normalOf;
  // Per polygon, per vertex, its smooth normal where the atlas has a curved chart
  // (src/scene/SmoothNormals.h; what normalOf weighs in there); empty otherwise.
  std::vector<std::vector<glm::dvec3>> vertexNormals;
  std::size_t elements = 0;

  // The chart of texel t, or kNoPolygon.
  std::uint32_t chartAt(std::size_t t) const { return polygonOf[t] == kNoPolygon ? kNoPolygon : chartOf[polygonOf[t]]; }
  // Continuous atlas coordinates of point p on polygon `polygon` (texel (i, j) spans [i, i+1)),
  // through its chart's mapping.
  glm::dvec2 atlasCoord(int polygon, const glm::dvec3& p) const;
  // Chart coordinates (scene units, ChartMapping.h) of point p on polygon `polygon`.
  glm::dvec2 chartCoord(int polygon, const glm::dvec3& p) const;
  // The element of texel (x, y) as its pieces in 3D, one per chart part it cuts (none if no
  // element). Used by outputs, the dense reference and tests.
  std::vector<Poly3> elementShape(const Scene& scene, int x, int y) const;
  // The pieces of the chart under an atlas rectangle of one chart (x, y, w, h): what a shooter
  // block emits from, each convex (elementShape for a 1 x 1 block).
  // polygons: if given, each piece's polygon.
  std::vector<Poly3> blockShape(const Scene& scene, glm::ivec4 rect,
                                std::vector<std::uint32_t>* polygons = nullptr) const;
  // The same region as few convex pieces as its chart allows: on a planar chart (not UV-mapped)
  // whose pieces tile a convex region, that region's outline, one piece (a block over a
  // triangulated wall, or over a refined chart's parts, costs the gather one contour, not one
  // a part); else blockShape's pieces. What shooter blocks emit from (shapeTable).
  std::vector<Poly3> blockOutline(const Scene& scene, glm::ivec4 rect) const;
  std::vector<ShooterBlock> shooterBlocks(int level) const;
  std::uint32_t chartUnder(glm::ivec4 rect) const;  // the chart of the rectangle's first element, or kNoPolygon
  // A hash of where every chart lies and how its grid is laid (origin, size, frame, corner):
  // checkpoints carry it, so one made with another layout is refused, not misread.
  std::uint64_t layoutHash() const;
  // Blocks of 2^chartLevel[c] texels a side on chart c.
  std::vector<ShooterBlock> shooterBlocks(const std::vector<int>& chartLevel) const;
  // Bilinear lookup of per-texel `values` at atlas coordinate `coord`, weighing only texels of
  // `polygon`'s chart (the CPU twin of shaders/camera.frag).
  glm::vec3 sample(const std::vector<glm::vec4>& values, int polygon, glm::dvec2 coord) const;
};

// Builds the atlas; throws InputError, naming the limit and a texel size that fits, if it would
// exceed maxSize texels on a side or need more than maxBytes of memory (0: this machine's).
// chartAngle: degrees (src/scene/Charts.h; kPolygonCharts: a chart per polygon).
// uv: where the charts' grids come from (Charts.h).
Atlas buildAtlas(const Scene& scene, double texelSize, int maxSize = 16384, std::size_t maxBytes = 0,
                 double chartAngle = 0, UvSource uv = UvSource::Auto);
// The atlas of charts laid by the caller; texelSize: the base side (Atlas::texelSize).
Atlas buildAtlas(const Scene& scene, const std::vector<ChartSpec>& specs, double texelSize, int maxSize = 16384,
                 std::size_t maxBytes = 0, double chartAngle = 0);
// The texel size that gives about `elements` elements (partial texels counted).
double texelSizeForElements(const Scene& scene, std::size_t elements, double chartAngle = 0,
                            UvSource uv = UvSource::Auto);

// The discretisation the user asked for: a texel size, or about a number of elements.
struct Discretisation {
  std::optional<double> texelSize;         // scene units
  std::optional<std::size_t> elements;     // or: about this many elements
  double chartAngle = kDefaultChartAngle;  // --chart-angle, degrees (Charts.h)
  UvSource uv = UvSource::Auto;            // --uv (Charts.h)
  static constexpr std::size_t kDefaultElements = 10000;
  // Past this many times the elements asked for, buildAtlas warns: the charts hold more.
  static constexpr double kElementsOver = 1.25;
};
// Texel size from the flags: --texel-size, else --elements, else about 10,000 elements.
double chooseTexelSize(const Scene& scene, const Discretisation& d);
// The atlas the flags ask for, at chooseTexelSize's texel size: its charts grown once for both
// (growing them, LSCM's solves included, is most of an atlas's time on real_400k).
Atlas buildAtlas(const Scene& scene, const Discretisation& d, int maxSize, std::size_t maxBytes = 0);

}  // namespace hemirad
