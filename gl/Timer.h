// GPU time per pass from GL_TIME_ELAPSED queries, read back only at sync points so timing
// never stalls the pipeline. Queries are recycled.
#pragma once
#include <span>
#include <utility>
#include <vector>

#include "gl/Objects.h"

namespace hemirad::gl {

class GpuTimer {
 public:
  void begin(int slot);
  void end();
  // Adds every pending query's milliseconds to totals[slot]; waits for unfinished ones.
  void collect(std::span<double> totals);

 private:
  std::vector<Query> free_;
  std::vector<std::pair<Query, int>> pending_;
};

}  // namespace hemirad::gl
