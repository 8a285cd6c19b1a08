#pragma once
// Runs a manifest's jobs, or one shard of them, K at a time, into DIR/ID/ folders, resumably:
// a job counts as done only once its folder holds a job.json saying so (JobRecord.h), so a run
// killed at any moment leaves finished jobs, which the next run skips, and scratch folders,
// which it clears and redoes. DIR/summary.csv lists every job of the manifest.
#include <lacrima/batch/BatchManifest.h>
#include <lacrima/batch/JobRunner.h>

#include <cstdio>
#include <string>
#include <vector>

namespace lacrima::batch {

// A job with its fingerprinted settings and id.
struct PlannedJob {
  BatchJob job;
  std::string canonical;  // canonicalJson
  std::string id;         // jobId(canonical)
};

// Every distinct job of the manifest, sorted by id: the stable order shards are cut from.
std::vector<PlannedJob> planJobs(const BatchManifest& manifest);

// The `index`-th (1-based) of `count` shares: the jobs at positions index-1, index-1+count, ...
// of `jobs`, so shares differ in size by one job at most.
std::vector<PlannedJob> shardOf(const std::vector<PlannedJob>& jobs, int index, int count);

struct BatchOptions {
  std::string outDir;
  int shardIndex = 1, shardCount = 1;
  int parallel = 1;           // --jobs
  bool verifyHashes = false;  // --verify: rehash outputs before skipping a job
  bool progressLine = false;  // a live line on a terminal, else a line per job
  std::string version;        // recorded in job.json
};

struct BatchResult {
  int planned = 0, skipped = 0, done = 0, failed = 0;
  bool stoppedOnUsageError = false;
  std::vector<std::string> failures;  // "ID (label): error"
};

// Runs the shard's jobs that are not complete. Throws FileError when DIR cannot be written.
BatchResult runBatch(const std::vector<PlannedJob>& all, const BatchOptions& options,
                     JobRunner& runner, std::FILE* log);

// DIR/summary.csv (written atomically): a row per job of `all`, sorted by id, from the job.json
// files found; "pending" for the others. Nothing time-dependent, so complete runs of the same
// manifest give the same file wherever and however they ran.
void writeSummary(const std::vector<PlannedJob>& all, const std::string& outDir);

}  // namespace lacrima::batch
