#pragma once
// Tears placed by hand on the default head, for the scene tests and the shot tool: their shape
// and place are known exactly, whatever state the simulation is in. The geometry is still the
// real pipeline's: drops are lattices of SPH particles (the simulation's spacing, mass and
// kernel) sitting on the skin, meshed by SurfaceMesher::build; trails come from TrailBuilder
// watching a drop slide down the cheek, so they are the meshes the player shows.
//
// Per eye: a small pool on the lower lid at the tear source, and a running drop further down a
// slightly curved path over the cheek, with the trail it left from the lid down to it.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/playback/FrameView.h>
#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TearSettings.h>
#include <lacrima/tears/TearSimulation.h>
#include <lacrima/tears/TrailBuilder.h>
#include <lacrima/tears/UniformGrid.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace lacrima::scenetest {

struct SkinHit {
  Eigen::Vector3d point, normal;
  int triangle = -1;  // index into the skin's triangle list
  Eigen::Vector3d barycentric;
};

class SyntheticTears {
 public:
  struct Options {
    double runLength = 0.55;  // head units the running drop has slid below the lid
    int runningDropParticles = 420;
    int poolParticles = 200;
    // Drops that slide down the same path one after the other, each leaving its own trail over
    // the last one's (a stream).
    int streamDrops = 1;
  };

  explicit SyntheticTears(const HeadMesh& head) : SyntheticTears(head, Options{}) {}
  SyntheticTears(const HeadMesh& head, const Options& options) : head_(head) {
    const HeadSubmesh* skin = head.findSubmesh("skin");
    skinTriangles_ = skin->triangles;
    params_ = tears::TearSimulation::forHead(head)->parameters();
    trails_ = std::make_unique<tears::TrailBuilder>(skinTriangles_);

    std::array<std::vector<Eigen::Vector3d>, 2> slidingOffsets;
    for (int e = 0; e < 2; ++e)
      eyes_[static_cast<std::size_t>(e)] = eyeOf(e == 0 ? "eye_l" : "eye_r");

    // The running drop slides from the lid down its path, leaving the trail.
    constexpr int kSteps = 60;
    for (int drop = 0; drop < options.streamDrops; ++drop)
      for (int step = 0; step <= kSteps; ++step) {
        tears::ParticleSet sliding;
        const double s = options.runLength * step / kSteps;
        for (int e = 0; e < 2; ++e) {
          auto hit = pathPoint(e, s);
          if (!hit) continue;
          addDrop(sliding, *hit, 0.55 * radiusFor(options.runningDropParticles), 1.25, e,
                  nextIdBase(e) + 10000 * static_cast<std::uint64_t>(drop),
                  options.runningDropParticles);
        }
        tears::UniformGrid grid;
        grid.build(sliding.position, params_.h);
        trails_->update(sliding, grid, params_.h, params_.particleRadius, head.positions,
                        1.0 / 22.0);
        if (step == kSteps) particles_ = sliding;
      }
    // Pools on the lower lids.
    for (int e = 0; e < 2; ++e)
      if (auto hit = pathPoint(e, 0.0))
        addDrop(particles_, *hit, radiusFor(options.poolParticles), 0.6, e, nextIdBase(e) + 100000,
                options.poolParticles);

    tears::UniformGrid grid;
    grid.build(particles_.position, params_.h);
    tears::SurfaceMesherSettings settings;
    settings.kernelRadius = params_.h;
    settings.cubeSize = params_.cubeSize;
    settings.iso = params_.iso;
    mesher_.build(particles_.position, particles_.mass, grid, settings);
  }

  playback::FrameView view(long long revision = 1) const {
    playback::FrameView v;
    v.neutral = &head_;
    v.positions = &head_.positions;
    v.normals = &head_.normals;
    v.surface = mesher_.surface().empty() ? nullptr : &mesher_.surface();
    v.trails = trails_->mesh().empty() ? nullptr : &trails_->mesh();
    v.revision = revision;
    return v;
  }
  const tears::ParticleSet& particles() const { return particles_; }
  double particleRadius() const { return params_.particleRadius; }
  const tears::TearSurface& surface() const { return mesher_.surface(); }
  const tears::TrailMesh& trails() const { return trails_->mesh(); }
  // Where the drops sit: the lid pool (s = 0) and the running drop (s = runLength) per eye.
  std::optional<SkinHit> pathPoint(int eye, double s) const {
    const auto& e = eyes_[static_cast<std::size_t>(eye)];
    const double outwards = e.first.x() > 0 ? 1 : -1;
    // Down the cheek, drifting outwards and curving back a little, as tears follow the cheekbone.
    const double x = e.first.x() + outwards * (0.04 + 0.10 * s - 0.06 * s * s);
    const double y = e.first.y() - 1.05 * e.second - s;
    return castDown(x, y);
  }

 private:
  std::pair<Eigen::Vector3d, double> eyeOf(const char* name) const {
    const HeadSubmesh* sub = head_.findSubmesh(name);
    const auto cols = head_.positions.middleCols(sub->firstVertex, sub->vertexCount);
    const Eigen::Vector3f low = cols.rowwise().minCoeff(), high = cols.rowwise().maxCoeff();
    return {(0.5f * (low + high)).cast<double>(), 0.5 * double((high - low).maxCoeff())};
  }

  static std::uint64_t nextIdBase(int eye) { return 1 + static_cast<std::uint64_t>(eye) * 1000000; }

  double radiusFor(int particles) const {
    // A half-ellipsoid lattice drop: volume ~ particles x spacing^3 (the lattice's spacing).
    return std::cbrt(3.0 * particles * std::pow(0.7 * params_.spacing, 3) /
                     (2.0 * 3.14159265 * 0.6));
  }

  // The front-most skin point along a ray going -z through (x, y).
  std::optional<SkinHit> castDown(double x, double y) const {
    std::optional<SkinHit> best;
    const Eigen::Vector3d origin(x, y, 100), dir(0, 0, -1);
    for (std::size_t t = 0; t < skinTriangles_.size(); ++t) {
      const Eigen::Vector3i& tri = skinTriangles_[t];
      const Eigen::Vector3d a = head_.positions.col(tri[0]).cast<double>();
      const Eigen::Vector3d b = head_.positions.col(tri[1]).cast<double>();
      const Eigen::Vector3d c = head_.positions.col(tri[2]).cast<double>();
      const double lowX = std::min({a.x(), b.x(), c.x()}), highX = std::max({a.x(), b.x(), c.x()});
      const double lowY = std::min({a.y(), b.y(), c.y()}), highY = std::max({a.y(), b.y(), c.y()});
      if (x < lowX || x > highX || y < lowY || y > highY) continue;
      const Eigen::Vector3d e1 = b - a, e2 = c - a, p = dir.cross(e2);
      const double det = e1.dot(p);
      if (std::abs(det) < 1e-14) continue;
      const Eigen::Vector3d tv = origin - a;
      const double u = tv.dot(p) / det;
      const Eigen::Vector3d q = tv.cross(e1);
      const double v = dir.dot(q) / det;
      if (u < 0 || v < 0 || u + v > 1) continue;
      const Eigen::Vector3d hit = a + u * e1 + v * e2;
      if (best && best->point.z() >= hit.z()) continue;
      SkinHit h;
      h.point = hit;
      h.normal = e1.cross(e2).normalized();
      if (h.normal.z() < 0) h.normal = -h.normal;
      h.triangle = static_cast<int>(t);
      h.barycentric = Eigen::Vector3d(1 - u - v, u, v);
      best = h;
    }
    return best;
  }

  // A lattice drop centred on `at`: radius `r` across, `stretch` x r along the downhill
  // tangent, 0.6 r high, sitting on the skin. Each particle's contact is the skin below it.
  // The lattice is 0.7 times the rest spacing with the mass scaled to match (the same water
  // and density, a smoother surface than a coarse lattice's bumps; a relaxed simulated drop is
  // smooth too).
  void addDrop(tears::ParticleSet& set, const SkinHit& at, double r, double stretch, int eye,
               std::uint64_t idBase, int maxParticles) const {
    const Eigen::Vector3d n = at.normal;
    Eigen::Vector3d down = Eigen::Vector3d(0, -1, 0) - n * (-n.y());
    down.normalize();
    const Eigen::Vector3d across = n.cross(down).normalized();
    const double sp = 0.7 * params_.spacing;
    const double mass = params_.particleMass * 0.7 * 0.7 * 0.7;
    const int reach = static_cast<int>(std::ceil(stretch * r / sp)) + 1;
    std::uint64_t id = idBase;
    int added = 0;
    for (int k = 0; k <= reach && added < maxParticles; ++k)
      for (int j = -reach; j <= reach && added < maxParticles; ++j)
        for (int i = -reach; i <= reach && added < maxParticles; ++i) {
          const double a = i * sp, d = j * sp, h = k * sp;
          const double q = (a / r) * (a / r) + (d / (stretch * r)) * (d / (stretch * r)) +
                           (h / (0.6 * r)) * (h / (0.6 * r));
          if (q > 1) continue;
          const Eigen::Vector3d x =
              at.point + a * across + d * down + (h + params_.particleRadius) * n;
          const int index = set.add(x, mass, id++, eye == 0 ? tears::Eye::Left : tears::Eye::Right);
          auto below = castDown(x.x(), x.y());
          if (below) {
            set.contact[static_cast<std::size_t>(index)].triangle = below->triangle;
            set.contact[static_cast<std::size_t>(index)].barycentric = below->barycentric;
          }
          ++added;
        }
  }

  const HeadMesh& head_;
  std::vector<Eigen::Vector3i> skinTriangles_;
  tears::ScaledParameters params_;
  std::array<std::pair<Eigen::Vector3d, double>, 2> eyes_;
  std::unique_ptr<tears::TrailBuilder> trails_;
  tears::ParticleSet particles_;
  tears::SurfaceMesher mesher_;
};

}  // namespace lacrima::scenetest
