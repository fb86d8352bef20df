// OSMesa: Mesa's llvmpipe in-process, the deterministic default. libOSMesa is opened at run
// time so the same binary also runs where it is absent (the GPU machine).
#include "gl/GL.h"
// glad first: its include guard keeps osmesa.h's <GL/gl.h> from declaring real gl* symbols.
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <fmt/format.h>

#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "gl/ProgramPool.h"
#include "gl/StoragePool.h"

namespace hemirad::gl {

namespace {

struct OSMesaApi {
  void* lib = nullptr;
  std::string error;  // why dlopen failed
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

OSMesaApi& api() {
  static OSMesaApi a = [] {
    OSMesaApi r;
    // HEMIRAD_OSMESA_LIBRARY names the library file to open instead (tests point it at nothing).
    const char* custom = std::getenv("HEMIRAD_OSMESA_LIBRARY");
    std::vector<std::string> names{"libOSMesa.so.8", "libOSMesa.so"};
    if (custom && *custom) names = {custom};
    for (const auto& name : names) {
      if ((r.lib = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL))) break;
      const char* e = dlerror();
      if (r.error.empty() && e) r.error = e;
    }
    if (!r.lib) {
      r.error = custom && *custom ? fmt::format("cannot load HEMIRAD_OSMESA_LIBRARY={}: {}", custom, r.error)
                                  : "libOSMesa.so.8 not found (install libosmesa6, or set HEMIRAD_OSMESA_LIBRARY)";
      return r;
    }
    r.createContextAttribs =
        reinterpret_cast<decltype(r.createContextAttribs)>(dlsym(r.lib, "OSMesaCreateContextAttribs"));
    r.makeCurrent = reinterpret_cast<decltype(r.makeCurrent)>(dlsym(r.lib, "OSMesaMakeCurrent"));
    r.destroyContext = reinterpret_cast<decltype(r.destroyContext)>(dlsym(r.lib, "OSMesaDestroyContext"));
    r.getProcAddress = reinterpret_cast<decltype(r.getProcAddress)>(dlsym(r.lib, "OSMesaGetProcAddress"));
    return r;
  }();
  return a;
}

void* resolve(const char* name) { return reinterpret_cast<void*>(api().getProcAddress(name)); }

class OSMesaBackend final : public RenderBackend {
 public:
  explicit OSMesaBackend(const BackendOptions& options) {
    OSMesaApi& a = api();
    if (!a.lib) throw Error("osmesa: " + a.error);
    if (!a.createContextAttribs || !a.makeCurrent || !a.destroyContext || !a.getProcAddress)
      throw Error("osmesa: libOSMesa lacks OSMesaCreateContextAttribs (Mesa too old)");
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    context_ = a.createContextAttribs(attribs, nullptr);
    if (!context_) throw Error("osmesa: could not create a GL 4.5 core context");
    // All rendering goes to FBOs; the default framebuffer is a 1x1 placeholder.
    if (!a.makeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      a.destroyContext(context_);
      throw Error("osmesa: could not make the context current");
    }
    loadFunctions(resolve, options.debug);
  }
  ~OSMesaBackend() override {
    closeProgramPool();  // while the context is current
    closeStoragePool();
    api().destroyContext(context_);
  }
  std::string name() const override { return "osmesa"; }

 private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> pixel_{};
};

}  // namespace

std::unique_ptr<RenderBackend> createOSMesaBackend(const BackendOptions& options) {
  return std::make_unique<OSMesaBackend>(options);
}

}  // namespace hemirad::gl
