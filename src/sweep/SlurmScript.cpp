#include "src/sweep/SlurmScript.h"

#include <fmt/format.h>

#include "src/base/Error.h"

namespace hemirad {

std::string slurmScript(const Sweep& s, const std::string& hemirad, const std::string& dir) {
  for (const std::string* path : {&hemirad, &dir})
    if (path->find_first_of(" \t\n'\"$`\\%") != std::string::npos)
      fail("--slurm {}: Slurm's #SBATCH lines take no whitespace, quotes, '$' or '%' in paths; choose another folder",
           *path);
  const SweepResources& r = s.resources;
  std::string text = fmt::format(
      "#!/bin/bash\n"
      "# hemirad sweep '{0}': {1} configurations, one array task each (docs/sweeps.md).\n"
      "# Submit: sbatch {2}/sweep.sbatch    Then: hemirad experiment merge {2}\n"
      "#SBATCH --job-name=hemirad-{0}\n"
      "#SBATCH --array=0-{3}\n"
      "#SBATCH --cpus-per-task={4}\n"
      "#SBATCH --mem={5}\n"
      "#SBATCH --time={6}\n",
      s.name, s.configurations.size(), dir, s.configurations.size() - 1, r.cpus, r.mem, r.time);
  if (r.gpu) text += "#SBATCH --gres=gpu:1\n";
  text += fmt::format(
      "#SBATCH --requeue\n"
      "#SBATCH --open-mode=append\n"
      "#SBATCH --signal=B:USR1@60\n"
      "#SBATCH --output={0}/logs/task_%a.log\n"
      "\n"
      "# --requeue: a preempted task goes back into the queue, and resumes from its checkpoint.\n"
      "# --open-mode=append: each attempt's lines follow the last one's in the task's log.\n"
      "# --signal=B:USR1@60: 60 s before the time limit, USR1 to this shell (not to hemirad), which\n"
      "# stops hemirad with SIGTERM (it checkpoints between batches and exits 143) and requeues the task.\n"
      "# A preemption or `scontrol requeue` sends SIGTERM to hemirad directly, which checkpoints likewise.\n"
      "\n"
      "export LP_NUM_THREADS=${{SLURM_CPUS_PER_TASK:-1}}  # llvmpipe: the task's CPUs (results do not depend on it)\n"
      "echo \"hemirad sweep: task ${{SLURM_ARRAY_TASK_ID}} (job ${{SLURM_ARRAY_JOB_ID}}_${{SLURM_ARRAY_TASK_ID}}), "
      "attempt $((${{SLURM_RESTART_COUNT:-0}} + 1)), on $(hostname) at $(date -u +%FT%TZ)\"\n"
      "requeue() {{\n"
      "  echo \"hemirad sweep: time limit near (USR1): checkpointing and requeueing\"\n"
      "  kill -TERM \"$pid\"; wait \"$pid\"\n"
      "  scontrol requeue \"${{SLURM_ARRAY_JOB_ID}}_${{SLURM_ARRAY_TASK_ID}}\"\n"
      "  exit 0\n"
      "}}\n"
      "trap requeue USR1\n"
      "{1} experiment run-task {0} \"$SLURM_ARRAY_TASK_ID\" &\n"
      "pid=$!\n"
      "wait \"$pid\"\n",
      dir, hemirad);
  return text;
}

}  // namespace hemirad
