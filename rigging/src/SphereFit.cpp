#include <lacrima/rigging/SphereFit.h>

#include <Eigen/QR>

#include <cmath>

namespace lacrima::rigging {

std::optional<Sphere> fitSphere(const Eigen::Matrix3Xd& points) {
  const Eigen::Index n = points.cols();
  if (n < 4) return std::nullopt;
  const Eigen::Vector3d mean = points.rowwise().mean();
  const Eigen::Matrix3Xd q = points.colwise() - mean;
  // Rows [2x 2y 2z 1] (c', k) = |q|^2, with c' the centre relative to the mean.
  Eigen::MatrixXd a(n, 4);
  a.leftCols<3>() = 2.0 * q.transpose();
  a.col(3).setOnes();
  const Eigen::VectorXd b = q.colwise().squaredNorm().transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 4) return std::nullopt;
  const Eigen::Vector4d x = qr.solve(b);
  const double r2 = x[3] + x.head<3>().squaredNorm();
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  return Sphere{mean + x.head<3>(), std::sqrt(r2)};
}

std::optional<Sphere> fitSphere(const HeadMesh& mesh, const std::vector<std::string>& names) {
  Eigen::Index count = 0;
  for (const std::string& name : names) count += mesh.findSubmesh(name)->vertexCount;
  Eigen::Matrix3Xd points(3, count);
  Eigen::Index k = 0;
  for (const std::string& name : names) {
    const HeadSubmesh& s = *mesh.findSubmesh(name);
    points.middleCols(k, s.vertexCount) =
        mesh.positions.middleCols(s.firstVertex, s.vertexCount).cast<double>();
    k += s.vertexCount;
  }
  return fitSphere(points);
}

}  // namespace lacrima::rigging
