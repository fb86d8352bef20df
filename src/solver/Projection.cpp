#include "src/solver/Projection.h"

#include "src/base/Error.h"

namespace hemirad {

Projection parseProjection(const std::string& name) {
  if (name == "stereographic" || name == "hemisphere") return Projection::Stereographic;
  if (name == "hemicube") return Projection::Hemicube;
  throw InputError("--hemisphere must be stereographic or hemicube, not '" + name + "'");
}

std::string projectionName(Projection p) { return p == Projection::Hemicube ? "hemicube" : "stereographic"; }

}  // namespace hemirad
