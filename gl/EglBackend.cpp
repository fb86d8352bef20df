// EGL: a headless context on a GPU through EGL_EXT_platform_device, or Mesa's surfaceless
// platform (llvmpipe) as the fallback. libEGL is opened at run time, like libOSMesa.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <fmt/format.h>
#include "gl/GL.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "gl/ProgramPool.h"
#include "gl/StoragePool.h"

namespace hemirad::gl {

namespace {

struct EglApi {
  void* lib = nullptr;
  std::string error;  // why dlopen failed
  PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
  template <class F>
  F get(const char* name) const {
    void* p = lib ? dlsym(lib, name) : nullptr;
    if (!p && getProcAddress) p = reinterpret_cast<void*>(getProcAddress(name));
    return reinterpret_cast<F>(p);
  }
};

EglApi& api() {
  static EglApi a = [] {
    EglApi r;
    // HEMIRAD_EGL_LIBRARY names the library file to open instead (tests point it at nothing).
    const char* custom = std::getenv("HEMIRAD_EGL_LIBRARY");
    r.lib = dlopen(custom && *custom ? custom : "libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!r.lib) {
      const char* e = dlerror();
      r.error = custom && *custom ? fmt::format("cannot load HEMIRAD_EGL_LIBRARY={}: {}", custom, e ? e : "")
                                  : "libEGL.so.1 not found (install libegl1, or set HEMIRAD_EGL_LIBRARY)";
    }
    if (r.lib) r.getProcAddress = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(r.lib, "eglGetProcAddress"));
    return r;
  }();
  return a;
}

void* resolve(const char* name) { return reinterpret_cast<void*>(api().getProcAddress(name)); }

bool hasToken(const char* list, const char* token) {
  if (!list) return false;
  size_t n = std::strlen(token);
  for (const char* p = list; (p = std::strstr(p, token)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// Per EGL device, in the order EglBackend tries them, whether it is Mesa's software rasterizer
// (empty without libEGL or device enumeration).
std::vector<bool> eglDevicesSoftware() {
  const EglApi& a = api();
  if (!a.lib || !a.getProcAddress) return {};
  auto queryDevices = a.get<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto queryDeviceString = a.get<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (!queryDevices || !queryDeviceString) return {};
  EGLint count = 0;
  queryDevices(0, nullptr, &count);
  std::vector<EGLDeviceEXT> devices(count);
  queryDevices(count, devices.data(), &count);
  std::vector<bool> software;
  for (EGLint i = 0; i < count; ++i)
    software.push_back(hasToken(queryDeviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software"));
  return software;
}

class EglBackend final : public RenderBackend {
 public:
  EglBackend(const BackendOptions& options, bool hardwareOnly) {
    const EglApi& a = api();
    if (!a.lib) throw Error("egl: " + a.error);
    if (!a.getProcAddress) throw Error("egl: the EGL library has no eglGetProcAddress");
    auto getPlatformDisplay = a.get<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    auto queryDevices = a.get<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = a.get<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    initialize_ = a.get<PFNEGLINITIALIZEPROC>("eglInitialize");
    terminate_ = a.get<PFNEGLTERMINATEPROC>("eglTerminate");
    destroyContext_ = a.get<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    makeCurrent_ = a.get<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    if (!getPlatformDisplay || !initialize_) throw Error("egl: EGL_EXT_platform_base is missing");

    // Devices first: a real GPU is only reachable this way when there is no display server.
    if (queryDevices && queryDeviceString) {
      EGLint count = 0;
      queryDevices(0, nullptr, &count);
      std::vector<EGLDeviceEXT> devices(count);
      queryDevices(count, devices.data(), &count);
      for (EGLint i = 0; i < count && !display_; ++i) {
        bool software = hasToken(queryDeviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software");
        if (options.gpu >= 0 ? i != options.gpu : (software && hardwareOnly)) continue;
        tryDisplay(getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
      }
      if (options.gpu >= 0 && !display_)
        throw Error(fmt::format("egl: GPU {} not usable ({} EGL devices found)", options.gpu, count));
    }
    if (!display_ && hardwareOnly) throw Error("egl: no hardware EGL device");
    if (!display_) tryDisplay(getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    if (!display_) throw Error("egl: no EGL device or surfaceless display could be initialised");

    auto bindApi = a.get<PFNEGLBINDAPIPROC>("eglBindAPI");
    auto createContext = a.get<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    if (!bindApi(EGL_OPENGL_API)) throw Error("egl: desktop OpenGL is not supported");
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                              4,
                              EGL_CONTEXT_MINOR_VERSION,
                              5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG,
                              options.debug ? EGL_TRUE : EGL_FALSE,
                              EGL_NONE};
    // No config and no surface: rendering goes to FBOs (EGL_KHR_no_config_context, surfaceless_context).
    context_ = createContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context_ == EGL_NO_CONTEXT) {
      auto getError = a.get<PFNEGLGETERRORPROC>("eglGetError");
      EGLint code = getError ? getError() : 0;
      terminate_(display_);
      throw Error(fmt::format("egl: could not create a GL 4.5 core context (EGL error 0x{:04x})", code));
    }
    if (!makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      destroyContext_(display_, context_);
      terminate_(display_);
      throw Error("egl: could not make the context current (EGL_KHR_surfaceless_context missing?)");
    }
    loadFunctions(resolve, options.debug);
  }

  ~EglBackend() override {
    closeProgramPool();  // while the context is current
    closeStoragePool();
    makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    destroyContext_(display_, context_);
    terminate_(display_);
  }
  std::string name() const override { return "egl"; }

 private:
  void tryDisplay(EGLDisplay d) {
    EGLint major = 0, minor = 0;
    if (d != EGL_NO_DISPLAY && initialize_(d, &major, &minor)) display_ = d;
  }

  PFNEGLINITIALIZEPROC initialize_ = nullptr;
  PFNEGLTERMINATEPROC terminate_ = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroyContext_ = nullptr;
  PFNEGLMAKECURRENTPROC makeCurrent_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

bool rendersOnCpu(const BackendOptions& options) {
  if (options.kind == BackendKind::OSMesa) return true;
  const std::vector<bool> software = eglDevicesSoftware();
  if (options.gpu >= 0) return options.gpu >= int(software.size()) || software[std::size_t(options.gpu)];
  if (options.kind == BackendKind::Egl) return software.empty() || software.front();
  return std::find(software.begin(), software.end(), false) == software.end();  // auto: any hardware device
}

std::unique_ptr<RenderBackend> createEglBackend(const BackendOptions& options, bool hardwareOnly) {
  return std::make_unique<EglBackend>(options, hardwareOnly);
}

}  // namespace hemirad::gl
