#pragma once
// A batch manifest (docs/batch.md): jobs listed, or a grid that expands into jobs.
//
//   { "format": "lacrima-batch", "version": 1,
//     "defaults": { "size": "640x360", "frames": "0-109", "outputs": ["frames", "masks"] },
//     "jobs": [ { "animation": "takes/sad.fap" } ],
//     "grid": { "take": [ { "mood": "sadness=0.8", "seed": 1 }, { "mood": "joy=0.7" } ],
//               "view": ["front", "three-quarter"] },
//     "paired": true }
//
// Every job starts from "defaults". A grid axis named as a job field lists that field's values;
// any other axis lists objects of job fields. The grid is the product of its axes, in the order
// of their names. "paired" runs every job twice, with and without tears. Relative paths are from
// the manifest's folder; files must exist. Anything else is a FileError naming the file, line,
// column, JSON path and what was expected.
#include <lacrima/batch/BatchJob.h>

#include <cstddef>
#include <string>
#include <vector>

namespace lacrima::batch {

struct BatchManifest {
  static constexpr std::size_t kMaxJobs = 100000;  // after expansion, pairs included
  static constexpr long long kMaxFileBytes = 16LL << 20;

  std::string path;            // as given
  std::vector<BatchJob> jobs;  // "jobs" first, then the grid's product, each pair together
};

BatchManifest readManifest(const std::string& path);

}  // namespace lacrima::batch
