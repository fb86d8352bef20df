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

// Seed 003's hemispherical projection (Listing 39-2): the direction is normalised onto the
// unit hemisphere and its xy taken, so a direction at angle theta from the normal lands at
// radius sin(theta): the normal at the centre, the horizon on the unit circle. Returns [-1,1]^2.
vec2 hemiProject(vec3 local) {
  float len = length(local);
  return len > 0.0 ? local.xy / len : vec2(0.0);
}

// DESIGN.md's disc form factor: receiving element j from a shooter of area A_s at distance r.
float discFormFactor(float cosS, float cosR, float r2, float shooterArea) {
  return max(cosS, 0.0) * max(cosR, 0.0) * shooterArea / (PI * r2 + shooterArea);
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
