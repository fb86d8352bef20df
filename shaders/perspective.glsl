// Perspective-driven shooting (seed 004 §5): only surfaces in the area of interest receive
// radiosity; what a shot would have given the others waits in the stored radiosity table.
// The table B_ij (shooter block i, surface j) is kept factored: shotSoFar[i] is all the
// radiosity block i has shot, and snapshot e holds shotSoFar as it was when epoch e began, so
// for a surface that left the view at epoch e, B_ij = shotSoFar[i] - snapshot[e][i]. That is
// O(blocks) per epoch instead of O(blocks x surfaces), with no limit on either. A surface that
// came back into view at epoch f receives shots itself from then on and is owed
// snapshot[f][i] - snapshot[e][i] until a delivery round hands it over.

layout(std430, binding = SSBO_SURFACE_VIEW) readonly buffer SurfaceView {
  uvec4 surfaceView[];  // per polygon: x 1 if in view; y, z 1 + the epochs its entries start and end at while
                        // a delivery round hands them over (else 0)
};
layout(std430, binding = SSBO_SHOT_SO_FAR) buffer ShotSoFar { vec4 shotSoFar[]; };        // per shooter block
layout(std430, binding = SSBO_SNAPSHOTS) readonly buffer Snapshots { vec4 snapshot[]; };  // epoch * blocks + block
uniform uint blockCount;
