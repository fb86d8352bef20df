// The polygon id of the nearest surface per pixel of a view (with camera.vert): which surfaces
// are in the perspective-driven solver's area of interest.
flat in uint vPolygon;
layout(location = 0) out uint id;

void main() { id = vPolygon; }
