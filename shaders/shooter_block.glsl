// A shooter's geometry: a shooter-tree node (a block or a part of one: seed 003's
// substructuring) with its area and exact shape, seen from its area-weighted centre; the
// selection then aims it at its unshot light (describeUnshot). Needs scene.glsl, control.glsl
// and shooter_tree.glsl.
void describeNode(uint slot, uint node, uint block) {
  Node n = nodes[node];
  control.shooter[slot].positionArea = vec4(shooterEye(n.centreArea.xyz, n.polygon, n.centreArea.w), n.centreArea.w);
  control.shooter[slot].normal = vec4(n.normal.xyz, 0.0);
  control.shooter[slot].shot = vec4(0.0);
  control.shooter[slot].rect = n.rect;
  control.shooter[slot].polygon = n.polygon;
  control.shooter[slot].power = 0.0;
  control.shooter[slot].block = block;
  control.shooter[slot].shape = node;
}

// The node shoots its area-weighted unshot radiosity (or importance) and sees from where that
// sits (node_stats.comp's weighted centre): a block half under a box would otherwise look out
// from inside the box and lose the lit half's light.
// Importance is the adjoint of light (W_t = R_t + sum_s F_ts rho_s W_s): light leaving t is
// worth what it is worth where it lands and is reflected, so importance shot from s carries
// s's reflectance (luminance), and receivers take it unscaled (gather.comp). Then W - R is
// what a unit of unshot radiosity at t is worth to the view: the importance-driven key.
void describeUnshot(uint slot, uint node, bool importance) {
  NodeStats s = stats[node];
  vec4 centre = importance ? s.viewCentre : s.lightCentre;
  float area = nodes[node].centreArea.w;
  if (centre.w > 0.0) control.shooter[slot].positionArea.xyz = shooterEye(centre.xyz / centre.w, nodes[node].polygon, area);
  float reflects = dot(polygons[nodes[node].polygon].reflectance.rgb, LUMINANCE);
  control.shooter[slot].shot = importance ? vec4(0.0, 0.0, 0.0, reflects * s.unshot.a / area) : vec4(s.unshot.rgb / area, 0.0);
}
