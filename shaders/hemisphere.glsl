// Shooter-frame maths shared by the item buffer, the gather and (mirrored in C++) the CPU
// reference in cpu/Hemisphere.h. Keep the two in step.

const float PI = 3.14159265358979;

// Orthonormal basis around unit n (Duff et al. 2017), so every pass builds the same frame.
void shooterBasis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Point p in the frame of a shooter at `origin` facing n: z is the height above its plane.
vec3 shooterLocal(vec3 p, vec3 origin, vec3 n) {
  vec3 t, b;
  shooterBasis(n, t, b);
  vec3 d = p - origin;
  return vec3(dot(d, t), dot(d, b), dot(d, n));
}

// Seed 003's hemispherical projection (Listing 39-2), the orthographic (Nusselt) map: the
// direction is normalised onto the unit hemisphere and its xy taken, so a direction at angle
// theta from the normal lands at radius sin(theta): the normal at the centre, the horizon on the
// unit circle. Returns [-1,1]^2.
vec2 hemiProject(vec3 local) {
  float len = length(local);
  return len > 0.0 ? local.xy / len : vec2(0.0);
}

// Its inverse: the unit direction through disc point ndc; outside the disc the nearest horizon
// direction.
vec3 hemiDirection(vec2 ndc) {
  float r2 = dot(ndc, ndc);
  return r2 < 1.0 ? vec3(ndc, sqrt(1.0 - r2)) : vec3(ndc * inversesqrt(r2), 0.0);
}

// The further disc maps (src/solver/Projection.h), on the unit direction u = local / |local|.
// Below the horizon (triangles the clip plane cuts) both grow past the rim instead of folding
// back; the floor keeps the antipode of the normal finite.
vec3 unitDirection(vec3 local) {
  float len = length(local);
  return len > 0.0 ? local / len : vec3(0.0, 0.0, 1.0);
}

// Conformal (true stereographic from the antipode, = the paraboloid map): r = tan(theta / 2).
vec2 conformalProject(vec3 local) {
  vec3 u = unitDirection(local);
  return u.xy / max(1.0 + u.z, 1e-6);
}
vec3 conformalDirection(vec2 ndc) {
  float r2 = dot(ndc, ndc);
  return r2 < 1.0 ? vec3(2.0 * ndc, 1.0 - r2) / (1.0 + r2) : vec3(ndc * inversesqrt(r2), 0.0);
}

// Lambert's equal-area map: r = sqrt(2) sin(theta / 2) = sqrt(1 - cos(theta)).
vec2 equalAreaProject(vec3 local) {
  vec3 u = unitDirection(local);
  return u.xy * inversesqrt(max(1.0 + u.z, 1e-12));
}
vec3 equalAreaDirection(vec2 ndc) {
  float r2 = dot(ndc, ndc);
  return r2 < 1.0 ? vec3(ndc * sqrt(2.0 - r2), 1.0 - r2) : vec3(ndc * inversesqrt(r2), 0.0);
}

// The disc map the item buffer uses: CONFORMAL or EQUAL_AREA defined (src/solver/ItemBuffer.cpp),
// else seed 003's.
#if defined(CONFORMAL)
#define diskProject conformalProject
#define diskDirection conformalDirection
#elif defined(EQUAL_AREA)
#define diskProject equalAreaProject
#define diskDirection equalAreaDirection
#else
#define diskProject hemiProject
#define diskDirection hemiDirection
#endif

// The disc form factor (docs/design.md#form-factor): receiving element j from a shooter of area A_s at distance r. Only
// a fallback now (formfactor.glsl is exact), for shooter shapes over MAX_SHAPE_VERTICES vertices.
float discFormFactor(float cosS, float cosR, float r2, float shooterArea) {
  return max(cosS, 0.0) * max(cosR, 0.0) * shooterArea / (PI * r2 + shooterArea);
}

float luminance(vec3 c) { return dot(c, LUMINANCE); }

// ---- Item-buffer projections. The item buffer is a 2D array texture: per shooter one layer
// for the hemisphere, five for the hemicube (HEMICUBE defined), whose side faces use their
// upper half.
#ifdef HEMICUBE
const int ITEM_FACES = 5;
// The hemicube's near plane (along each face's axis) as a fraction of the far distance: a point is
// drawn in the face of its largest axis, so only points within ~1e-6 far of the shooter are lost,
// ten times closer than the horizon margin (1e-5 far, itembuffer.vert) already drops.
const float ITEM_NEAR = 1e-6;
#else
const int ITEM_FACES = 1;
#endif

#ifdef HEMICUBE
// Face f's coordinates (a, b, c) of a shooter-frame point: it looks along +c with a 90-degree
// field of view, so (a/c, b/c) in [-1, 1]^2. Faces: +z (top), +x, -x, +y, -y.
vec3 cubeFace(vec3 l, int face) {
  if (face == 0) return l;
  if (face == 1) return vec3(l.y, l.z, l.x);
  if (face == 2) return vec3(-l.y, l.z, -l.x);
  if (face == 3) return vec3(-l.x, l.z, l.y);
  return vec3(l.x, l.z, -l.y);
}
int cubeFaceOf(vec3 l) {
  vec3 a = abs(l);
  if (l.z >= a.x && l.z >= a.y) return 0;
  if (a.x >= a.y) return l.x >= 0.0 ? 1 : 2;
  return l.y >= 0.0 ? 3 : 4;
}
#endif

// Clip-space position of a shooter-frame point on item-buffer layer `face`, so that occlusion
// is ordered along each ray. Hemicube: a face is a plain perspective view, under which a planar
// polygon's near / depth is linear across the screen, so the rasteriser's interpolated
// reversed depth (near / f.z in [0, 1], GL_GREATER, gl/State.h) is exact and the fragment shader
// writes none (early depth test). Hemisphere: distance / far, made exact per pixel by
// itembuffer.frag (the curved projection's interpolation is not).
vec4 itemClipPosition(vec3 local, float farDistance, int face) {
#ifdef HEMICUBE
  vec3 f = cubeFace(local, face);
  return vec4(f.xy, ITEM_NEAR * farDistance, f.z);
#else
  return vec4(diskProject(local), 2.0 * length(local) / farDistance - 1.0, 1.0);
#endif
}

// The shooter-frame direction (not normalised) through item-buffer point ndc of layer `face`:
// the inverse of the projection, for exact per-pixel depths (itembuffer.frag). Outside the
// hemisphere's disc it returns the nearest horizon direction.
vec3 itemDirection(vec2 ndc, int face) {
#ifdef HEMICUBE
  vec3 f = vec3(ndc, 1.0);  // inverse of cubeFace
  if (face == 0) return f;
  if (face == 1) return vec3(f.z, f.x, f.y);
  if (face == 2) return vec3(-f.z, -f.x, f.y);
  if (face == 3) return vec3(-f.x, f.z, f.y);
  return vec3(f.x, -f.z, f.y);
#else
  return diskDirection(ndc);
#endif
}

// The item-buffer texel (x, y, layer) a shooter-frame direction falls in.
ivec3 itemTexel(vec3 local, ivec2 size) {
#ifdef HEMICUBE
  int face = cubeFaceOf(local);
  vec3 f = cubeFace(local, face);
  vec2 ndc = f.xy / f.z;
#else
  int face = 0;
  vec2 ndc = diskProject(local);
#endif
  ivec2 pixel = clamp(ivec2(floor((ndc * 0.5 + 0.5) * vec2(size))), ivec2(0), size - 1);
  return ivec3(pixel, face);
}
