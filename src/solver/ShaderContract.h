// The C++/GLSL contract, declared once: every binding slot (SSBO binding points, image units,
// texture units) and every limit both sides size things by. Programs are built through
// computeProgram/renderProgram here, which hand the table to the shader loader as #define lines,
// so shaders write `layout(binding = SSBO_CONTROL)` and C++ binds `slot::SSBO_CONTROL`: a slot
// is a name on both sides, never a number (tests/ShaderContractGLTest.cpp checks both).
// Two names may share a number when no program declares both (the kinds are separate GL spaces).
#pragma once
#include <string>

#include "gl/Shader.h"

// X(name, number): one line per slot.
#define HEMIRAD_BINDING_SLOTS(X)                                                                           \
  /* SSBOs: the scene and the shooting state (scene.glsl, control.glsl, formfactor.glsl, ...) */           \
  X(SSBO_POLYGONS, 0)          /* scene.glsl: the polygon table */                                         \
  X(SSBO_POLYGON_VERTICES, 10) /* scene.glsl: every polygon's vertices */                                  \
  X(SSBO_CONTROL, 3)           /* control.glsl: the pass's shooters, stop rule, history */                 \
  X(SSBO_SHOOTER_SHAPES, 11)   /* formfactor.glsl: the shooters' exact shapes */                           \
  X(SSBO_PLANES, 12)           /* itembuffer.frag: per polygon unit normal and offset */                   \
  X(SSBO_ITEM_CHUNKS, 16)      /* cull_items.comp: per item-mesh chunk its bounds and indices */           \
  X(SSBO_ITEM_COMMANDS, 17)    /* cull_items.comp: the item buffer's indirect draws */                     \
  X(SSBO_NODES, 13)            /* shooter_tree.glsl: the shooter blocks' quadtrees */                      \
  X(SSBO_NODE_STATS, 14)       /* shooter_tree.glsl: each node's unshot sums */                            \
  X(SSBO_BLOCK_LIST, 18)       /* node_stats.comp: the blocks of one workgroup size */                     \
  X(SSBO_REDUCE_IN, 2)         /* reduce_entry.glsl: a ranking level read */                               \
  X(SSBO_REDUCE_OUT, 4)        /* reduce.comp: the level written */                                        \
  X(SSBO_PYRAMID, 5)           /* pyramid.glsl: the luminance sum pyramid */                               \
  X(SSBO_AMBIENT, 5)           /* ambient.comp, camera.frag: the display-only ambient term */              \
  X(SSBO_CHARTS, 6)            /* texel_shape.glsl: per chart its frame, then the parts' vertices */       \
  X(SSBO_TEXEL_PARTS, 15)      /* texel_shape.glsl: per texel the chart parts its element is cut from */   \
  X(SSBO_SURFACE_VIEW, 6)      /* perspective.glsl: per surface in view, epochs owed */                    \
  X(SSBO_SHOT_SO_FAR, 7)       /* perspective.glsl: per shooter block */                                   \
  X(SSBO_SNAPSHOTS, 8)         /* perspective.glsl, pending_blocks.comp */                                 \
  X(SSBO_SEEN, 9)              /* view_surfaces.comp, important_surfaces.comp */                           \
  X(SSBO_PENDING, 9)           /* pending_blocks.comp: per block the power owed */                         \
  X(SSBO_DEFERRED_BLOCKS, 9)   /* deferred_shooters.comp */                                                \
  X(SSBO_SPANS, 10)            /* pending_blocks.comp (which has no scene.glsl) */                         \
  X(SSBO_BVH_NODES, 20)        /* bvh.glsl */                                                              \
  X(SSBO_BVH_TRIANGLES, 21)    /* bvh.glsl */                                                              \
  X(SSBO_EMITTERS, 22)         /* vpl_trace.comp */                                                        \
  X(SSBO_VPLS, 23)             /* vpl.glsl */                                                              \
  X(SSBO_PATH_ENDS, 24)        /* vpl_trace.comp */                                                        \
  X(SSBO_REFERENCE_SUMS, 25)   /* reference.comp: per pixel its batch's path sums */                       \
  X(SSBO_LEAF_OF, 26)          /* gradient.comp: per texel its quadtree leaf (src/scene/Leaves.h) */       \
  X(SSBO_LEAF_COUNTS, 27)      /* gradient.comp: per leaf its texels over the gradient threshold */        \
  X(SSBO_RECEIVERS, 28)        /* gather.comp: its receiver texels in visiting order (ReceiverOrder.h) */  \
  X(SSBO_HOST_VISIBLE, 29)     /* visibility.glsl: the host's traced answers for the pass (HostTrace.h) */ \
  X(SSBO_WALKS_CUT, 30)        /* bvh.glsl: set where llvmpipe's loop limit cut a walk (BvhBuffers.h) */   \
  X(SSBO_PROBE_IN, 0)          /* the *_probe.comp test kernels: inputs */                                 \
  X(SSBO_PROBE_OUT, 1)         /* and outputs */                                                           \
  X(SSBO_PROBE_POINTS, 2)      /* projection_probe.comp: item-buffer points */                             \
  /* Image units */                                                                                        \
  X(IMAGE_RADIOSITY, 0)      /* B (or the pyramid's source) */                                             \
  X(IMAGE_DELTA_B, 1)        /* dB; stochastic iteration's next iterate */                                 \
  X(IMAGE_VIEW_PIXELS, 2)    /* importance_view.frag, importance_update.comp */                            \
  X(IMAGE_DIRECT, 3)         /* importance_update.comp: R per texel */                                     \
  X(IMAGE_VIEW_IDS, 0)       /* view_surfaces.comp: the perspective view's polygon ids */                  \
  X(IMAGE_SHADED, 0)         /* instant_deferred.comp, instant_filter.comp */                              \
  X(IMAGE_FILTERED, 1)       /* instant_filter.comp */                                                     \
  X(IMAGE_PROBE, 0)          /* formfactor_probe.comp */                                                   \
  X(IMAGE_CEILING_VALUES, 0) /* ceiling.comp */                                                            \
  X(IMAGE_RESOLVED, 0)       /* resolve.comp: the camera's resolved pixels */                              \
  /* Texture units */                                                                                      \
  X(SAMPLER_ATLAS_POSITION_AREA, 0) /* scene.glsl */                                                       \
  X(SAMPLER_ATLAS_POLYGON, 1)       /* scene.glsl */                                                       \
  X(SAMPLER_ATLAS_NORMAL, 3)        /* scene.glsl: per texel the receiver normal */                        \
  X(SAMPLER_ITEM_ID, 2)             /* visibility.glsl: the item buffer's polygon ids */                   \
  X(SAMPLER_ATLAS_VALUES, 2)        /* camera.frag: the per-element values shown */                        \
  X(SAMPLER_SHADOW_ID, 4)           /* instant_shade.glsl: the VPL shadow maps */                          \
  X(SAMPLER_G_POLYGON, 6)           /* instant_deferred.comp, instant_filter.comp */                       \
  X(SAMPLER_LIGHTMAP, 0)            /* lightmap.frag */                                                    \
  X(SAMPLER_MULTISAMPLE, 0)         /* resolve.comp: the camera's samples */

namespace hemirad {

namespace slot {
#define HEMIRAD_SLOT_ENUMERATOR(name, number) name = number,
enum Slot : unsigned { HEMIRAD_BINDING_SLOTS(HEMIRAD_SLOT_ENUMERATOR) };
#undef HEMIRAD_SLOT_ENUMERATOR
}  // namespace slot

// Limits: shaders get them as SHOOTER_SLOTS and MAX_SHAPE_VERTICES (SHAPE_STRIDE); and
// MAX_SPLIT_DEPTH, the shooter tree's kMaxSplitDepth (src/solver/ShooterTree.h).
inline constexpr unsigned kMaxPassShooters = 64;                 // radiosity shooters a pass; as many importance ones
inline constexpr unsigned kShooterSlots = 2 * kMaxPassShooters;  // control.glsl's shooter array
// A convex polygon of <= 8 sides cut by a block's rectangle (formfactor.glsl, texel_shape.glsl).
inline constexpr int kMaxShapeVertices = 12;
inline constexpr int kShapeStride = kMaxShapeVertices + 1;  // the count, then the vertices
// Convex pieces a shooter's shape may have (a block over several polygons of one chart).
inline constexpr int kMaxShapePieces = 64;
// Pieces a texel sampled by stochastic iteration may have (texel_shape.glsl; more: the disc).
// Shooter k's first piece is slot k, the others slots SHOOTER_SLOTS + k (MAX_TEXEL_PIECES - 1) on.
inline constexpr int kMaxTexelPieces = 16;
// The exact segment test's plane tolerance (segment.glsl's blocksSegment), a fraction of the scene's
// far distance: SEGMENT_TOLERANCE in the shaders (the gather, refinement, traced visibility, VPLs).
inline constexpr double kSegmentTolerance = 4e-7;
// Samples a camera pixel may have (`--msaa`'s largest; resolve.comp: MAX_CAMERA_SAMPLES).
inline constexpr int kMaxCameraSamples = 32;

// The table as #define lines (slots, limits, LUMINANCE: the Rec. 709 weights of src/scene/Scene.h).
const gl::Defines& contractDefines();

// gl::computeProgram / gl::renderProgram with contractDefines() before `defines`.
gl::Program computeProgram(const std::string& file, const gl::Defines& defines = {});
gl::Program renderProgram(const std::string& vertexFile, const std::string& fragmentFile,
                          const gl::Defines& defines = {});

}  // namespace hemirad
