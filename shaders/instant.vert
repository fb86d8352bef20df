// Instant radiosity's camera passes (forward, G-buffer): the scene's triangles with world
// positions and polygon ids. `invariant`: the forward passes test depth for equality against
// the depth pre-pass, and the G-buffer must hold the very positions forward shading sees.
layout(location = 0) in vec3 position;
layout(location = 1) in uint polygon;
uniform mat4 viewProjection;
out vec3 vPosition;
flat out uint vPolygon;
invariant gl_Position;

void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vPosition = position;
  vPolygon = polygon;
}
