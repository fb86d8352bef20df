#include "gl/Limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "gl/Backend.h"
#include "gl/GL.h"

namespace hemirad::gl {

namespace {

std::optional<Limits> cached;
unsigned testCap = 0;

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) { return (a + b - 1) / b; }

// A layer of `groups` groups as x by y, y as small as the x limit allows, x then as small as
// y allows (fewer than y groups left idle).
Grid layer(std::uint64_t groups, unsigned maxX) {
  Grid g;
  g.y = unsigned(ceilDiv(groups, maxX));
  g.x = unsigned(ceilDiv(groups, g.y));
  return g;
}

}  // namespace

const Limits& limits() {
  if (!cached) {
    Limits l;
    for (GLuint i = 0; i < 3; ++i) {
      GLint n = 0;
      glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &n);
      l.workGroupCount[i] = unsigned(std::max(n, 1));
    }
    GLint64 block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    l.storageBlockBytes = std::size_t(std::max<GLint64>(block, 0));
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &l.textureSize);
    GLint color = 1, depth = 1;  // GL_SAMPLES lists the counts largest first
    glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA32F, GL_SAMPLES, 1, &color);
    glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, GL_DEPTH_COMPONENT32F, GL_SAMPLES, 1, &depth);
    l.cameraSamples = std::max(1, std::min(color, depth));
    cached = l;
  }
  return *cached;
}

void forgetLimits() { cached.reset(); }

void limitWorkGroupCount(unsigned perDimension) { testCap = perDimension; }

Grid tiledGrid(std::uint64_t groups) {
  const Limits& l = limits();
  unsigned most[3];
  for (int i = 0; i < 3; ++i) most[i] = testCap ? std::min(testCap, l.workGroupCount[i]) : l.workGroupCount[i];
  if (groups == 0) return {0, 1, 1};
  const std::uint64_t perLayer = std::uint64_t(most[0]) * most[1];
  const std::uint64_t layers = ceilDiv(groups, perLayer);
  if (layers > most[2])
    throw Error(fmt::format("{} workgroups are more than the GPU's {} x {} x {} (GL_MAX_COMPUTE_WORK_GROUP_COUNT)",
                            groups, most[0], most[1], most[2]));
  Grid g = layer(ceilDiv(groups, layers), most[0]);
  g.z = unsigned(layers);
  return g;
}

void dispatchLinear(std::uint64_t groups) {
  const Grid g = tiledGrid(groups);
  if (g.x) glDispatchCompute(g.x, g.y, g.z);
}

void requireStorageBlock(std::size_t bytes, const std::string& what) {
  const std::size_t most = limits().storageBlockBytes;
  if (bytes > most)
    throw Error(
        fmt::format("{} needs {} bytes in one shader storage block, over the GPU's "
                    "GL_MAX_SHADER_STORAGE_BLOCK_SIZE of {} ({:.1f} MiB)",
                    what, bytes, most, most / 1048576.0));
}

}  // namespace hemirad::gl
