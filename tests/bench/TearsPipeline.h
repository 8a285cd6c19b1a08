#pragma once
// The full tear pipeline as the player runs it each frame (simulation step, surface mesher,
// trail builder), on either the generated cheek sheet or the rigged default head, shared by
// `lacrima-bench tears` and `lacrima-bench tears-sweep` so both time the same work.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TearSimulation.h>
#include <lacrima/tears/TrailBuilder.h>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::bench {

struct TearScene {
  std::string name;                            // "cheek sheet" or "default head"
  Eigen::Matrix3Xf rest;                       // all head (or sheet) vertices
  std::vector<Eigen::Vector3i> skinTriangles;  // by global vertex, as the simulation has them
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1;             // half the skin's height, for escape distances
  std::optional<HeadMesh> head;  // set for a real head: simulations via forHead
  // Tear sources in the head frame: the sheet's, or the rig's for the default head.
  Eigen::Vector3d leftSource = Eigen::Vector3d::Zero(), rightSource = Eigen::Vector3d::Zero();
  double headHeight = 0;  // SimulationOptions::headHeight for the sheet

  // A fresh simulation of this scene (forHead for a head, the sheet's sources otherwise).
  std::unique_ptr<tears::TearSimulation> simulate(const tears::TearSettings& settings,
                                                  tears::SimulationOptions options) const;
  // The skin at time t: the rest pose, or rigidly swayed about the centre when `sway` is set.
  Eigen::Matrix3Xf positionsAt(double t, bool sway) const;
};

TearScene cheekScene();
// The cached default head, rigged for its tear sources; nullopt with `why` set when it is absent
// or unreadable.
std::optional<TearScene> defaultHeadScene(std::string& why);
// The scene a tear benchmark asked for: the default head (`head`) or the cheek sheet. Without
// the head, prints "BENCH: skipping the default head: why" and returns nothing.
std::optional<TearScene> benchScene(bool head, const char* bench);

struct FrameTimes {
  double simulation = 0, surface = 0, trails = 0;  // ms
  double total() const { return simulation + surface + trails; }
};

// One pipeline instance: the simulation and the mesher and trail builder fed from it.
class TearPipeline {
 public:
  TearPipeline(const TearScene& scene, const tears::TearSettings& settings,
               const tears::SimulationOptions& options);
  // Steps every stage one frame; the stages are timed separately.
  FrameTimes step(const Eigen::Matrix3Xf& positions, int left, int right, double dt);

  tears::TearSimulation& simulation() { return *sim_; }
  const tears::SurfaceMesher& mesher() const { return mesher_; }
  const tears::TrailBuilder& trails() const { return trails_; }

 private:
  std::unique_ptr<tears::TearSimulation> sim_;
  tears::SurfaceMesher mesher_;
  tears::TrailBuilder trails_;
};

}  // namespace lacrima::bench
