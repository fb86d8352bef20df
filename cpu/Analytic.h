// Closed-form form factors (Howell's catalogue, "A Catalog of Radiation Heat Transfer
// Configuration Factors"), the exact answers the GPU pipeline is tested against.
#pragma once

namespace hemirad::cpu {

// C-11: from one a x b rectangle to an identical, parallel, directly opposed one at distance c.
double parallelRectangles(double a, double b, double c);
// C-14: between rectangles sharing an edge of length l at a right angle; from the one of
// width w (perpendicular to the edge) to the one of height h.
double perpendicularRectangles(double l, double w, double h);
// B-13: differential area to a parallel coaxial disc of radius R at height H.
double pointToCoaxialDisc(double R, double H);

}  // namespace hemirad::cpu
