#pragma once
// The real heads the benchmarks run on when they are present on this machine: the cached
// default head (packaging/fetch-default-head.sh) and the ICT-FaceKit head in the shared
// reference folder, each with its feature-point file from the source tree. Absent heads are
// reported with a reason so a benchmark can print a note and skip them instead of failing.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <optional>
#include <string>

namespace lacrima::bench {

struct RealHeadSpec {
  std::string name;
  bool defaultHead = false;  // loadDefaultHead() from the cache, else importHeadMesh(meshPath)
  std::string meshPath;      // for imported heads
  std::string fdpPath;
};

RealHeadSpec defaultHeadSpec();
RealHeadSpec ictHeadSpec();

struct LoadedHead {
  HeadMesh mesh;
  rigging::FeaturePointFile fdp;  // read and validated against `mesh`
};

// Loads the mesh alone; nullopt with `why` set when its files are absent or unreadable.
std::optional<HeadMesh> loadRealMesh(const RealHeadSpec& spec, std::string& why);
// Loads the mesh and its feature-point file; nullopt with `why` set when either is missing.
std::optional<LoadedHead> loadRealHead(const RealHeadSpec& spec, std::string& why);

}  // namespace lacrima::bench
