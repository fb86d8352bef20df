#include "src/output/PlyWriter.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Image.h"

namespace hemirad {

namespace {
struct PlyVertex {
  float x, y, z;
  unsigned char r, g, b;
  float br, bg, bb;
};
}  // namespace

std::string encodePly(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B, double scale) {
  std::vector<PlyVertex> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
  // Corners shared by neighbouring cuts agree to rounding; weld them on a fine grid.
  std::map<std::pair<std::uint32_t, std::array<long long, 3>>, std::uint32_t> welded;
  const double quantum = atlas.texelSize * 1e-6;
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      std::uint32_t polygon = atlas.polygonOf[size_t(y) * atlas.width + x];
      if (polygon == kNoPolygon) continue;
      const std::uint32_t chart = atlas.chartOf[polygon];
      for (const Poly3& piece : atlas.elementShape(scene, x, y)) {  // a face per piece
        std::vector<std::uint32_t> face;
        for (const glm::dvec3& p : piece) {
          auto key =
              std::make_pair(chart, std::array<long long, 3>{std::llround(p.x / quantum), std::llround(p.y / quantum),
                                                             std::llround(p.z / quantum)});
          auto [it, added] = welded.try_emplace(key, std::uint32_t(vertices.size()));
          if (added) {
            glm::vec3 b = atlas.sample(B, int(polygon), atlas.atlasCoord(int(polygon), p));
            Image one{1, 1, {b.x, b.y, b.z}};
            std::vector<unsigned char> c = toneMap(one, scale);
            const glm::dvec3 at = p / scene.unitScale;  // in the file's units
            vertices.push_back({float(at.x), float(at.y), float(at.z), c[0], c[1], c[2], b.x, b.y, b.z});
          }
          if (face.empty() || face.back() != it->second) face.push_back(it->second);
        }
        if (face.size() >= 3) faces.push_back(std::move(face));
      }
    }

  std::ostringstream out;
  out << "ply\nformat binary_little_endian 1.0\ncomment hemirad radiosity solution\n"
      << "element vertex " << vertices.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property float radiosity_r\nproperty float radiosity_g\nproperty float radiosity_b\n"
      << "element face " << faces.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
  for (const PlyVertex& v : vertices) {
    out.write(reinterpret_cast<const char*>(&v.x), 12);
    out.write(reinterpret_cast<const char*>(&v.r), 3);
    out.write(reinterpret_cast<const char*>(&v.br), 12);
  }
  for (const auto& f : faces) {
    unsigned char n = static_cast<unsigned char>(f.size());
    out.write(reinterpret_cast<const char*>(&n), 1);
    out.write(reinterpret_cast<const char*>(f.data()), std::streamsize(f.size() * 4));
  }
  return std::move(out).str();
}

void writePly(const std::string& path, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
              double scale) {
  writeFileBytes(path, encodePly(scene, atlas, B, scale));
}

}  // namespace hemirad
