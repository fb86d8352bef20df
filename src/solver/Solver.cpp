#include "src/solver/Solver.h"

#include <fmt/format.h>

#include "src/base/Error.h"

namespace hemirad {

Algorithm parseAlgorithm(const std::string& name) {
  const auto& names = algorithmNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return Algorithm(i);
  throw InputError(fmt::format("unknown algorithm '{}' (progressive, importance or perspective)", name));
}

const char* algorithmName(Algorithm a) { return algorithmNames().at(std::size_t(a)).c_str(); }

}  // namespace hemirad
