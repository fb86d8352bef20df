#include "src/base/ResidentMemory.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace hemirad {

std::optional<ResidentMemory> residentMemory() {
  std::ifstream in("/proc/self/status");
  std::string line;
  ResidentMemory m;
  bool found = false;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    std::size_t kib = 0;
    if (!(fields >> key >> kib)) continue;
    if (key == "VmRSS:") m.bytes = kib * 1024, found = true;
    if (key == "VmHWM:") m.peakBytes = kib * 1024;
  }
  if (!found) return std::nullopt;
  return m;
}

std::string bytesPerUnit(std::size_t bytes, std::size_t elements, std::size_t triangles) {
  const double b = double(bytes);
  return fmt::format("{:.1f} MiB ({:.0f} bytes an element, {:.0f} a triangle)", b / (1 << 20),
                     elements ? b / double(elements) : 0.0, triangles ? b / double(triangles) : 0.0);
}

}  // namespace hemirad
