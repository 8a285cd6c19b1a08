#include "MarkerLayer.h"

#include <OgreMaterialManager.h>
#include <OgreSceneNode.h>

#include <array>
#include <cmath>
#include <numbers>

namespace lacrima::scene::detail {
namespace {

using Attribute = StreamedGeometry::Attribute;
constexpr std::array kLayout{Attribute{Ogre::VET_FLOAT3, Ogre::VES_POSITION},
                             Attribute{Ogre::VET_FLOAT3, Ogre::VES_TEXTURE_COORDINATES, 0}};
constexpr int kRim = 16;  // vertices round a disc: round at 20 pixels, cheap at hundreds
constexpr double kOutline = 1.5, kRing = 2.5;  // pixels
// Depth-tested markers are moved this fraction of their distance towards the eye, so the face
// they sit on does not hide them (the disc is flat, the face curves away from it).
constexpr double kDepthNudge = 0.01;

std::unique_ptr<StreamedGeometry> makeLayer(Ogre::SceneNode& node, const std::string& name,
                                            const std::string& material, const std::string& group,
                                            unsigned char queue) {
  auto layer = std::make_unique<StreamedGeometry>(name, kLayout);
  layer->setUseIdentityProjection(true);
  layer->setUseIdentityView(true);
  layer->setRenderQueueGroup(queue);
  layer->setMaterial(Ogre::MaterialManager::getSingleton().getByName(material, group));
  node.attachObject(layer.get());
  return layer;
}

struct Disc {
  Eigen::Vector3d centre;  // clip space, w = 1
  double radiusX, radiusY;
  Eigen::Vector3f colour;
};

// Writes discs as triangle fans into `layer`, in order (later ones over earlier ones).
void draw(StreamedGeometry& layer, const std::vector<Disc>& discs) {
  if (discs.empty()) {
    layer.hide();
    return;
  }
  const int vertices = static_cast<int>(discs.size()) * (kRim + 1);
  float* out = layer.lockVertices(vertices);
  for (const Disc& disc : discs) {
    auto put = [&](double x, double y) {
      *out++ = float(x);
      *out++ = float(y);
      *out++ = float(disc.centre.z());
      for (int c = 0; c < 3; ++c) *out++ = disc.colour[c];
    };
    put(disc.centre.x(), disc.centre.y());
    for (int k = 0; k < kRim; ++k) {
      const double angle = 2 * std::numbers::pi * k / kRim;
      put(disc.centre.x() + disc.radiusX * std::cos(angle),
          disc.centre.y() + disc.radiusY * std::sin(angle));
    }
  }
  layer.unlockVertices();
  const int indices = static_cast<int>(discs.size()) * 3 * kRim;
  std::uint32_t* index = layer.lockIndices(indices);
  for (std::size_t d = 0; d < discs.size(); ++d) {
    const auto centre = static_cast<std::uint32_t>(d * (kRim + 1));
    for (std::uint32_t k = 0; k < kRim; ++k) {
      *index++ = centre;
      *index++ = centre + 1 + k;
      *index++ = centre + 1 + (k + 1) % kRim;
    }
  }
  layer.unlockIndices();
  layer.setDrawn(indices, Eigen::Vector3f(-1, -1, -1), Eigen::Vector3f(1, 1, 1));
  layer.setBoundingBox(Ogre::AxisAlignedBox::BOX_INFINITE);  // clip space: never culled
}

Eigen::Vector3f rgb(const QColor& colour) {
  return Eigen::Vector3f(float(colour.redF()), float(colour.greenF()), float(colour.blueF()));
}

}  // namespace

MarkerLayer::MarkerLayer(Ogre::SceneNode& node, const std::string& name, const std::string& group)
    : node_(node),
      onTop_(makeLayer(node, name + "/top", "Lacrima/MarkerOnTop", group, kMarkerQueue + 1)),
      depthTested_(
          makeLayer(node, name + "/depth", "Lacrima/MarkerDepthTested", group, kMarkerQueue)) {}

MarkerLayer::~MarkerLayer() {
  node_.detachObject(onTop_.get());
  node_.detachObject(depthTested_.get());
}

void MarkerLayer::setMarkers(std::vector<Marker> markers) { markers_ = std::move(markers); }

void MarkerLayer::update(const Eigen::Matrix4d& viewProjection, const Eigen::Vector3d& eye,
                         double width, double height) {
  std::vector<Disc> top, tested;
  if (width > 0 && height > 0) {
    for (const Marker& marker : markers_) {
      if (!marker.position.allFinite() || !(marker.sizePixels > 0)) continue;
      const Eigen::Vector3d towardsEye = eye - marker.position;
      const Eigen::Vector3d at = marker.onTop
                                     ? marker.position
                                     : Eigen::Vector3d(marker.position + kDepthNudge * towardsEye);
      const Eigen::Vector4d clip = viewProjection * at.homogeneous();
      if (!(clip.w() > 0)) continue;  // behind the camera
      const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
      if (!ndc.allFinite()) continue;
      // Pixels to clip-space units: the picture spans 2 units across its width and height.
      const double radius = 0.5 * std::min(marker.sizePixels, 200.0);
      auto disc = [&](double pixels, const Eigen::Vector3f& colour) {
        return Disc{Eigen::Vector3d(ndc.x(), ndc.y(), marker.onTop ? 0.0 : ndc.z()),
                    2 * pixels / width, 2 * pixels / height, colour};
      };
      std::vector<Disc>& out = marker.onTop ? top : tested;
      if (marker.highlighted) out.push_back(disc(radius + kOutline + kRing, {1, 1, 1}));
      out.push_back(disc(radius + kOutline, {0.06f, 0.06f, 0.07f}));
      out.push_back(
          disc(radius, rgb(marker.highlighted ? marker.colour.lighter(130) : marker.colour)));
    }
  }
  draw(*onTop_, top);
  draw(*depthTested_, tested);
}

}  // namespace lacrima::scene::detail
