#include "TearLayers.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailBuilder.h>

#include <OgreMaterialManager.h>
#include <OgreRenderQueue.h>
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
                                  Attribute{Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES, 0}};
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

// Positions, normals and, for trails, (wetness, across) per vertex, then the triangles.
// `across` is -1, 0, 1 for a trail section's left, middle and right point (TrailBuilder stores
// three vertices per section in that order), so the film can thin out towards its edges.
template <typename Positions, typename Normals, typename Triangles>
void upload(StreamedGeometry& geometry, const Positions& positions, const Normals& normals,
            const double* wetness, const Triangles& triangles) {
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
    if (wetness) {
      *out++ = static_cast<float>(wetness[v]);
      *out++ = static_cast<float>(v % 3 - 1);
    }
  }
  geometry.unlockVertices();
  std::uint32_t* index = geometry.lockIndices(3 * t);
  for (int i = 0; i < t; ++i)
    for (int k = 0; k < 3; ++k) *index++ = static_cast<std::uint32_t>(triangles(k, i));
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

}  // namespace

TearLayers::TearLayers(Ogre::SceneManager&, Ogre::SceneNode& node, const std::string& prefix,
                       const std::string& group)
    : node_(node) {
  surface_ =
      makeLayer(kSurfaceLayout, prefix + "/surface", "Lacrima/Tear", group, kTearQueue, node);
  trails_ = makeLayer(kTrailLayout, prefix + "/trails", "Lacrima/Trail", group, kTrailQueue, node);
  particles_ = makeLayer(kImpostorLayout, prefix + "/particles", "Lacrima/Particle", group,
                         Ogre::RENDER_QUEUE_MAIN, node);
  particles_->setCustomParameter(0, Ogre::Vector4(0, 0, 0, 0));
}

TearLayers::~TearLayers() {
  for (auto* geometry : {surface_.get(), trails_.get(), particles_.get()})
    if (geometry && geometry->isAttached()) node_.detachObject(geometry);
}

void TearLayers::showSurface(const tears::TearSurface* surface) {
  if (!surface || surface->empty()) {
    surface_->hide();
    return;
  }
  upload(*surface_, surface->positions(), surface->normals(), nullptr, surface->triangles());
}

void TearLayers::showTrails(const tears::TrailMesh* trails) {
  if (!trails || trails->empty()) {
    trails_->hide();
    return;
  }
  upload(*trails_, trails->positions(), trails->normals(), trails->alpha().data(),
         trails->triangles());
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
