# `cmake --install build --prefix P` (docs/install.md): bin/hemirad and bin/hemirad-bench, the headers
# under include/hemirad (included as "src/scene/SceneLoader.h", as inside hemirad), the pipeline's
# static libraries, find_package(hemirad) (hemirad::hemirad) and pkg-config (hemirad.pc), and
# share/hemirad: the scenes (bench's and experiment's defaults) and the plotting script.
# The command-line front end (cli/) and the GLFW viewer stay inside the binary.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HEMIRAD_EXPORTED base scene solver output output_files options bench validate walk walk_files sweep)
set(_targets hemirad_gl hemirad_cpu glad_gl hemirad_shaders)
foreach(l ${HEMIRAD_EXPORTED})
  list(APPEND _targets hemirad_${l})
endforeach()
foreach(t ${_targets})  # hemirad::scene, hemirad::solver, ... (hemirad::glad_gl for the loader)
  string(REGEX REPLACE "^hemirad_" "" _name ${t})
  set_target_properties(${t} PROPERTIES EXPORT_NAME ${_name})
endforeach()

# hemirad::hemirad: the whole library (every exported part), C++20 like hemirad itself.
add_library(hemirad_library INTERFACE)
target_link_libraries(hemirad_library INTERFACE hemirad_output_files hemirad_bench hemirad_validate hemirad_walk_files
                                                hemirad_sweep)
target_compile_features(hemirad_library INTERFACE cxx_std_20)
set_target_properties(hemirad_library PROPERTIES EXPORT_NAME hemirad)

install(TARGETS hemirad hemirad-bench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS hemirad_library ${_targets} EXPORT hemiradTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hemirad)
install(DIRECTORY src gl cpu DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hemirad FILES_MATCHING PATTERN "*.h"
        PATTERN "cli" EXCLUDE PATTERN "viewer" EXCLUDE)
install(DIRECTORY ${GLAD_OUT}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hemirad)
install(DIRECTORY scenes DESTINATION ${CMAKE_INSTALL_DATADIR}/hemirad)
install(FILES python/plot.py DESTINATION ${CMAKE_INSTALL_DATADIR}/hemirad/python)

set(_cmakedir ${CMAKE_INSTALL_LIBDIR}/cmake/hemirad)
install(EXPORT hemiradTargets NAMESPACE hemirad:: DESTINATION ${_cmakedir})
configure_package_config_file(cmake/hemiradConfig.cmake.in ${CMAKE_BINARY_DIR}/hemiradConfig.cmake
                              INSTALL_DESTINATION ${_cmakedir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/hemiradConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/hemiradConfig.cmake ${CMAKE_BINARY_DIR}/hemiradConfigVersion.cmake
              cmake/hemiradDependencies.cmake DESTINATION ${_cmakedir})

# pkg-config: the same libraries, in link order, then the Debian packages they need.
set(HEMIRAD_PC_LIBS "")
foreach(l sweep walk_files walk validate bench options output_files output solver cpu gl scene base)
  string(APPEND HEMIRAD_PC_LIBS " -lhemirad_${l}")
endforeach()
string(APPEND HEMIRAD_PC_LIBS " -lglad_gl -lhemirad_shaders")
file(RELATIVE_PATH HEMIRAD_PC_UP /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)  # ../.. from lib/pkgconfig
string(REGEX REPLACE "/$" "" HEMIRAD_PC_UP "${HEMIRAD_PC_UP}")
configure_file(cmake/hemirad.pc.in ${CMAKE_BINARY_DIR}/hemirad.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/hemirad.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
