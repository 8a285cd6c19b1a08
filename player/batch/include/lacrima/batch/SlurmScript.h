#pragma once
// The Slurm job array that runs a batch on a cluster (docs/batch.md): task I of N runs
// `lacrima-batch MANIFEST --out DIR --shard I/N` on whichever node Slurm gives it; the
// software renderer needs no GPU, and lacrima-batch starts its own virtual display.
#include <string>

namespace lacrima::batch {

struct SlurmSettings {
  std::string batchProgram;  // absolute path of lacrima-batch, the same on every node
  std::string manifest;      // absolute
  std::string outDir;        // absolute, on storage every node shares
  int jobCount = 0;          // distinct jobs in the manifest
  int arraySize = 1;         // tasks (shards)
  int cpusPerTask = 2;
  int memoryMiB = 4096;
  int minutesPerJob = 10;  // the time limit is this times the jobs of the largest shard
  std::string partition;   // "" for the cluster's default
};

// The sbatch script, its resources stated as #SBATCH lines.
std::string slurmScript(const SlurmSettings& settings);

// "D-HH:MM:SS" as sbatch --time reads it.
std::string slurmTime(long long minutes);

}  // namespace lacrima::batch
