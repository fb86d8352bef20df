// The flags of seed 004's experiments, declared once (from the option table, options/Options.h) for
// `hemirad experiment` and for the lean `hemirad-bench experiment` that GPU machines run.
#pragma once
#include <CLI/CLI.hpp>
#include <vector>

#include "src/walk/Experiment.h"

namespace hemirad {

// Adds them to `cmd`, bound to `e`; returns those a sweep SPEC makes meaningless (all but --out-dir).
std::vector<CLI::Option*> addExperimentFlags(CLI::App* cmd, ExperimentOptions& e);

}  // namespace hemirad
