// The virtual point lights (SSBO_VPLS), written by vpl_trace.comp, read by the shadow maps and the
// shading. Whole vec4s only (seed 002 §4.1); mirrored by src/solver/VplTracer.h.
struct Vpl {
  vec4 position;  // xyz; w (uint bits): the polygon it lies on
  vec4 normal;    // xyz its polygon's front normal; w: its bounce level (0: on an emitter)
  vec4 flux;      // rgb: the power it emits, Lambertian around the normal (0: an empty slot)
};
layout(std430, binding = SSBO_VPLS) buffer Vpls { Vpl vpl[]; };
