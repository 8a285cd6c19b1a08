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
#include <lacrima/playback/FrameView.h>
#include <lacrima/scene/OrbitView.h>

#include <Eigen/Core>

#include <QPointF>
#include <QSize>

#include <memory>

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

  // Rebuilds geometry, materials and masks for another head (about 50-100 ms), resets the view.
  void setHead(const HeadMesh& head);
  const HeadMesh* head() const;  // nullptr before the first head

  // Uploads what `view` shows. Positions/normals null: the neutral head. A view of another
  // neutral head switches to it first; without any head it does nothing. Throws
  // std::invalid_argument when positions or normals do not match the head's vertex count.
  void show(const playback::FrameView& view);

  // Adds a viewport showing this scene's camera to `target` (one target per scene).
  Ogre::Viewport& attach(Ogre::RenderTarget& target);
  void setAspect(double widthOverHeight);

  const OrbitView& view() const;
  void setView(const OrbitView& view);
  void resetView();

  // Pixel position of a head-frame point in an image of `size` under the current camera
  // (y down); non-finite when the point is behind the camera.
  QPointF project(const Eigen::Vector3d& headPoint, QSize size) const;

  OgreRuntime& runtime() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::scene
