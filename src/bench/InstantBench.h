// `hemirad bench --method instant`: frames per second of instant radiosity (shadow maps and
// shading of every VPL, forward and deferred) at given VPL counts, beside seed 002's Figure 5
// (GeForce GTX Titan). The VPLs are traced once per row, as the seed does after loading.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "gl/Backend.h"
#include "src/bench/Bench.h"

namespace hemirad {

// Prints the table through `say` and returns the rows as JSON.
nlohmann::json benchInstant(gl::RenderBackend& backend, const BenchOptions& o,
                            const std::function<void(const std::string&)>& say);

}  // namespace hemirad
