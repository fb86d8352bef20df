// A lightmapped mesh as an engine draws it: position and the lightmap's TEXCOORD_1.
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 lightmapUv;
layout(location = 2) in uint surface;
uniform mat4 viewProjection;
out vec2 vUv;
flat out uint vSurface;

void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vUv = lightmapUv;
  vSurface = surface;
}
