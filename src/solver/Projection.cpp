#include "src/solver/Projection.h"

#include <utility>

#include "src/base/Error.h"

namespace hemirad {

namespace {
// Canonical names first; then the aliases that earlier versions wrote into commands, reports,
// checkpoints and sweep specs, which must keep meaning (bitwise) what they meant.
const std::pair<const char*, Projection> kNames[] = {
    {"orthographic", Projection::Orthographic},  {"hemicube", Projection::Hemicube},
    {"conformal", Projection::Conformal},        {"equal-area", Projection::EqualArea},
    {"stereographic", Projection::Orthographic}, {"hemisphere", Projection::Orthographic},
    {"paraboloid", Projection::Conformal}};
constexpr std::size_t kCanonical = 4;
}  // namespace

Projection parseProjection(const std::string& name) {
  for (const auto& [n, p] : kNames)
    if (name == n) return p;
  throw InputError("--hemisphere must be orthographic, hemicube, conformal or equal-area, not '" + name + "'");
}

std::string projectionName(Projection p) {
  for (std::size_t k = 0; k < kCanonical; ++k)
    if (kNames[k].second == p) return kNames[k].first;
  return "orthographic";
}

std::vector<std::string> projectionNames() {
  std::vector<std::string> names;
  for (const auto& [n, p] : kNames) names.push_back(n);
  return names;
}

std::vector<Projection> allProjections() {
  std::vector<Projection> all;
  for (std::size_t k = 0; k < kCanonical; ++k) all.push_back(kNames[k].second);
  return all;
}

Projection parseProjectionFlag(const std::string& name) {
  const Projection p = parseProjection(name);
  if (name == "stereographic")
    warn(
        "--hemisphere stereographic is seed 003's orthographic (Nusselt) map, r = sin theta, as before; "
        "now named orthographic. The true stereographic map is conformal");
  return p;
}

}  // namespace hemirad
