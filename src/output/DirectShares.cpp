#include "src/output/DirectShares.h"

#include <algorithm>

namespace hemirad {

std::vector<DirectShare> directShares(SharePlan plan, unsigned pieces, unsigned grid, unsigned blocks) {
  const unsigned strips = pieces * grid;
  if (plan == SharePlan{}) return {{0, strips, 0, blocks}};
  const unsigned d = std::min(std::max(plan.direct, 1u), strips), b = std::min(std::max(plan.gather, 1u), blocks);
  const auto bound = [&](unsigned k) { return d <= pieces ? grid * (pieces * k / d) : strips * k / d; };
  std::vector<DirectShare> shares;
  for (unsigned k = 0; k < d; ++k) shares.push_back({.stripsFirst = bound(k), .stripsEnd = bound(k + 1)});
  for (unsigned k = 0; k < b; ++k) shares.push_back({.blocksFirst = blocks * k / b, .blocksEnd = blocks * (k + 1) / b});
  return shares;
}

}  // namespace hemirad
