// Figures for papers (src/output/Figure.h, python/plot.py): the sizes --figure-size names, fonts
// that travel with the file, and no title drawn inside the figure.
#include <catch2/catch.hpp>

#include "src/base/Error.h"
#include "src/output/Figure.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Matchers::Contains;

namespace {
std::size_t occurrences(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("Figure size column draws 3.5 x 2.6 inches, text as outlines, the title only in the metadata", "[cpu]") {
  const std::string stem = test::tempPath("figure_column");
  Figures figures(provenance("test", "none"), parseFigureSize("column"));
  LinePlot plot{"Form factor error against level", "item-mesh level L", "relative error", false, true, {}};
  plot.series.push_back({"orthographic", {0, 1, 2, 3}, {0.1, 0.03, 0.01, 0.004}});
  figures.add(stem, plot);
  figures.write();
  const std::string svg = test::readText(stem + ".svg");
  CHECK_THAT(svg, Contains("width=\"252pt\" height=\"187.2pt\""));  // 72 pt an inch
  CHECK(occurrences(svg, "<text") == 0);                            // glyphs as paths: no font needed to view it
  CHECK_THAT(svg, Contains("<dc:title>Form factor error against level</dc:title>"));
  // Drawn, the title would need the glyph of its capital F (U+0046), which no label or legend has.
  CHECK(occurrences(svg, "id=\"DejaVuSans-46\"") == 0);
  CHECK(occurrences(svg, "id=\"DejaVuSans-4c\"") == 1);  // the L of the x label: glyphs are defined
  CHECK(test::readText(stem + ".pdf").find("/FontFile2") != std::string::npos);  // TrueType embedded
}

TEST_CASE("Figure size: --figure-size takes column, page or W,H inches and names itself when it refuses", "[cpu]") {
  CHECK(parseFigureSize("page").width == 7.0);
  CHECK(parseFigureSize("page").height == 4.2);
  CHECK(parseFigureSize("5,3").width == 5.0);
  CHECK(parseFigureSize("5,3").height == 3.0);
  CHECK(parseFigureSize("").width == 0.0);  // each kind's default
  for (const char* bad : {"huge", "0,3", "5,3,1", "50,3", "5", "5;3"}) {
    INFO(bad);
    CHECK_THROWS_WITH(parseFigureSize(bad), Contains("--figure-size " + std::string(bad)));
  }
}
