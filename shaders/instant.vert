// Instant radiosity's camera passes (forward, G-buffer): the scene's triangles with their
// polygon ids; the shading passes find the point from the pixel (instant_shade.glsl). `invariant`:
// the forward passes test depth for equality against the depth pre-pass.
layout(location = 0) in vec3 position;
layout(location = 1) in uint polygon;
uniform mat4 viewProjection;
flat out uint vPolygon;
invariant gl_Position;

void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vPolygon = polygon;
}
