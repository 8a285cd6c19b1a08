#include "TearsPipeline.h"

#include "RealHeads.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/tears/SyntheticSkin.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <exception>
#include <numbers>

namespace lacrima::bench {

using namespace lacrima::tears;

std::unique_ptr<TearSimulation> TearScene::simulate(const TearSettings& settings,
                                                    SimulationOptions options) const {
  if (head) {
    HeadTearOptions sources;  // the rig's, as the player passes them
    sources.leftSource = leftSource;
    sources.rightSource = rightSource;
    return TearSimulation::forHead(*head, settings, options, sources);
  }
  options.headHeight = headHeight;
  auto sim = std::make_unique<TearSimulation>(rest, skinTriangles, settings, options);
  sim->setSource(Eye::Left, leftSource);
  sim->setSource(Eye::Right, rightSource);
  return sim;
}

Eigen::Matrix3Xf TearScene::positionsAt(double t, bool sway) const {
  if (!sway) return rest;
  // The same motion the sheet benchmark always used: 2 cm at 0.5 Hz, 0.08 rad about y at 0.3 Hz
  // (in head units: decimetres for both scenes).
  const Eigen::Vector3d shift(0.02 * std::sin(2 * std::numbers::pi * 0.5 * t), 0, 0);
  const Eigen::AngleAxisd turn(0.08 * std::sin(2 * std::numbers::pi * 0.3 * t),
                               Eigen::Vector3d::UnitY());
  const Eigen::Matrix3f r = turn.toRotationMatrix().cast<float>();
  const Eigen::Vector3f c = centre.cast<float>(), s = shift.cast<float>();
  return ((r * (rest.colwise() - c)).colwise() + (c + s)).eval();
}

TearScene cheekScene() {
  const SyntheticSkin sheet = makeCheekSheet();
  TearScene scene;
  scene.name = "cheek sheet";
  scene.rest = sheet.positions;
  scene.skinTriangles = sheet.triangles;
  scene.centre = sheet.centre;
  scene.radius = sheet.radius;
  scene.leftSource = sheet.leftSource;
  scene.rightSource = sheet.rightSource;
  scene.headHeight = 2.7;  // the sheet stands in for a decimetre head
  return scene;
}

std::optional<TearScene> defaultHeadScene(std::string& why) {
  std::optional<LoadedHead> loaded = loadRealHead(defaultHeadSpec(), why);
  if (!loaded) return std::nullopt;
  const HeadSubmesh* skin = loaded->mesh.findSubmesh("skin");
  if (!skin) {
    why = "the default head has no 'skin' sub-mesh";
    return std::nullopt;
  }
  TearScene scene;
  try {
    // The rig's tear sources (skin just below each lower-lid mid-point), as the player uses.
    const rigging::BuiltRig rig = rigging::buildRig(loaded->mesh, loaded->fdp);
    scene.leftSource = rig.tearLeft.position;
    scene.rightSource = rig.tearRight.position;
  } catch (const std::exception& e) {
    why = std::string("rigging the default head failed: ") + e.what();
    return std::nullopt;
  }
  scene.name = "default head";
  scene.rest = loaded->mesh.positions;
  scene.skinTriangles =
      skin->triangles;  // the trail builder's skin; forHead adds the eyes after it
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3i& t : scene.skinTriangles)
    for (int k = 0; k < 3; ++k) box.extend(scene.rest.col(t[k]).cast<double>());
  scene.centre = box.center();
  scene.radius = 0.5 * box.sizes().y();
  scene.head = std::move(loaded->mesh);
  return scene;
}

TearPipeline::TearPipeline(const TearScene& scene, const TearSettings& settings,
                           const SimulationOptions& options)
    : sim_(scene.simulate(settings, options)), trails_(scene.skinTriangles) {}

FrameTimes TearPipeline::step(const Eigen::Matrix3Xf& positions, int left, int right, double dt) {
  FrameTimes t;
  const auto start = SteadyClock::now();
  sim_->step(positions, left, right, dt);
  t.simulation = millisecondsSince(start);
  mesher_.update(*sim_);
  t.surface = mesher_.stats().milliseconds;
  trails_.update(*sim_, positions, dt);
  t.trails = trails_.lastMilliseconds();
  return t;
}

std::optional<TearScene> benchScene(bool head, const char* bench) {
  if (!head) return cheekScene();
  std::string why;
  std::optional<TearScene> scene = defaultHeadScene(why);
  if (!scene) std::printf("%s: skipping the default head: %s\n", bench, why.c_str());
  return scene;
}

}  // namespace lacrima::bench
