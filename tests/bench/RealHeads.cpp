#include "RealHeads.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/MeshImport.h>

#include <exception>
#include <filesystem>

namespace lacrima::bench {

RealHeadSpec defaultHeadSpec() {
  return {"default head", true, {}, LACRIMA_SOURCE_DIR "/media/default-head.fdp.json"};
}

RealHeadSpec ictHeadSpec() {
  return {"ICT-FaceKit head", false,
          LACRIMA_SHARED_DIR "/heads/ict-facekit/generic_neutral_mesh.obj",
          LACRIMA_SOURCE_DIR "/tests/rigging/ict-facekit.fdp.json"};
}

std::optional<HeadMesh> loadRealMesh(const RealHeadSpec& spec, std::string& why) {
  try {
    if (spec.defaultHead) {
      if (!rigging::defaultHeadAvailable()) {
        why = "not in the cache " + rigging::defaultHeadPackageDir() +
              " (run packaging/fetch-default-head.sh)";
        return std::nullopt;
      }
      return rigging::loadDefaultHead();
    }
    if (!std::filesystem::exists(spec.meshPath)) {
      why = spec.meshPath + " is absent";
      return std::nullopt;
    }
    return rigging::importHeadMesh(spec.meshPath);
  } catch (const std::exception& e) {
    // A damaged cache or file is a skip with its reason, not a crashed benchmark run.
    why = e.what();
    return std::nullopt;
  }
}

std::optional<LoadedHead> loadRealHead(const RealHeadSpec& spec, std::string& why) {
  if (!std::filesystem::exists(spec.fdpPath)) {
    why = spec.fdpPath + " is absent";
    return std::nullopt;
  }
  std::optional<HeadMesh> mesh = loadRealMesh(spec, why);
  if (!mesh) return std::nullopt;
  try {
    LoadedHead head{std::move(*mesh), {}};
    Warnings warnings;  // missing optional points only cost their FAPs; the bench still runs
    head.fdp = rigging::readFeaturePointFile(spec.fdpPath, &warnings);
    rigging::validateFeaturePoints(head.fdp, head.mesh, &warnings);
    return head;
  } catch (const std::exception& e) {
    why = e.what();
    return std::nullopt;
  }
}

}  // namespace lacrima::bench
