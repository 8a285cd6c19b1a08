#include "SlideScene.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/tears/SyntheticSkin.h>
#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace lacrima::bench {

using namespace lacrima::tears;

namespace {

constexpr double kHeadHeight = 2.7;  // the sheet stands in for a decimetre head (TearsPipeline)
constexpr double kPlateHeight = 3.0, kPlateWidth = 1.0;  // dm, along and across the slope

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

SlideRun runSlide(const SlideSetup& setup) {
  // The cheek sheet's generator leans a vertical sheet back by `tilt`; a plate at alpha from the
  // horizontal is one leaned back by 90 - alpha, and a huge cylinder radius makes it flat.
  CheekSheetOptions plateOptions;
  plateOptions.width = kPlateWidth;
  plateOptions.height = kPlateHeight;
  plateOptions.cylinderRadius = 1e4;
  plateOptions.tiltDegrees = 90 - setup.angleDegrees;
  const SyntheticSkin plate = makeCheekSheet(plateOptions);
  // Down the slope: the sheet's "down" (-v) leaned as the sheet is (SyntheticSkin.cpp).
  const Eigen::Vector3d downhill =
      Eigen::AngleAxisd(-radians(plateOptions.tiltDegrees), Eigen::Vector3d::UnitX()) *
      Eigen::Vector3d(0, -1, 0);
  // The lower edge is at v = -height / 2, i.e. height / 2 down the slope from the centre; a
  // drop within 0.2 dm of it may be falling off, and its speed no longer the slide's.
  const double edge = downhill.dot(plate.centre) + 0.5 * kPlateHeight - 0.2;

  SimulationOptions options;
  options.pressureSolver = setup.solver;
  options.threads = setup.threads;
  options.headHeight = kHeadHeight;
  if (!setup.trailLoss) options.trailDecayMetres = 1e12;  // e-folds after 10^12 m: none
  options.scaleSubsteps(setup.lambdaScale);               // as the sweep
  TearSimulation sim(plate.positions, plate.triangles, TearSettings{}, options);
  sim.setSource(Eye::Left, plate.leftSource);
  sim.setSource(Eye::Right, plate.rightSource);

  // Down-slope position of the centroid and of the lowest particle; NaN when none is left.
  SlideRun r;
  auto measure = [&](double& centroid, double& front) {
    const ParticleSet& p = sim.particles();
    centroid = std::numeric_limits<double>::quiet_NaN();
    front = centroid;
    if (p.size() == 0) return;
    double sum = 0, lowest = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& x : p.position) {
      if (!x.allFinite()) r.finite = false;
      const double s = downhill.dot(x);
      sum += s;
      lowest = std::max(lowest, s);
    }
    centroid = sum / p.size();
    front = lowest;
  };

  const double dt = 1.0 / setup.fps;
  const int total = setup.settleFrames + setup.measureFrames;
  const int half = setup.settleFrames + setup.measureFrames / 2;
  double start = 0, middle = 0, end = 0, frontStart = 0, frontEnd = 0, unused = 0, ms = 0;
  for (int f = 1; f <= total; ++f) {
    const auto begin = SteadyClock::now();
    sim.step(plate.positions, setup.particles, 0, dt);  // the count holds: one drop, emitted once
    ms += millisecondsSince(begin);
    if (f == setup.settleFrames) measure(start, frontStart);
    if (f == half) measure(middle, unused);
    if (f == total) measure(end, frontEnd);
  }
  const double metres = 1.0 / sim.scale().headUnitsPerMetre;
  const double window = setup.measureFrames * dt;
  r.speed = (end - start) * metres / window;
  r.earlySpeed = (middle - start) * metres / (window / 2);
  r.lateSpeed = (end - middle) * metres / (window / 2);
  r.frontSpeed = (frontEnd - frontStart) * metres / window;
  r.msPerFrame = ms / total;
  r.substepsPerFrame = double(sim.counters().substeps) / total;
  r.alive = sim.particles().size();
  double mass = 0;
  for (double m : sim.particles().mass) mass += m;
  r.massLeft = mass / (setup.particles * sim.parameters().particleMass);
  r.recycled = sim.counters().recycled;
  r.onPlate =
      r.alive == setup.particles && r.recycled == 0 && std::isfinite(end) && frontEnd < edge;
  r.finite = r.finite && std::isfinite(r.speed);
  return r;
}

double SlidePhysics::bondNumber() const {
  return density * gravity * std::cbrt(volume * volume) / tension;
}

double SlidePhysics::dragLimitedSpeed(double angleDegrees) const {
  const double a = radians(angleDegrees);
  return gravity * std::sin(a) / (dragRate * (gravity * std::cos(a) + adhesion));
}

SlidePhysics slidePhysics(const TearSettings& settings, int particles) {
  const ScaledParameters p =
      ScaledParameters::from(settings, UnitScale::fromHeadHeight(kHeadHeight));
  const double perMetre = p.headUnitsPerMetre;
  SlidePhysics s;
  // Rest density is normalised to 1 in the solver and stands for water's 1000 kg/m^3; the
  // solver's kinematic viscosity and sigma / rho0 are per unit density, so they scale by it.
  s.viscosity = s.density * p.kinematicViscosity / (perMetre * perMetre);
  s.tension = s.density * p.tensionSigma / (perMetre * perMetre * perMetre);
  s.gravity = p.gravity / perMetre;
  s.adhesion = p.adhesion / perMetre;
  s.volume = particles * std::pow(p.spacing / perMetre, 3);
  s.dragRate = p.friction * perMetre;  // s per head unit -> s per metre
  return s;
}

}  // namespace lacrima::bench
