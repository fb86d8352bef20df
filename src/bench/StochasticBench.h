// `hemirad bench --method stochastic`: the cost of one stochastic iteration (pyramid and
// selection, item buffers, update) on atlases of given sides, filled by the texel size.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "gl/Backend.h"
#include "src/bench/Bench.h"

namespace hemirad {

// Prints the table through `say` and returns the rows as JSON.
nlohmann::json benchStochastic(gl::RenderBackend& backend, const BenchOptions& o,
                               const std::function<void(const std::string&)>& say);

}  // namespace hemirad
