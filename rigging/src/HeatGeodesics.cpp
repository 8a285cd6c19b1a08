#include <lacrima/rigging/HeatGeodesics.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace lacrima::rigging {

namespace {

// Below this ratio of twice the area to the summed squared edge lengths a triangle counts as
// flat: the ratio is ~0.29 for an equilateral triangle and ~sin(angle)/2 for a needle.
constexpr double kFlatRatio = 1e-4;
constexpr double kMassFloor = 1e-12;     // relative to the mean lumped mass
constexpr double kPoissonShift = 1e-12;  // relative to the mean diagonal of -L

}  // namespace

HeatGeodesics::HeatGeodesics(const SurfaceGraph& graph, double timeFactor, bool straightLineBound)
    : positions_(graph.positions),
      nodeOfVertex_(graph.nodeOfVertex),
      component_(graph.component),
      componentCount_(graph.componentCount),
      straightLineBound_(straightLineBound) {
  if (!std::isfinite(timeFactor) || timeFactor <= 0)
    throw std::invalid_argument("HeatGeodesics: the time factor must be finite and > 0");
  const int n = graph.nodeCount();
  timeStep_ = timeFactor * graph.meanEdgeLength * graph.meanEdgeLength;

  std::vector<Eigen::Triplet<double>> laplacian;  // L, summed on construction
  laplacian.reserve(graph.triangles.size() * 9);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  faces_.reserve(graph.triangles.size());
  for (const Eigen::Vector3i& t : graph.triangles) {
    Face f;
    f.nodes = t;
    Eigen::Vector3d p[3], e[3];
    for (int i = 0; i < 3; ++i) p[i] = positions_.col(t[i]);
    for (int i = 0; i < 3; ++i) e[i] = p[(i + 2) % 3] - p[(i + 1) % 3];  // opposite corner i
    const Eigen::Vector3d cross = (p[1] - p[0]).cross(p[2] - p[0]);
    const double twiceArea = cross.norm();
    const double scale = e[0].squaredNorm() + e[1].squaredNorm() + e[2].squaredNorm();
    // Distinct nodes have distinct positions, so scale > 0; the guard only keeps a broken
    // input from dividing 0 by 0.
    const double denominator = std::max(twiceArea, kFlatRatio * scale);
    f.flat = !(twiceArea >= kFlatRatio * scale) || denominator <= 0;
    for (int i = 0; i < 3; ++i) {
      // cot of the angle at corner i = (p_j - p_i).(p_k - p_i) / |cross|, clamped as above.
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      f.cot[i] = denominator > 0 ? (p[j] - p[i]).dot(p[k] - p[i]) / denominator : 0.0;
      const double w = 0.5 * f.cot[i];  // weight of the edge jk opposite corner i
      laplacian.emplace_back(t[j], t[k], w);
      laplacian.emplace_back(t[k], t[j], w);
      laplacian.emplace_back(t[j], t[j], -w);
      laplacian.emplace_back(t[k], t[k], -w);
      mass[t[i]] += twiceArea / 6.0;
    }
    if (f.flat) {
      f.gradient.setZero();
    } else {
      const Eigen::Vector3d normal = cross / twiceArea;
      for (int i = 0; i < 3; ++i) f.gradient.col(i) = normal.cross(e[i]) / twiceArea;
    }
    faces_.push_back(f);
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(laplacian.begin(), laplacian.end());

  // Heat system M - t L, with a mass floor for nodes that only touch flat triangles.
  const double meanMass = n > 0 ? mass.sum() / n : 0.0;
  const double massFloor = kMassFloor * (meanMass > 0 ? meanMass : 1.0);
  Eigen::SparseMatrix<double> heat = -timeStep_ * L;
  for (int i = 0; i < n; ++i) heat.coeffRef(i, i) += std::max(mass[i], massFloor);
  heat_.compute(heat);
  if (heat_.info() != Eigen::Success)
    throw std::runtime_error("HeatGeodesics: factoring the heat system failed");

  // Poisson system -L with the first node of every component pinned (row and column replaced
  // by the identity), plus a tiny diagonal shift.
  std::vector<char> pinned(static_cast<size_t>(n), 0);
  std::vector<char> seen(static_cast<size_t>(componentCount_), 0);
  for (int i = 0; i < n; ++i) {
    char& s = seen[static_cast<size_t>(component_[static_cast<size_t>(i)])];
    if (!s) pinned[static_cast<size_t>(i)] = s = 1;
  }
  const double meanDiagonal = n > 0 ? -L.diagonal().sum() / n : 0.0;
  const double shift = kPoissonShift * (meanDiagonal > 0 ? meanDiagonal : 1.0);
  std::vector<Eigen::Triplet<double>> poisson;
  poisson.reserve(static_cast<size_t>(L.nonZeros()) + static_cast<size_t>(n));
  for (int col = 0; col < L.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, col); it; ++it)
      if (!pinned[static_cast<size_t>(it.row())] && !pinned[static_cast<size_t>(it.col())])
        poisson.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), -it.value());
  for (int i = 0; i < n; ++i)
    poisson.emplace_back(i, i, pinned[static_cast<size_t>(i)] ? 1.0 : shift);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(poisson.begin(), poisson.end());
  poisson_.compute(A);
  if (poisson_.info() != Eigen::Success)
    throw std::runtime_error("HeatGeodesics: factoring the Poisson system failed");
  pinned_ = std::move(pinned);
}

Eigen::VectorXd HeatGeodesics::distances(const Eigen::VectorXi& sources) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(positions_.cols());
  const int meshVertices = static_cast<int>(nodeOfVertex_.size());
  if (sources.size() == 0) throw std::invalid_argument("HeatGeodesics: no source");

  Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
  std::vector<int> sourceNodes;
  for (const int v : sources) {
    const int node = v >= 0 && v < meshVertices ? nodeOfVertex_[static_cast<size_t>(v)] : -1;
    if (node < 0)
      throw std::invalid_argument("HeatGeodesics: source vertex " + std::to_string(v) +
                                  " is not in the surface graph");
    if (delta[node] == 0) sourceNodes.push_back(node);
    delta[node] = 1;
  }

  // 1. Heat flow for one (backward Euler) step.
  const Eigen::VectorXd u = heat_.solve(delta);

  // 2 and 3. Unit field against the heat gradient, and its integrated divergence.
  Eigen::VectorXd divergence = Eigen::VectorXd::Zero(n);
  for (const Face& f : faces_) {
    if (f.flat) continue;
    const Eigen::Vector3d corners(u[f.nodes[0]], u[f.nodes[1]], u[f.nodes[2]]);
    Eigen::Vector3d g = f.gradient * corners;
    // Far from the sources u is tiny; divide by the largest component first so squaring
    // cannot underflow and a zero gradient (no heat, or constant heat) gives X = 0.
    const double largest = g.cwiseAbs().maxCoeff();
    if (!(largest > 0) || !std::isfinite(largest)) continue;
    g /= largest;
    const Eigen::Vector3d X = -g / g.norm();
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const Eigen::Vector3d pi = positions_.col(f.nodes[i]);
      divergence[f.nodes[i]] += 0.5 * (f.cot[k] * (positions_.col(f.nodes[j]) - pi).dot(X) +
                                       f.cot[j] * (positions_.col(f.nodes[k]) - pi).dot(X));
    }
  }
  // L phi = div X, solved as (-L) phi = -div X; pinned rows read phi = 0.
  Eigen::VectorXd rhs = -divergence;
  for (int i = 0; i < n; ++i)
    if (pinned_[static_cast<size_t>(i)]) rhs[i] = 0;
  Eigen::VectorXd phi = poisson_.solve(rhs);

  // 4. Shift each component so its sources sit at 0 (on average; then exactly); components
  // without a source are unreachable.
  std::vector<double> offset(static_cast<size_t>(componentCount_), 0.0);
  std::vector<int> count(static_cast<size_t>(componentCount_), 0);
  for (const int node : sourceNodes) {
    const auto c = static_cast<size_t>(component_[static_cast<size_t>(node)]);
    offset[c] += phi[node];
    ++count[c];
  }
  for (int i = 0; i < n; ++i) {
    const auto c = static_cast<size_t>(component_[static_cast<size_t>(i)]);
    if (count[c] == 0) {
      phi[i] = kInfinity;
      continue;
    }
    // 5. No path over the surface is shorter than the straight segment to the nearest source
    // of the component, so raising phi to that bound can only remove error.
    double straight = 0;
    if (straightLineBound_) {
      straight = kInfinity;
      for (const int node : sourceNodes)
        if (component_[static_cast<size_t>(node)] == component_[static_cast<size_t>(i)])
          straight = std::min(straight, (positions_.col(i) - positions_.col(node)).norm());
    }
    const double d = phi[i] - offset[c] / count[c];
    phi[i] = std::isfinite(d) ? std::max(d, straight) : kInfinity;
  }
  for (const int node : sourceNodes) phi[node] = 0;

  Eigen::VectorXd out(meshVertices);
  for (int v = 0; v < meshVertices; ++v) {
    const int node = nodeOfVertex_[static_cast<size_t>(v)];
    out[v] = node < 0 ? kInfinity : phi[node];
  }
  return out;
}

}  // namespace lacrima::rigging
