// The polygon id, and (hemisphere only) the exact distance along the pixel-centre ray to the polygon's plane as
// depth (distance / far): the vertex shader's depth is interpolated linearly over item-mesh
// triangles, which under-estimates a curved projection's distances by far more than the gap
// between, say, a ceiling and a light hung 0.5 mm below it. Exact depths order such surfaces
// right in every pixel. Needs the polygon planes (SSBO_PLANES: unit normal, offset n . p).
#include "hemisphere.glsl"
#include "control.glsl"

flat in uint vPolygon;
flat in int vLayer;
layout(location = 0) out uint itemId;
layout(std430, binding = SSBO_PLANES) readonly buffer Planes { vec4 plane[]; };
uniform float farDistance;
uniform float faceSize;  // pixels on a side

void main() {
  itemId = vPolygon;
#ifndef HEMICUBE  // the hemicube's interpolated depth is exact (hemisphere.glsl)
  uint shooter = uint(vLayer / ITEM_FACES);
  vec3 o = control.shooter[shooter].positionArea.xyz, n = control.shooter[shooter].normal.xyz;
  vec3 l = itemDirection(gl_FragCoord.xy / faceSize * 2.0 - 1.0, vLayer % ITEM_FACES);
  vec3 t, b;
  shooterBasis(n, t, b);
  vec3 d = l.x * t + l.y * b + l.z * n;
  vec4 p = plane[vPolygon];
  float along = dot(p.xyz, d), distance = (p.w - dot(p.xyz, o)) / along * length(d);
  // A ray (nearly) parallel to the plane, or a pixel centre beyond the triangle's reach: keep
  // the interpolated depth.
  gl_FragDepth = along != 0.0 && distance > 0.0 && distance < farDistance ? distance / farDistance : gl_FragCoord.z;
#endif
}
