# glad2 (Debian python3-glad) generates a GL 4.5 core loader that takes a custom resolver,
# so each backend fills it from OSMesaGetProcAddress or eglGetProcAddress (docs/design.md#gl-loading:
# epoxy and GLEW fail under OSMesa).
find_program(SYSTEM_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${GLAD_OUT}/src/gl.c ${GLAD_OUT}/include/glad/gl.h
  COMMAND ${SYSTEM_PYTHON3} -m glad --quiet --reproducible --api gl:core=4.5
          --extensions GL_KHR_debug --out-path ${GLAD_OUT} c
  COMMENT "Generating the glad GL 4.5 core loader")
add_library(glad_gl STATIC ${GLAD_OUT}/src/gl.c)
target_include_directories(glad_gl SYSTEM PUBLIC $<BUILD_INTERFACE:${GLAD_OUT}/include>)
set_target_properties(glad_gl PROPERTIES POSITION_INDEPENDENT_CODE ON)
