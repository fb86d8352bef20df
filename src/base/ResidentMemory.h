// This process's resident memory (Linux /proc/self/status): now (VmRSS) and its peak (VmHWM),
// which info and bench report per element and per triangle.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

namespace hemirad {

struct ResidentMemory {
  std::size_t bytes = 0, peakBytes = 0;
};
// nullopt where /proc/self/status has no VmRSS line (not Linux).
std::optional<ResidentMemory> residentMemory();

// "12.3 MiB (1,234 bytes an element, 56 a triangle)": a footprint per unit of the scene.
std::string bytesPerUnit(std::size_t bytes, std::size_t elements, std::size_t triangles);

}  // namespace hemirad
