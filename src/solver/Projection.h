// How an item buffer maps a shooter's hemisphere to pixels. A direction at angle theta from the
// normal lands at radius r(theta) of the unit disc (the horizon on the rim):
//   orthographic  r = sin(theta)           seed 003's map, the Nusselt analog (the default; its old
//                                          names `stereographic` and `hemisphere` are aliases)
//   conformal     r = tan(theta / 2)       the true stereographic map (= Heidrich & Seidel's paraboloid,
//                                          accepted as `paraboloid`)
//   equal-area    r = sqrt(2) sin(theta/2) Lambert's azimuthal map: every pixel the same solid angle
// or the classic five-face hemicube (Cohen & Greenberg 1985). docs/validation.md#projections says why.
#pragma once
#include <string>
#include <vector>

namespace hemirad {

enum class Projection { Orthographic, Hemicube, Conformal, EqualArea };
// A name or alias; throws InputError otherwise.
Projection parseProjection(const std::string& name);
std::string projectionName(Projection p);  // the canonical name
// The names --hemisphere accepts, canonical first, and what `validate --hemisphere all` compares.
std::vector<std::string> projectionNames();
std::vector<Projection> allProjections();
// parseProjection for a --hemisphere given on the command line: the old name `stereographic`
// (the orthographic map, not the true stereographic one) gets a one-line warning.
Projection parseProjectionFlag(const std::string& name);

}  // namespace hemirad
