#include "src/output/CameraTarget.h"

#include <fmt/format.h>

#include <algorithm>

#include "gl/Backend.h"
#include "gl/State.h"
#include "src/output/Supersample.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {

gl::Texture cameraTexture(GLenum format, int width, int height, int samples) {
  if (samples > 1) return gl::Texture(format, width, height, gl::Texture::Samples{samples});
  return gl::Texture(format, width, height);
}

}  // namespace

CameraTarget::CameraTarget(int width, int height, int samples)
    : color_(cameraTexture(GL_RGBA32F, width, height, samples)),
      depth_(cameraTexture(GL_DEPTH_COMPONENT32F, width, height, samples)) {
  fbo_.attach(GL_COLOR_ATTACHMENT0, color_);
  fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
  fbo_.checkComplete("camera");
  if (color_.samples() == 1) return;
  if (color_.samples() > kMaxCameraSamples || (color_.samples() & (color_.samples() - 1)))
    throw gl::Error(
        fmt::format("camera: the driver gave {} samples a pixel for {} (resolve.comp sums a power of two "
                    "up to {})",
                    color_.samples(), samples, kMaxCameraSamples));
  resolved_.emplace(GL_RGBA32F, width, height);
  resolve_.emplace(computeProgram("resolve.comp"));
}

CameraPlan cameraPlan(int width, int height, int supersample, int samples, int maxTextureSize) {
  const int n = std::max(1, supersample);
  const std::size_t all = std::size_t(width) * n * std::size_t(height) * n * std::size_t(std::max(1, samples));
  if (samples > 1 && all <= CameraPlan::kMaxSamples && std::max(width, height) * n <= maxTextureSize)
    return {n, samples};
  return {SupersampleGrid(n).scale(), 1};
}

void CameraTarget::clearAndBind() {
  fbo_.clearColor(0, 0, 0, 1);
  fbo_.clearDepth(0.0f);
  fbo_.bind();
}

void CameraTarget::read(std::vector<float>& rgba) {
  rgba.resize(std::size_t(color_.width()) * color_.height() * 4);
  if (!resolved_) {
    color_.read(GL_RGBA, GL_FLOAT, rgba.size() * sizeof(float), rgba.data());
    return;
  }
  color_.bindUnit(slot::SAMPLER_MULTISAMPLE);
  resolved_->bindImage(slot::IMAGE_RESOLVED, GL_WRITE_ONLY);
  resolve_->set("sampleCount", color_.samples());
  resolve_->use();
  gl::Program::dispatch(unsigned(color_.width() + 7) / 8, unsigned(color_.height() + 7) / 8);
  gl::barrier(gl::Barrier::TextureUpdate);
  resolved_->read(GL_RGBA, GL_FLOAT, rgba.size() * sizeof(float), rgba.data());
}

}  // namespace hemirad
