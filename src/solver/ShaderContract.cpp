#include "src/solver/ShaderContract.h"

#include <fmt/format.h>

#include "src/scene/Scene.h"
#include "src/solver/ShooterTree.h"

namespace hemirad {

const gl::Defines& contractDefines() {
  static const gl::Defines defines = [] {
    gl::Defines d = {
#define HEMIRAD_SLOT_DEFINE(name, number) {#name, #number},
        HEMIRAD_BINDING_SLOTS(HEMIRAD_SLOT_DEFINE)
#undef HEMIRAD_SLOT_DEFINE
    };
    d.push_back({"SHOOTER_SLOTS", fmt::format("{}u", kShooterSlots)});
    d.push_back({"MAX_SHAPE_VERTICES", fmt::format("{}", kMaxShapeVertices)});
    d.push_back({"SHAPE_STRIDE", fmt::format("{}u", kShapeStride)});
    d.push_back({"MAX_SPLIT_DEPTH", fmt::format("{}", kMaxSplitDepth)});
    d.push_back({"MAX_TEXEL_PIECES", fmt::format("{}u", kMaxTexelPieces)});
    d.push_back({"MAX_CAMERA_SAMPLES", fmt::format("{}", kMaxCameraSamples)});
    d.push_back({"SEGMENT_TOLERANCE", fmt::format("{}", kSegmentTolerance)});
    // Shortest round-trip text: the literals the shaders held before, so the same floats.
    d.push_back({"LUMINANCE",
                 fmt::format("vec3({}, {}, {})", kLuminanceWeights[0], kLuminanceWeights[1], kLuminanceWeights[2])});
    return d;
  }();
  return defines;
}

namespace {
gl::Defines withContract(const gl::Defines& defines) {
  gl::Defines all = contractDefines();
  all.insert(all.end(), defines.begin(), defines.end());
  return all;
}
}  // namespace

gl::Program computeProgram(const std::string& file, const gl::Defines& defines) {
  return gl::computeProgram(file, withContract(defines));
}

gl::Program renderProgram(const std::string& vertexFile, const std::string& fragmentFile, const gl::Defines& defines) {
  return gl::renderProgram(vertexFile, fragmentFile, withContract(defines));
}

}  // namespace hemirad
