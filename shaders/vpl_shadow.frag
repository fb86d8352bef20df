// The nearest polygon's id and its exact distance along the pixel-centre ray (distance / far),
// as itembuffer.frag: interpolated depths under the curved projection err by more than a
// shadow test can allow.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "vpl.glsl"

flat in uint vPolygon;
flat in uint vVpl;
layout(location = 0) out uint itemId;
uniform float farDistance;
uniform float faceSize;

void main() {
  itemId = vPolygon;
  vec3 o = vpl[vVpl].position.xyz, n = vpl[vVpl].normal.xyz;
  vec3 l = itemDirection(gl_FragCoord.xy / faceSize * 2.0 - 1.0, 0);
  vec3 t, b;
  shooterBasis(n, t, b);
  vec3 d = l.x * t + l.y * b + l.z * n;
  vec4 p = polygons[vPolygon].normal;
  float along = dot(p.xyz, d), distance = (p.w - dot(p.xyz, o)) / along * length(d);
  gl_FragDepth = along != 0.0 && distance > 0.0 && distance < farDistance ? distance / farDistance : gl_FragCoord.z;
}
