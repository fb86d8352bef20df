// The workgroup's index along a 1D count dispatched as a 2D/3D grid (gl/Limits.h dispatchLinear):
// the grid may hold a few groups past the count, which the caller's bound check skips.
#ifndef LINEAR_GROUP_GLSL
#define LINEAR_GROUP_GLSL
uint linearGroup() {
  return gl_WorkGroupID.x + gl_NumWorkGroups.x * (gl_WorkGroupID.y + gl_NumWorkGroups.y * gl_WorkGroupID.z);
}
// The invocation's index along the count; groupSize: the local size (gl_WorkGroupSize.x).
uint linearInvocation(uint groupSize) { return linearGroup() * groupSize + gl_LocalInvocationID.x; }
#endif
