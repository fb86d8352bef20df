// hemirad: GPU progressive-refinement radiosity with a hemispherical item buffer.
#include <cstdio>
#include <memory>

#include "src/base/Error.h"
#include "src/cli/Commands.h"
#include "src/options/Suggest.h"
#include "src/output/Provenance.h"

using namespace hemirad;

int main(int argc, char** argv) {
  recordCommandLine(argc, argv);  // every report's and figure's provenance
  auto commands = std::make_unique<Commands>();
  if (std::optional<int> exit = options::parse(commands->app, argc, argv)) return *exit;
  try {
    return commands->run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitFailure;
  }
}
