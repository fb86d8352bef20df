// What loading a scene repaired or skipped, and how it is printed: warnings of one kind (87,432
// non-planar faces) become one line with their count and first places, and the lines are capped,
// so a big model's warnings stay readable. Every command that prints scene warnings goes through
// printWarnings (or warningLines, for `info`).
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hemirad {

struct SceneWarning {
  SceneWarning(std::string where, std::string message, std::string counted = "faces", std::string kind = "")
      : where(std::move(where)), message(std::move(message)), counted(std::move(counted)), kind(std::move(kind)) {}
  std::string where;    // "s.obj:7", "m.mtl:4", "s.gltf: mesh 0 primitive 1 triangle 5"
  std::string message;  // "non-planar polygon split into triangles"
  std::string counted;  // what a group of them counts: "3,720 faces: ..."
  std::string kind;     // what warnings of one sort share, when the message names its material ("": message)
  std::string text() const { return where.empty() ? message : where + ": " + message; }
  const std::string& group() const { return kind.empty() ? message : kind; }
};

constexpr std::size_t kWarningPlaces = 3;  // a kind seen this often or less prints each warning
constexpr std::size_t kWarningLines = 20;  // at most this many lines, the last one counting the rest

// The lines to print, in order of each kind's first warning: a kind seen up to kWarningPlaces times
// as its warnings, more as "3,720 faces: MESSAGE (first at A, B, C, ...)".
std::vector<std::string> warningLines(const std::vector<SceneWarning>& warnings);
// Prints warningLines, each as `hemirad: warning: LINE`.
void printWarnings(const std::vector<SceneWarning>& warnings);

std::string withThousands(std::size_t n);  // 87432 -> "87,432"

}  // namespace hemirad
