#pragma once
// Placing a MakeHuman proxy (eyes, teeth, tongue, eyelashes, eyebrows) on the base mesh.
#include "ThreeJsonModel.h"

#include <Eigen/Core>

namespace lacrima::rigging {

// The proxy's vertices fitted to `base`, the full base-mesh vertex array (helper vertices
// included: the bindings point at them). A proxy's own "vertices" were written for other body
// proportions (the package's eyes sit 8.47 dm too high), so only the fitted positions are usable.
// Throws FileError naming the proxy when it is not bound or points past the end of `base`.
Eigen::Matrix3Xf fitProxy(const ThreeModel& proxy, const Eigen::Matrix3Xf& base);

}  // namespace lacrima::rigging
