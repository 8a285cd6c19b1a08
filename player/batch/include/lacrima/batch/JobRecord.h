#pragma once
// A job's job.json: what it was asked, what ran it, how long it took, what it simulated and what
// it wrote, each output with its size and SHA-256. It is written last, into the job's scratch
// folder, before the folder is renamed into place: a job folder with a job.json saying "done" is
// whole (docs/batch.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::batch {

struct OutputFile {
  std::string file;  // relative to the job's folder, '/'-separated
  long long bytes = 0;
  std::string sha256;
  bool operator==(const OutputFile&) const = default;
};

// What lacrima-player --stats reports of a run (exporting::RunStatistics).
struct RunFigures {
  int frames = 0, framesWithTears = 0, peakParticles = 0;
  std::string tearStateHash;  // 16 hex digits
  bool operator==(const RunFigures&) const = default;
};

// Reads a --stats file; throws FileError naming what is wrong.
RunFigures readRunFigures(const std::string& path);

struct JobRecord {
  static constexpr long long kMaxFileBytes = 64LL << 20;
  static constexpr std::size_t kMaxOutputs = 1000000;

  std::string id;
  bool done = false;    // false: failed, `error` says why
  std::string error;    // the first failing step and its message
  std::string job;      // canonicalJson of the job
  std::string label;    // BatchJob::label, for people
  std::string version;  // lacrima-batch's
  std::string host;     // the machine that ran it
  double wallSeconds = 0;
  std::optional<RunFigures> statistics;  // absent when no player ran
  std::vector<OutputFile> outputs;       // sorted by file

  std::string toJson() const;
  // Throws FileError (file, line, what was expected) for a damaged record.
  static JobRecord read(const std::string& path);
  // SHA-256 over "file sha256\n" of every output: one fingerprint of all the job wrote.
  std::string outputsSha256() const;
};

// Every regular file under `folder` but job.json, with sizes and SHA-256, sorted by path.
std::vector<OutputFile> listOutputs(const std::string& folder);

// Whether `folder` holds a finished job `id`: its job.json reads, says done, names `id`, and
// every output it lists is there with its size (and, with `verifyHashes`, its SHA-256).
bool isComplete(const std::string& folder, const std::string& id, bool verifyHashes);

}  // namespace lacrima::batch
