// Camera view of the solution: the scene's polygons with their atlas coordinates.
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 atlasCoord;
layout(location = 2) in uint polygon;
layout(location = 3) in vec3 normal;  // a curved chart's smooth normal, else 0
uniform mat4 viewProjection;
centroid out vec2 vAtlas;  // centroid: inside the surface when MSAA covers a pixel in part
flat out uint vPolygon;
#ifdef PER_PIXEL_DIRECT
centroid out vec3 vPosition, vNormal;
invariant gl_Position;  // both passes find the same depths (GL_EQUAL)
#endif

void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vAtlas = atlasCoord;
  vPolygon = polygon;
#ifdef PER_PIXEL_DIRECT
  vPosition = position, vNormal = normal;
#endif
}
