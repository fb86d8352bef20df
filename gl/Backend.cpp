#include "gl/Backend.h"
#include "gl/ProgramPool.h"
#include "gl/StoragePool.h"

#include <fmt/format.h>

#include <cstdio>

#include "gl/Debug.h"
#include "gl/GL.h"
#include "gl/Limits.h"

namespace hemirad::gl {

namespace {
std::string glString(GLenum e) {
  const GLubyte* s = glGetString(e);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

std::string RenderBackend::renderer() const { return glString(GL_RENDERER); }
std::string RenderBackend::version() const { return glString(GL_VERSION); }
bool RenderBackend::software() const { return softwareRenderer(); }
bool softwareRenderer() {
  const std::string r = glString(GL_RENDERER);
  return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos;
}
void RenderBackend::finish() const { glFinish(); }
int RenderBackend::maxTextureSize() const {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

std::optional<double> RenderBackend::freeMemoryMiB() const {
  constexpr GLenum kCurrentAvailableVidmemNVX = 0x9049;  // GL_NVX_gpu_memory_info, in KiB
  GLint extensions = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &extensions);
  for (GLint i = 0; i < extensions; ++i)
    if (std::string(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)))) ==
        "GL_NVX_gpu_memory_info") {
      GLint kib = 0;
      glGetIntegerv(kCurrentAvailableVidmemNVX, &kib);
      return kib / 1024.0;
    }
  return std::nullopt;
}

void RenderBackend::loadFunctions(void* (*resolve)(const char*), bool debug) {
  int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(resolve));
  if (version == 0) throw Error(fmt::format("{}: could not load GL functions", name()));
  int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
  if (major * 10 + minor < 45)
    throw Error(fmt::format("{}: GL {}.{} found, hemirad needs GL 4.5 core", name(), major, minor));
  forgetLimits();  // another context may be another driver
  openProgramPool();
  openStoragePool();
  if (debug) enableDebugOutput();
}

BackendKind parseBackendKind(const std::string& name) {
  if (name == "osmesa") return BackendKind::OSMesa;
  if (name == "egl") return BackendKind::Egl;
  if (name == "auto") return BackendKind::Auto;
  throw Error(fmt::format("unknown backend '{}' (osmesa, egl or auto)", name));
}

std::unique_ptr<RenderBackend> createBackend(const BackendOptions& options) {
  switch (options.kind) {
    case BackendKind::OSMesa:
      return createOSMesaBackend(options);
    case BackendKind::Egl:
      return createEglBackend(options, false);
    case BackendKind::Auto:
      // A hardware EGL device when there is one, else the software path, saying why.
      try {
        return createEglBackend(options, true);
      } catch (const Error& e) {
        std::fprintf(stderr, "hemirad: warning: --backend auto: %s; falling back to osmesa\n", e.what());
        return createOSMesaBackend(options);
      }
  }
  throw Error("unreachable backend kind");
}

}  // namespace hemirad::gl
