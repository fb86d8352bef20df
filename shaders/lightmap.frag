// Plain bilinear sampling of the lightmap (GL_LINEAR, no masking): what engines do, so the
// gutters must hold the charts' own values. Alpha carries the surface id, for edge bands.
layout(binding = SAMPLER_LIGHTMAP) uniform sampler2D lightmap;
in vec2 vUv;
flat in uint vSurface;
layout(location = 0) out vec4 color;

void main() { color = vec4(texture(lightmap, vUv).rgb, float(vSurface)); }
