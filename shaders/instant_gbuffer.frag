// Deferred shading's G-buffer: the visible point and its polygon (id + 1; 0: background). The
// normal and albedo are the polygon's (hemirad's polygons are flat and of one material), read
// from the polygon table by the shading pass.
in vec3 vPosition;
flat in uint vPolygon;
layout(location = 0) out vec4 gPosition;
void main() { gPosition = vec4(vPosition, float(vPolygon + 1u)); }
