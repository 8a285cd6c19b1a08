#pragma once
// A project folder that names the ICT-FaceKit head by relative paths, as a user would lay it
// out: project.json beside heads/ict.obj (with its material file) and heads/ict.fdp.json.
// Shared by the editor and player suites; they check for ../shared first (LACRIMA_REQUIRE_SHARED).
#include "../rigging/TestHeadFiles.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

namespace lacrima::rigtest {

// Copies the ICT head into `folder`/heads and writes `folder`/project.json naming it, with
// `keys` as the project's "keys" array (JSON text) and `fdpText` as the feature-point file
// (empty: the hand-made one). Returns the project's path, or an empty string on failure.
inline QString writeIctProject(const QString& folder, const QByteArray& keys,
                               const QByteArray& fdpText = {}) {
  const QDir dir(folder);
  if (!dir.mkpath(QStringLiteral("heads"))) return {};
  const QString meshFolder = QFileInfo(kIctMesh).path();
  if (!QFile::copy(kIctMesh, dir.filePath(QStringLiteral("heads/ict.obj")))) return {};
  // The OBJ names its materials' file; the sub-mesh names come from its usemtl lines.
  QFile::copy(meshFolder + QStringLiteral("/ICTFaceModelMaterial.mtl"),
              dir.filePath(QStringLiteral("heads/ICTFaceModelMaterial.mtl")));
  const QString fdpPath = dir.filePath(QStringLiteral("heads/ict.fdp.json"));
  if (fdpText.isEmpty()) {
    if (!QFile::copy(kIctFdp, fdpPath)) return {};
  } else {
    QFile fdp(fdpPath);
    if (!fdp.open(QIODevice::WriteOnly) || fdp.write(fdpText) != fdpText.size()) return {};
  }
  const QString projectPath = dir.filePath(QStringLiteral("project.json"));
  QFile project(projectPath);
  if (!project.open(QIODevice::WriteOnly)) return {};
  project.write(
      "{\"format\": \"lacrima-project\", \"version\": 1, \"name\": \"ict\",\n"
      " \"head\": {\"mesh\": \"heads/ict.obj\", \"fdp\": \"heads/ict.fdp.json\"},\n"
      " \"keys\": " +
      keys + "}\n");
  return projectPath;
}

}  // namespace lacrima::rigtest
