// RenderBackend: where a headless GL 4.5 core context comes from. The solver above it is
// the same GL code on every backend; backends differ only in how the context is made and
// where the GL function pointers are resolved (Filament's Platform split).
#pragma once
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace hemirad::gl {

// Anything GL could not do: no context, no library, shader build failure, GL error.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class BackendKind { OSMesa, Egl, Auto };

struct BackendOptions {
  BackendKind kind = BackendKind::OSMesa;
  int gpu = -1;        // EGL device index; -1 picks the first hardware device
  bool debug = false;  // KHR_debug context with synchronous error output
};

// The current context's renderer is a CPU rasterizer (what RenderBackend::software() asks).
bool softwareRenderer();

class RenderBackend {
 public:
  virtual ~RenderBackend() = default;
  RenderBackend(const RenderBackend&) = delete;
  RenderBackend& operator=(const RenderBackend&) = delete;

  virtual std::string name() const = 0;  // "osmesa" or "egl"
  std::string renderer() const;          // GL_RENDERER
  std::string version() const;           // GL_VERSION
  // A CPU rasterizer (Mesa's llvmpipe or softpipe): no clocks that ramp, no device memory.
  bool software() const;
  // Blocks until the GPU has finished all submitted work.
  void finish() const;
  int maxTextureSize() const;  // GL_MAX_TEXTURE_SIZE
  // Free device memory in MiB where the driver says (NVIDIA's GL_NVX_gpu_memory_info), else
  // nullopt (llvmpipe): the bench reports what a solve holds as the drop across it.
  std::optional<double> freeMemoryMiB() const;

 protected:
  RenderBackend() = default;
  // Fills glad's pointers from `resolve` and checks for GL 4.5 core; call after make-current.
  void loadFunctions(void* (*resolve)(const char*), bool debug);
};

// One backend is live per process at a time: glad's function table is global.
std::unique_ptr<RenderBackend> createBackend(const BackendOptions& options);
std::unique_ptr<RenderBackend> createOSMesaBackend(const BackendOptions& options);
std::unique_ptr<RenderBackend> createEglBackend(const BackendOptions& options, bool hardwareOnly);

BackendKind parseBackendKind(const std::string& name);  // throws Error for unknown names
// Whether createBackend(options) will rasterize on the CPU (llvmpipe), told from the EGL device
// list without making a context: osmesa always; egl where the device it tries first (--gpu's) is
// Mesa's software one or none is listed; auto where no hardware device is listed.
bool rendersOnCpu(const BackendOptions& options);

}  // namespace hemirad::gl
