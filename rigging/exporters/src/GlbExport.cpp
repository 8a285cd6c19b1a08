#include <lacrima/exporters/GlbExport.h>

#include <lacrima/exporters/GltfDocument.h>
#include <lacrima/exporters/RigExport.h>

namespace lacrima::exporters {

void exportGlb(const HeadMesh& head, const PoseSet& poses, const std::string& path) {
  const std::vector<ExportedPose> exported = prepareRigExport(head, poses, path);
  std::vector<std::string> names;
  for (const ExportedPose& pose : exported) names.push_back(pose.name);
  GltfDocument document;
  document.addHead(head, exported, names, -1);
  document.save(path);
}

}  // namespace lacrima::exporters
