#include <lacrima/batch/SlurmScript.h>

#include <cstdio>

namespace lacrima::batch {

namespace {

// Single-quoted for bash: the paths may hold spaces or dollars.
std::string quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string slurmTime(long long minutes) {
  char text[48];
  std::snprintf(text, sizeof text, "%lld-%02lld:%02lld:00", minutes / 1440, minutes / 60 % 24,
                minutes % 60);
  return text;
}

std::string slurmScript(const SlurmSettings& s) {
  const int perTask = (s.jobCount + s.arraySize - 1) / s.arraySize;
  const std::string logs = s.outDir + "/slurm";
  std::string script = "#!/bin/bash\n";
  script += "# lacrima-batch on Slurm: " + std::to_string(s.jobCount) + " jobs in " +
            std::to_string(s.arraySize) + " tasks of at most " + std::to_string(perTask) +
            " (docs/batch.md).\n";
  script += "# Task I runs shard I of " + std::to_string(s.arraySize) +
            "; a task that is requeued or rerun skips the jobs it finished.\n";
  script += "#SBATCH --job-name=lacrima-batch\n";
  script += "#SBATCH --array=1-" + std::to_string(s.arraySize) + "\n";
  script += "#SBATCH --ntasks=1\n";
  script += "#SBATCH --cpus-per-task=" + std::to_string(s.cpusPerTask) + "\n";
  script += "#SBATCH --mem=" + std::to_string(s.memoryMiB) + "M\n";
  script += "#SBATCH --time=" + slurmTime(static_cast<long long>(perTask) * s.minutesPerJob) + "\n";
  script += "#SBATCH --output=" + logs + "/%A_%a.out\n";
  if (!s.partition.empty()) script += "#SBATCH --partition=" + s.partition + "\n";
  script += "set -eu\n";
  script += "exec " + quoted(s.batchProgram) + " " + quoted(s.manifest) + " --out " +
            quoted(s.outDir) + " --shard \"${SLURM_ARRAY_TASK_ID}/" + std::to_string(s.arraySize) +
            "\" --jobs 1 --threads \"${SLURM_CPUS_PER_TASK:-" + std::to_string(s.cpusPerTask) +
            "}\"\n";
  return script;
}

}  // namespace lacrima::batch
