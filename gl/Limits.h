// The driver's per-call limits that grow with a scene, queried once per context, and the ways
// to stay within them: a 1D workgroup count tiled over a 2D/3D grid (GL 4.5 promises only
// 65,535 groups a dimension), and storage blocks checked before work with one clear error.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace hemirad::gl {

struct Limits {
  unsigned workGroupCount[3] = {0, 0, 0};  // GL_MAX_COMPUTE_WORK_GROUP_COUNT
  std::size_t storageBlockBytes = 0;       // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  int textureSize = 0;                     // GL_MAX_TEXTURE_SIZE
  int cameraSamples = 1;  // the most samples of an RGBA32F and a DEPTH_COMPONENT32F multisample texture
};

// Queried at the first call after a backend loads its functions (needs a current context).
const Limits& limits();
void forgetLimits();  // a new context: query again

struct Grid {
  unsigned x = 1, y = 1, z = 1;
};
// The smallest near-square grid of at least `groups` groups within the limits; throws Error when
// even the full 3D grid cannot hold them.
Grid tiledGrid(std::uint64_t groups);
// Dispatches `groups` workgroups of a 1D count (the program must be in use). The shader takes
// its index from linearGroup() (shaders/linear_group.glsl) and skips groups past the count.
void dispatchLinear(std::uint64_t groups);
// Tests: caps each grid dimension at `perDimension` (0: the driver's), so small scenes tile.
void limitWorkGroupCount(unsigned perDimension);

// Throws Error naming `what` when `bytes` exceed one shader storage block.
void requireStorageBlock(std::size_t bytes, const std::string& what);

}  // namespace hemirad::gl
