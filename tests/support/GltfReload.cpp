#include "tests/support/GltfReload.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <glm/gtc/quaternion.hpp>

#include "src/scene/Scene.h"  // luminance

namespace hemirad::test {

namespace {

bool noImages(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// Accessor `index` as `count` x `components` values of type T (tightly packed or strided).
template <class T>
std::vector<T> read(const tinygltf::Model& m, int index, int components) {
  const tinygltf::Accessor& a = m.accessors.at(std::size_t(index));
  const tinygltf::BufferView& v = m.bufferViews.at(std::size_t(a.bufferView));
  const std::size_t stride = v.byteStride ? v.byteStride : sizeof(T) * std::size_t(components);
  const unsigned char* base = m.buffers.at(std::size_t(v.buffer)).data.data() + v.byteOffset + a.byteOffset;
  std::vector<T> out(a.count * std::size_t(components));
  for (std::size_t i = 0; i < a.count; ++i)
    std::memcpy(&out[i * std::size_t(components)], base + i * stride, sizeof(T) * std::size_t(components));
  return out;
}

void addPrimitive(const tinygltf::Model& m, const tinygltf::Primitive& p, std::uint32_t& surfaces, ReloadedGltf& out) {
  REQUIRE(p.attributes.count("TEXCOORD_1"));
  REQUIRE(m.accessors.at(std::size_t(p.indices)).componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  const std::vector<float> position = read<float>(m, p.attributes.at("POSITION"), 3);
  const std::vector<float> uv = read<float>(m, p.attributes.at("TEXCOORD_1"), 2);
  const std::vector<std::uint32_t> indices = read<std::uint32_t>(m, p.indices, 1);
  std::uint32_t top = 0;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    // A fan a b c, a c d, ... shares its first vertex, the least index of each of its triangles.
    const std::uint32_t fan = std::min({indices[t], indices[t + 1], indices[t + 2]});
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = indices[t + std::size_t(k)];
      out.triangles.push_back(
          {{position[i * 3], position[i * 3 + 1], position[i * 3 + 2]}, {uv[i * 2], uv[i * 2 + 1]}, surfaces + fan});
    }
    top = std::max(top, fan + 1);
  }
  surfaces += top;
}

Camera camera(const tinygltf::Model& m, double& aspect) {
  for (const tinygltf::Node& n : m.nodes) {
    if (n.camera < 0) continue;
    const tinygltf::Camera& c = m.cameras.at(std::size_t(n.camera));
    REQUIRE(c.type == "perspective");
    REQUIRE((c.perspective.znear > 0 && c.perspective.zfar > c.perspective.znear));  // a valid glTF camera
    REQUIRE(n.translation.size() == 3);
    REQUIRE(n.rotation.size() == 4);
    const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
    Camera cam;
    cam.eye = {n.translation[0], n.translation[1], n.translation[2]};
    cam.target = cam.eye + q * glm::dvec3(0, 0, -1);  // glTF cameras look down their -z
    cam.up = q * glm::dvec3(0, 1, 0);
    cam.fovY = glm::degrees(c.perspective.yfov);
    aspect = c.perspective.aspectRatio;
    return cam;
  }
  FAIL("no camera node");
  return {};
}

}  // namespace

ReloadedGltf reloadGltf(const std::string& path) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(noImages, nullptr);
  tinygltf::Model m;
  std::string err, warning;
  INFO(err);
  REQUIRE(loader.LoadBinaryFromFile(&m, &err, &warning, path));
  ReloadedGltf out;
  std::uint32_t surfaces = 0;
  for (const tinygltf::Mesh& mesh : m.meshes)
    for (const tinygltf::Primitive& p : mesh.primitives) addPrimitive(m, p, surfaces, out);
  out.camera = camera(m, out.aspect);
  REQUIRE(m.textures.size() == 1);
  const tinygltf::Image& image = m.images.at(std::size_t(m.textures[0].source));
  out.imageUri = image.uri;
  if (image.bufferView >= 0) {
    const tinygltf::BufferView& v = m.bufferViews.at(std::size_t(image.bufferView));
    const auto& data = m.buffers.at(std::size_t(v.buffer)).data;
    REQUIRE(v.byteOffset + v.byteLength <= data.size());
    out.embeddedImage.assign(data.begin() + std::ptrdiff_t(v.byteOffset),
                             data.begin() + std::ptrdiff_t(v.byteOffset + v.byteLength));
  }
  const tinygltf::Sampler& s = m.samplers.at(std::size_t(m.textures[0].sampler));
  out.samplerFilter = s.minFilter == s.magFilter ? s.magFilter : -1;
  out.samplerWrap = s.wrapS == s.wrapT ? s.wrapS : -1;
  for (const tinygltf::Material& mat : m.materials) {
    out.emissiveTexCoords.push_back(mat.emissiveTexture.index == 0 ? mat.emissiveTexture.texCoord : -1);
    const auto& c = mat.pbrMetallicRoughness.baseColorFactor;
    out.baseColorSums.push_back(c[0] + c[1] + c[2]);
  }
  return out;
}

Bands bandLuminance(const Image& image, const std::vector<int>& surface) {
  const int w = image.width, h = image.height;
  auto lum = [&](std::size_t p) {
    return luminance(glm::dvec3(image.rgb[p * 3], image.rgb[p * 3 + 1], image.rgb[p * 3 + 2]));
  };
  auto at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h ? surface[std::size_t(y) * w + std::size_t(x)] : -3;
  };
  // An edge pixel: its samples saw two surfaces, or (one sample a pixel) a neighbour sees another.
  std::vector<char> edge(surface.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int s = at(x, y), n[4] = {at(x + 1, y), at(x - 1, y), at(x, y + 1), at(x, y - 1)};
      edge[std::size_t(y) * w + std::size_t(x)] =
          s == -1 || std::any_of(n, n + 4, [&](int o) { return o != s && o != -3; });
    }
  auto edgeWithin = [&](int x, int y, int r) {  // an edge pixel at chessboard distance <= r
    for (int j = -r; j <= r; ++j)
      for (int i = -r; i <= r; ++i)
        if (at(x + i, y + j) != -3 && edge[std::size_t(y + j) * w + std::size_t(x + i)]) return true;
    return false;
  };
  double sum[3] = {0, 0, 0};
  int n[3] = {0, 0, 0};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * w + std::size_t(x);
      if (surface[p] == -2) continue;
      const int set = edge[p] ? 0 : edgeWithin(x, y, 1) ? 1 : edgeWithin(x, y, 2) ? 3 : 2;
      if (set == 3) continue;  // between the 2-pixel band and the interior
      for (int s = set; s <= (set == 0 ? 1 : set); ++s) sum[s] += lum(p), ++n[s];
    }
  return {n[0] ? sum[0] / n[0] : 0, n[1] ? sum[1] / n[1] : 0, n[2] ? sum[2] / n[2] : 0};
}

}  // namespace hemirad::test
