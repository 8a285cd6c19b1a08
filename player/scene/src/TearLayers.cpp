#include "TearLayers.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailBuilder.h>

#include <OgreMaterialManager.h>
#include <OgrePass.h>
#include <OgreRenderObjectListener.h>
#include <OgreRenderQueue.h>
#include <OgreRenderSystem.h>
#include <OgreRoot.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include <array>
#include <limits>

namespace lacrima::scene::detail {
namespace {

using Attribute = StreamedGeometry::Attribute;
constexpr std::array kSurfaceLayout{Attribute{Ogre::VET_FLOAT3, Ogre::VES_POSITION},
                                    Attribute{Ogre::VET_FLOAT3, Ogre::VES_NORMAL}};
constexpr std::array kTrailLayout{Attribute{Ogre::VET_FLOAT3, Ogre::VES_POSITION},
                                  Attribute{Ogre::VET_FLOAT3, Ogre::VES_NORMAL},
                                  Attribute{Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES, 0},
                                  Attribute{Ogre::VET_FLOAT3, Ogre::VES_TANGENT}};
constexpr std::array kImpostorLayout{Attribute{Ogre::VET_FLOAT3, Ogre::VES_POSITION},
                                     Attribute{Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES, 0}};

struct Bounds {
  Eigen::Vector3f low = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f high = -low;
  void add(const Eigen::Vector3f& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
};

enum class Order { AsGiven, Reversed };

// Positions and normals per vertex, then whatever `extra(v, out)` appends for vertex v (it
// returns the pointer past what it wrote), then the triangles in the given order.
template <typename Positions, typename Normals, typename Triangles, typename Extra>
void upload(StreamedGeometry& geometry, const Positions& positions, const Normals& normals,
            const Triangles& triangles, Order order, Extra&& extra) {
  const int n = static_cast<int>(positions.cols());
  const int t = static_cast<int>(triangles.cols());
  if (n == 0 || t == 0) {
    geometry.hide();
    return;
  }
  Bounds bounds;
  float* out = geometry.lockVertices(n);
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3f p = positions.col(v).template cast<float>();
    const Eigen::Vector3f q = normals.col(v).template cast<float>();
    bounds.add(p);
    *out++ = p.x();
    *out++ = p.y();
    *out++ = p.z();
    *out++ = q.x();
    *out++ = q.y();
    *out++ = q.z();
    out = extra(v, out);
  }
  geometry.unlockVertices();
  std::uint32_t* index = geometry.lockIndices(3 * t);
  for (int i = 0; i < t; ++i) {
    const int triangle = order == Order::AsGiven ? i : t - 1 - i;
    for (int k = 0; k < 3; ++k) *index++ = static_cast<std::uint32_t>(triangles(k, triangle));
  }
  geometry.unlockIndices();
  geometry.setDrawn(3 * t, bounds.low, bounds.high);
}

std::unique_ptr<StreamedGeometry> makeLayer(std::span<const Attribute> layout,
                                            const std::string& name, const char* material,
                                            const std::string& group, unsigned char queue,
                                            Ogre::SceneNode& node) {
  auto geometry = std::make_unique<StreamedGeometry>(name, layout);
  geometry->setMaterial(Ogre::MaterialManager::getSingleton().getByName(material, group));
  geometry->setRenderQueueGroup(queue);
  node.attachObject(geometry.get());
  return geometry;
}

void showWater(StreamedGeometry& geometry, const tears::TearSurface* water) {
  if (!water || water->empty()) {
    geometry.hide();
    return;
  }
  upload(geometry, water->positions(), water->normals(), water->triangles(), Order::AsGiven,
         [](int, float* out) { return out; });
}

}  // namespace

class TrailStencil : public Ogre::RenderObjectListener {
 public:
  explicit TrailStencil(const Ogre::Renderable& trails) : trails_(trails) {}

  void notifyRenderSingleObject(Ogre::Renderable* renderable, const Ogre::Pass* pass,
                                const Ogre::AutoParamDataSource*, const Ogre::LightList*,
                                bool) override {
    Ogre::RenderSystem& system = *Ogre::Root::getSingleton().getRenderSystem();
    if (renderable != &trails_) {
      system.setStencilCheckEnabled(false);
      return;
    }
    // Pass 0 (tint) where the mark is 0, pass 1 (light) where it is 1; OGRE passes when
    // (reference compare stencil) holds.
    const auto reference = static_cast<Ogre::uint32>(pass->getIndex() + 1);
    system.setStencilCheckEnabled(true);
    system.setStencilBufferParams(Ogre::CMPF_EQUAL, reference - 1, 0xff, 0xff, Ogre::SOP_KEEP,
                                  Ogre::SOP_KEEP, Ogre::SOP_INCREMENT);
  }

 private:
  const Ogre::Renderable& trails_;
};

TearLayers::TearLayers(Ogre::SceneManager& scene, Ogre::SceneNode& node, const std::string& prefix,
                       const std::string& group)
    : scene_(scene), node_(node) {
  surface_ =
      makeLayer(kSurfaceLayout, prefix + "/surface", "Lacrima/Tear", group, kTearQueue, node);
  drops_ = makeLayer(kSurfaceLayout, prefix + "/drops", "Lacrima/Tear", group, kTearQueue, node);
  trails_ = makeLayer(kTrailLayout, prefix + "/trails", "Lacrima/Trail", group, kTrailQueue, node);
  particles_ = makeLayer(kImpostorLayout, prefix + "/particles", "Lacrima/Particle", group,
                         Ogre::RENDER_QUEUE_MAIN, node);
  particles_->setCustomParameter(0, Ogre::Vector4(0, 0, 0, 0));
  stencil_ = std::make_unique<TrailStencil>(*trails_);
  scene_.addRenderObjectListener(stencil_.get());
}

TearLayers::~TearLayers() {
  scene_.removeRenderObjectListener(stencil_.get());
  for (auto* geometry : {surface_.get(), drops_.get(), trails_.get(), particles_.get()})
    if (geometry && geometry->isAttached()) node_.detachObject(geometry);
}

void TearLayers::showSurface(const tears::TearSurface* surface) { showWater(*surface_, surface); }

void TearLayers::showDrops(const tears::TearSurface* caps) { showWater(*drops_, caps); }

void TearLayers::showTrails(const tears::TrailMesh* trails) {
  if (!trails || trails->empty()) {
    trails_->hide();
    return;
  }
  // Per vertex: (wetness, across), across -1, 0, 1 for a section's left, middle and right point
  // (TrailBuilder stores three vertices per section in that order), and the section's direction
  // from left to right, along which the film's shader rounds its normal. Segments come oldest
  // first; drawn newest first, the freshest water wins the stencil (TrailStencil).
  const auto positions = trails->positions();
  const auto alpha = trails->alpha();
  upload(*trails_, positions, trails->normals(), trails->triangles(), Order::Reversed,
         [&](int v, float* out) {
           const int left = v - v % 3;
           const Eigen::Vector3d span = positions.col(left + 2) - positions.col(left);
           const Eigen::Vector3f across = span.norm() > 0
                                              ? Eigen::Vector3f(span.normalized().cast<float>())
                                              : Eigen::Vector3f::Zero();
           *out++ = static_cast<float>(alpha[v]);
           *out++ = static_cast<float>(v % 3 - 1);
           *out++ = across.x();
           *out++ = across.y();
           *out++ = across.z();
           return out;
         });
}

void TearLayers::showParticles(const tears::ParticleSet* particles, double radius) {
  if (!particles || particles->empty() || !(radius > 0)) {
    particles_->hide();
    return;
  }
  const int n = particles->size();
  static constexpr float kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Bounds bounds;
  float* out = particles_->lockVertices(4 * n);
  for (const Eigen::Vector3d& centre : particles->position) {
    const Eigen::Vector3f c = centre.cast<float>();
    bounds.add(c);
    for (const auto& corner : kCorners) {
      *out++ = c.x();
      *out++ = c.y();
      *out++ = c.z();
      *out++ = corner[0];
      *out++ = corner[1];
    }
  }
  particles_->unlockVertices();
  std::uint32_t* index = particles_->lockIndices(6 * n);
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
    const std::uint32_t b = 4 * i;
    for (std::uint32_t k : {b, b + 1, b + 2, b, b + 2, b + 3}) *index++ = k;
  }
  particles_->unlockIndices();
  const auto r = static_cast<float>(radius);
  particles_->setCustomParameter(0, Ogre::Vector4(r, 0, 0, 0));
  particles_->setDrawn(6 * n, bounds.low - Eigen::Vector3f::Constant(r),
                       bounds.high + Eigen::Vector3f::Constant(r));
}

}  // namespace lacrima::scene::detail
