// What every report and figure says about the run that made it: hemirad's version, the git
// commit it was built from (at configure time), the command line, the GL backend and its
// renderer string. One place, so JSON reports and figure metadata say the same.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace hemirad {

struct Provenance {
  std::string version, gitHash, commandLine, backend, renderer;
};

// main() records argv once; commandLine() is it, shell-quoted ("" if never recorded).
void recordCommandLine(int argc, const char* const* argv);
const std::string& commandLine();
// This build's version, commit and the recorded command line, with the run's backend and renderer.
Provenance provenance(const std::string& backend, const std::string& renderer);
// "hemirad 0.1.0 (git 0123abcd4567)", what --version prints.
std::string versionString();
// "hemirad 0.1.0 (git 0123abcd4567), osmesa (llvmpipe ...): hemirad solve ...", the figures' metadata.
std::string provenanceText(const Provenance& p);
// {"version", "git_hash", "command_line", "backend", "renderer"}: every JSON report's "provenance".
nlohmann::json provenanceJson(const Provenance& p);

}  // namespace hemirad
