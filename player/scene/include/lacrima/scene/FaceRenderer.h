#pragma once
// Off-screen rendering of a face and its tears into images: batch renders (lacrima-player
// --render), tests and benchmarks. Uses the same scene as the on-screen viewport.
//
// Needs an X display (OGRE on Debian is GLX only); the constructor throws std::runtime_error
// saying so (run under xvfb-run) when there is none.
#include <lacrima/common/RayMesh.h>
#include <lacrima/playback/FrameView.h>

#include <Eigen/Core>

#include <QImage>
#include <QPointF>
#include <QSize>

#include <memory>
#include <optional>

namespace lacrima::scene {

class FaceScene;

// upload: the last show(); render: submitting the frame (the software rasteriser may still be
// drawing when it returns); readback: waiting for the pixels and copying them into the image.
// render + readback is what a frame costs.
struct RenderTimes {
  double upload = 0, render = 0, readback = 0;  // milliseconds
};

class FaceRenderer {
 public:
  // `neutral` must outlive the renderer. Sizes outside isImageSizeInBounds (ImageSize.h) throw
  // std::invalid_argument, here and in resize().
  FaceRenderer(const HeadMesh& neutral, QSize size);
  ~FaceRenderer();
  FaceRenderer(const FaceRenderer&) = delete;
  FaceRenderer& operator=(const FaceRenderer&) = delete;

  void resize(QSize size);
  QSize size() const;
  void show(const playback::FrameView& view);
  // Format_RGBA8888, upright; Format_RGBA8888_Premultiplied over a transparent background
  // (FaceScene::setTransparentBackground).
  QImage render();
  // The ID pass of the frame shown, from the same camera and geometry as render(): Grayscale8,
  // 255 where tear water (surface, drops) is the nearest thing seen, 128 where a wet trail is,
  // 0 elsewhere (skin, eyes, the background). Each part's label is written whatever its colour
  // (the scheme "LacrimaMask" of media/materials/lacrima.material), so it is exact per pixel,
  // not a threshold. Lashes and brows are left out of it.
  QImage renderMask();
  // Camera: the same framing as the viewport's reset view, then orbit/zoom in its terms.
  void resetView();
  void orbit(double yawDegrees, double pitchDegrees);
  void zoom(double factor);           // < 1 moves closer
  void pan(double right, double up);  // moves the target by fractions of the view's height
  // Pixel position of a point in the head frame under the current camera (tests: where the
  // eyes and cheeks are in the image); y grows downwards.
  QPointF project(const Eigen::Vector3d& headPoint) const;
  // The inverse: the ray through an image pixel, in the head frame (FaceScene::rayAt).
  std::optional<Ray> rayAt(QPointF pixel) const;
  const RenderTimes& lastTimes() const;

  // Multisampling of the render target: 0 (none), 2 or 4 (other values round down to these).
  static constexpr int kDefaultSamples = 0;
  void setSamples(int samples);
  int samples() const;
  // The scene behind the images (camera, per-frame details) for tools and tests.
  FaceScene& scene();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::scene
