// The Slurm job-array script of a sweep (docs/sweeps.md): one array task per configuration,
// each running `hemirad experiment run-task DIR INDEX`, requeueable, with the spec's resources.
#pragma once
#include <string>

#include "src/sweep/SweepSpec.h"

namespace hemirad {

// The script's text; `hemirad` and `dir` absolute (InputError if either holds whitespace or quotes).
std::string slurmScript(const Sweep& sweep, const std::string& hemirad, const std::string& dir);

}  // namespace hemirad
