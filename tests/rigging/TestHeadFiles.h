#pragma once
// Files the rigging tests share: the default head's feature points, the ICT-FaceKit head
// (../shared, optional: tests that need it skip without it, MissingData.h) with its hand-made
// feature-point file, and the rigging tool.
#include "../support/MissingData.h"

#include <QString>

namespace lacrima::rigtest {

inline const QString kDefaultFdp =
    QStringLiteral(LACRIMA_SOURCE_DIR "/media/default-head.fdp.json");
inline const QString kIctMesh =
    testsupport::sharedPath(QStringLiteral("heads/ict-facekit/generic_neutral_mesh.obj"));
inline const QString kIctFdp =
    QStringLiteral(LACRIMA_SOURCE_DIR "/tests/rigging/ict-facekit.fdp.json");
inline const QString kRigTool = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-rig");

}  // namespace lacrima::rigtest
