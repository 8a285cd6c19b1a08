#pragma once
// Work for a RigJob: the ways the editor gets a rigged head, each reporting its stages so the
// window can show progress while a worker thread does the rigging.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/editor/RigJob.h>

#include <string>

namespace lacrima::editor {

// The default head (fetched at set-up) with media/default-head.fdp.json.
RigJob::Work defaultHeadWork();
// A mesh assimp reads and its feature-point file: read both, then rig with progress. Throws
// (on the worker, so RigJob reports failed()) the readers' FileErrors, naming the file.
RigJob::Work headFilesWork(std::string meshPath, std::string fdpPath);
// Fails with `problem` (e.g. a project's head file that is missing), through the same path as
// any other rigging failure, so it supersedes a job still running for another head.
RigJob::Work failingWork(Diagnostic problem);

}  // namespace lacrima::editor
