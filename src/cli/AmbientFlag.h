// `--ambient on|off` (default on): seed 004's ambient term on previews; shared by solve, view
// and experiment. Header-only so the viewer and walk libraries need no link to the CLI one.
#pragma once
#include <CLI/CLI.hpp>
#include <map>
#include <string>

namespace hemirad {

inline void addAmbientFlag(CLI::App* cmd, bool& ambient) {
  static const std::map<std::string, bool> onOff{{"on", true}, {"off", false}};
  cmd->add_option("--ambient", ambient,
                  "Seed 004's ambient term R x (area-averaged unshot radiosity) x rho on the camera images: on "
                  "(default) or off. Never in B, the report, the atlas or the PLY")
      ->transform(CLI::CheckedTransformer(onOff, CLI::ignore_case));
}

}  // namespace hemirad
