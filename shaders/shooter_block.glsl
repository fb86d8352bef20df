// A shooter block's geometry: it shoots from its texels' area-weighted centre with their total
// area (seed 003's substructuring). Needs scene.glsl and control.glsl.
void describeShooter(uint slot, ivec4 rect, uint block) {
  vec3 centre = vec3(0.0);
  float area = 0.0;
  uint polygon = NO_POLYGON;
  for (int y = rect.y; y < rect.y + rect.w; ++y)
    for (int x = rect.x; x < rect.x + rect.z; ++x) {
      vec4 pa = texelFetch(atlasPositionArea, ivec2(x, y), 0);
      if (pa.w <= 0.0) continue;
      centre += pa.xyz * pa.w;
      area += pa.w;
      polygon = texelFetch(atlasPolygon, ivec2(x, y), 0).r;
    }
  control.shooter[slot].positionArea = vec4(centre / area, area);
  control.shooter[slot].normal = vec4(polygons[polygon].normal.xyz, 0.0);
  control.shooter[slot].shot = vec4(0.0);
  control.shooter[slot].rect = rect;
  control.shooter[slot].polygon = polygon;
  control.shooter[slot].power = 0.0;
  control.shooter[slot].block = block;
}
