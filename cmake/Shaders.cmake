# Shaders stay real files in shaders/; the build embeds them so one binary runs anywhere
# (the GPU machine has no source tree). gl/Shader.cpp resolves #include between them.
file(GLOB HEMIRAD_SHADER_FILES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*)
string(REPLACE ";" "|" HEMIRAD_SHADER_LIST "${HEMIRAD_SHADER_FILES}")
set(HEMIRAD_SHADERS_CPP ${CMAKE_BINARY_DIR}/generated/EmbeddedShaders.cpp)
add_custom_command(
  OUTPUT ${HEMIRAD_SHADERS_CPP}
  COMMAND ${CMAKE_COMMAND} -DOUT=${HEMIRAD_SHADERS_CPP} "-DFILES=${HEMIRAD_SHADER_LIST}"
          -P ${CMAKE_SOURCE_DIR}/cmake/EmbedShaders.cmake
  DEPENDS ${HEMIRAD_SHADER_FILES} ${CMAKE_SOURCE_DIR}/cmake/EmbedShaders.cmake
  COMMENT "Embedding shaders"
  VERBATIM)
add_library(hemirad_shaders STATIC ${HEMIRAD_SHADERS_CPP})
target_include_directories(hemirad_shaders PUBLIC $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}>)
