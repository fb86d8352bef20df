// Bench fill ceiling (src/bench/Ceilings.cpp): instance i is a triangle covering the whole target,
// nearer than instance i - 1, so every fragment passes the depth test and is written, as the
// item buffer's nearest surfaces are. Drawn with fill.frag.
flat out uint vPolygon;
uniform int instances;

void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
  vPolygon = uint(gl_InstanceID);
  gl_Position = vec4(p, 1.0 - 2.0 * float(gl_InstanceID + 1) / float(instances + 1), 1.0);
}
