#pragma once
// A point marked on the face (a feature point being placed, a proposal, the point under the
// mouse): a disc of constant size on screen at a head-frame position, drawn over the face.
// onTop markers show through the surface (a point behind the nose stays visible while the view
// turns); the others hide where the face is in front of them. A highlighted marker is brighter
// and ringed in white. Shared by FaceScene (which draws them) and FaceViewport (which takes them).
#include <Eigen/Core>

#include <QColor>

namespace lacrima::scene {

struct Marker {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  QColor colour = QColor(255, 200, 40);
  double sizePixels = 9;  // the disc's diameter
  bool highlighted = false;
  bool onTop = true;
};

}  // namespace lacrima::scene
