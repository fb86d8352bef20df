# What hemirad's libraries link: found by the build (CMakeLists.txt) and, installed next to
# hemiradConfig.cmake, by every find_package(hemirad) (Debian 12 packages, ci/setup).
find_package(OpenMesh REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(OpenEXR REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(fmt REQUIRED)
find_package(glm REQUIRED)
find_package(Threads REQUIRED)
find_package(CGAL REQUIRED)
find_package(Eigen3 3.3 REQUIRED)  # CGAL's FindEigen3; for its LSCM (src/scene/Lscm.cpp)
include(CGAL_Eigen3_support)
find_package(TBB REQUIRED)
find_package(embree 3 REQUIRED)  # a CPU device's traced visibility (src/solver/HostTrace.h)
find_package(PkgConfig REQUIRED)
pkg_check_modules(stb REQUIRED IMPORTED_TARGET stb)  # stb_rect_pack, stb_image(_write) (libstb-dev)

