#pragma once
// The markers of a face scene (Marker.h) as flat discs built on the CPU in clip space (identity
// view and projection, like the backdrop): each marker is projected once per camera change and
// drawn as a dark outline disc under a disc of its colour, highlighted ones with a white ring
// outside, all of its diameter in pixels whatever the distance. onTop markers go in a geometry
// drawn without a depth test; the others sit at their point's depth (nudged towards the eye) and
// are hidden where the face is nearer. Both are drawn last, the depth-tested ones first
// (kMarkerQueue) so on-top markers stay above them (kMarkerQueue + 1), each in the order given.
// Hundreds of markers are a few thousand vertices: rebuilding them every mouse move is free.
#include "StreamedGeometry.h"

#include <lacrima/scene/Marker.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace Ogre {
class SceneNode;
}

namespace lacrima::scene::detail {

inline constexpr unsigned char kMarkerQueue = 90;

class MarkerLayer {
 public:
  MarkerLayer(Ogre::SceneNode& node, const std::string& name, const std::string& group);
  ~MarkerLayer();
  MarkerLayer(const MarkerLayer&) = delete;
  MarkerLayer& operator=(const MarkerLayer&) = delete;

  void setMarkers(std::vector<Marker> markers);
  bool empty() const { return markers_.empty(); }
  // Rebuilds the discs for the camera `viewProjection` (head frame to clip space, OpenGL
  // convention), its eye, and a render target of the given size in pixels.
  void update(const Eigen::Matrix4d& viewProjection, const Eigen::Vector3d& eye, double width,
              double height);

 private:
  Ogre::SceneNode& node_;
  std::vector<Marker> markers_;
  std::unique_ptr<StreamedGeometry> onTop_, depthTested_;
};

}  // namespace lacrima::scene::detail
