// Deferred shading's G-buffer: the visible polygon per pixel (id + 1; 0: background), one
// 32-bit word. The point is the camera ray through the pixel's centre met with that polygon's
// plane (instant_shade.glsl: surfacePoint), its normal and albedo the polygon's (hemirad's
// polygons are flat and of one material): an RGBA32F position target wrote four times the bytes
// at a quarter of the raster's rate, the floor of a 1024^2 frame on the H200.
flat in uint vPolygon;
layout(location = 0) out uint gPolygon;
void main() { gPolygon = vPolygon + 1u; }
