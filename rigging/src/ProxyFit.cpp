#include "ProxyFit.h"

#include <lacrima/common/Diagnostics.h>

namespace lacrima::rigging {

Eigen::Matrix3Xf fitProxy(const ThreeModel& proxy, const Eigen::Matrix3Xf& base) {
  if (!proxy.isProxy())
    throw FileError(
        SourceLocation{proxy.path},
        "expected a proxy bound to the base mesh (\"ref_vIdxs\", \"weights\", \"offsets\")");
  const ThreeProxyBinding& b = proxy.binding;
  if (b.refs.maxCoeff() >= base.cols())
    throw FileError(SourceLocation{proxy.path},
                    "\"ref_vIdxs\" points at base-mesh vertex " +
                        std::to_string(b.refs.maxCoeff()) + ", but the base mesh has " +
                        std::to_string(base.cols()) + ": a proxy for another base mesh?");
  Eigen::Matrix3Xf fitted = b.offsets;
  for (Eigen::Index v = 0; v < fitted.cols(); ++v)
    for (int k = 0; k < 3; ++k) fitted.col(v) += b.weights(k, v) * base.col(b.refs(k, v));
  return fitted;
}

}  // namespace lacrima::rigging
