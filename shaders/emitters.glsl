// The scene's emitter triangles picked by power (src/solver/EmitterTable.h): instant radiosity's
// light-path starts and the reference's direct-light samples.
struct Emitter {
  vec4 v0;    // w: cumulative power fraction up to and including this triangle
  vec4 e1;    // w (uint bits): polygon id
  vec4 e2;
  vec4 flux;  // rgb: E W / lum(E), a light sample's flux times n[0] (W: total lum(E) A)
};
layout(std430, binding = SSBO_EMITTERS) readonly buffer Emitters { Emitter emitter[]; };
uniform uint emitterCount;

uint pickEmitter(float u) {
  uint lo = 0u, hi = emitterCount - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (emitter[mid].v0.w > u) hi = mid; else lo = mid + 1u;
  }
  return lo;
}
