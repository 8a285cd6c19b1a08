#pragma once
// The OGRE scene of a face with its tears: the head (HeadGeometry: CPU-deformed vertices in a
// dynamic buffer; HeadLook: materials and texture layers), the tears (TearLayers: surface,
// trails, particle impostors), a dark gradient backdrop and a camera steered as an OrbitView.
// Shared by the off-screen FaceRenderer and the on-screen FaceViewport: both attach the
// scene's camera to a render target of their own.
//
// show() uploads at once (positions, normals, tear geometry, overlay weights), so the frame's
// pointers need to stay valid only during the call; drawing happens whenever the owner updates
// its render target.
#include <lacrima/common/RayMesh.h>
#include <lacrima/playback/FrameView.h>
#include <lacrima/scene/Marker.h>
#include <lacrima/scene/OrbitView.h>

#include <Eigen/Core>

#include <QPointF>
#include <QSize>

#include <memory>
#include <optional>
#include <vector>

namespace Ogre {
class RenderTarget;
class Viewport;
}  // namespace Ogre

namespace lacrima::scene {

class OgreRuntime;

class FaceScene {
 public:
  // `head` must outlive the scene (or the next setHead). Without a head the scene shows only
  // its backdrop until setHead() or a frame with a neutral head arrives.
  FaceScene(std::shared_ptr<OgreRuntime> runtime, const HeadMesh& head);
  explicit FaceScene(std::shared_ptr<OgreRuntime> runtime);
  ~FaceScene();
  FaceScene(const FaceScene&) = delete;
  FaceScene& operator=(const FaceScene&) = delete;

  // Rebuilds geometry, materials and masks for another head (about 50-100 ms), resets the view
  // and the view frame (identity: the head is taken to be in the face frame until told).
  void setHead(const HeadMesh& head);
  const HeadMesh* head() const;  // nullptr before the first head

  // Uploads what `view` shows. Positions/normals null: the neutral head. A view of another
  // neutral head switches to it first; without any head it does nothing. Throws
  // std::invalid_argument when positions or normals do not match the head's vertex count.
  void show(const playback::FrameView& view);

  // Adds a viewport showing this scene's camera to `target` (one target per scene).
  Ogre::Viewport& attach(Ogre::RenderTarget& target);
  // Without the backdrop, over a clear of alpha 0, for compositing (--render --alpha): the
  // pixels come out premultiplied by their alpha (the lashes' and the tears' blending keeps the
  // alpha channel an "over" of what is behind them).
  void setTransparentBackground(bool transparent);
  bool transparentBackground() const;
  void setAspect(double widthOverHeight);

  const OrbitView& view() const;
  void setView(const OrbitView& view);
  void resetView();  // OrbitView::framing of the head in the view frame
  // Which way the face looks in head coordinates: the columns of `faceToHead` are the face's own
  // left (+x), up and forward axes (made a rotation first, OrbitView.h). Re-frames the view:
  // the orbit then turns about the face's up and yaw 0 looks at the face.
  void setViewFrame(const Eigen::Matrix3d& faceToHead);
  const Eigen::Matrix3d& viewFrame() const;

  // Markers drawn over the face (Marker.h), replacing the previous ones; cheap enough for every
  // mouse move (a few hundred discs are rebuilt on the CPU).
  void setMarkers(std::vector<Marker> markers);

  // Pixel position of a head-frame point in an image of `size` under the current camera
  // (y down); non-finite when the point is behind the camera.
  QPointF project(const Eigen::Vector3d& headPoint, QSize size) const;
  // The inverse: the ray through pixel `pixel` of an image of `size` (pixel centres at +0.5),
  // from the near plane away from the eye, in the head frame, unit direction. nullopt for an
  // empty size or a non-finite pixel.
  std::optional<Ray> rayAt(QPointF pixel, QSize size) const;

  OgreRuntime& runtime() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::scene
