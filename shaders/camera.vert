// Camera view of the solution: the scene's polygons with their atlas coordinates.
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 atlasCoord;
layout(location = 2) in uint polygon;
uniform mat4 viewProjection;
out vec2 vAtlas;
flat out uint vPolygon;

void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vAtlas = atlasCoord;
  vPolygon = polygon;
}
