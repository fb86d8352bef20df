// How an item buffer maps a shooter's hemisphere to pixels: seed 003's single-pass stereographic
// projection, or the classic five-face hemicube (Cohen & Greenberg 1985) as the baseline.
#pragma once
#include <string>

namespace hemirad {

enum class Projection { Stereographic, Hemicube };
Projection parseProjection(const std::string& name);  // "stereographic" or "hemicube"
std::string projectionName(Projection p);

}  // namespace hemirad
