#include "src/output/Provenance.h"

#include <fmt/format.h>

#include "GitHash.h"  // HEMIRAD_GIT_HASH, written at build time (cmake/GitHash.cmake)

namespace hemirad {

namespace {

std::string& recorded() {
  static std::string line;
  return line;
}

// Quoted only where a shell would split or expand it, so the line can be pasted back.
std::string shellWord(const std::string& w) {
  if (!w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=.,/:@%") ==
                        std::string::npos)
    return w;
  std::string out = "'";
  for (char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void recordCommandLine(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + shellWord(argv[i]);
  recorded() = line;
}

const std::string& commandLine() { return recorded(); }

Provenance provenance(const std::string& backend, const std::string& renderer) {
  return {HEMIRAD_VERSION, HEMIRAD_GIT_HASH, commandLine(), backend, renderer};
}

std::string versionString() { return fmt::format("hemirad {} (git {})", HEMIRAD_VERSION, HEMIRAD_GIT_HASH); }

std::string provenanceText(const Provenance& p) {
  return fmt::format("hemirad {} (git {}), {} ({}): {}", p.version, p.gitHash, p.backend, p.renderer, p.commandLine);
}

nlohmann::json provenanceJson(const Provenance& p) {
  return {{"version", p.version},
          {"git_hash", p.gitHash},
          {"command_line", p.commandLine},
          {"backend", p.backend},
          {"renderer", p.renderer}};
}

}  // namespace hemirad
