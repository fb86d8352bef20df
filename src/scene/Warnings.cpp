#include "src/scene/Warnings.h"

#include <fmt/format.h>

#include <map>

#include "src/base/Error.h"

namespace hemirad {

std::string withThousands(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    if (k && (digits.size() - k) % 3 == 0) out += ',';
    out += digits[k];
  }
  return out;
}

namespace {

std::string groupLine(const std::vector<const SceneWarning*>& group) {
  std::string places;
  for (std::size_t k = 0; k < kWarningPlaces; ++k) places += (k ? ", " : "") + group[k]->where;
  return fmt::format("{} {}: {} (first at {}, ...)", withThousands(group.size()), group.front()->counted,
                     group.front()->group(), places);
}

}  // namespace

std::vector<std::string> warningLines(const std::vector<SceneWarning>& warnings) {
  std::vector<std::vector<const SceneWarning*>> groups;  // in order of first warning
  std::map<std::string, std::size_t> index;
  for (const SceneWarning& w : warnings) {
    auto [it, added] = index.emplace(w.group(), groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(&w);
  }
  std::vector<std::string> lines;
  std::size_t shown = 0, kinds = 0;
  for (const auto& group : groups) {
    const std::size_t needed = group.size() <= kWarningPlaces ? group.size() : 1;
    const bool last = shown + group.size() == warnings.size();
    if (lines.size() + needed + (last ? 0 : 1) > kWarningLines) break;  // one line kept to count the rest
    if (group.size() <= kWarningPlaces)
      for (const SceneWarning* w : group) lines.push_back(w->text());
    else
      lines.push_back(groupLine(group));
    shown += group.size();
    ++kinds;
  }
  if (shown < warnings.size())
    lines.push_back(fmt::format("{} more warnings of {} other kinds not shown", withThousands(warnings.size() - shown),
                                groups.size() - kinds));
  return lines;
}

void printWarnings(const std::vector<SceneWarning>& warnings) {
  for (const std::string& line : warningLines(warnings)) warn(line);
}

}  // namespace hemirad
