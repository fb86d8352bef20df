flat in uint vPolygon;
layout(location = 0) out uint itemId;
void main() { itemId = vPolygon; }
