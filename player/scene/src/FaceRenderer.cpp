#include <lacrima/scene/FaceRenderer.h>

#include <lacrima/common/ImageSize.h>
#include <lacrima/common/Milliseconds.h>
#include <lacrima/scene/FaceScene.h>
#include <lacrima/scene/OgreRuntime.h>

#include <OgreHardwarePixelBuffer.h>
#include <OgreMaterialManager.h>
#include <OgreRenderTexture.h>
#include <OgreRoot.h>
#include <OgreTextureManager.h>
#include <OgreViewport.h>

#include <stdexcept>

namespace lacrima::scene {
namespace {

void checkSize(QSize size) {
  if (!isImageSizeInBounds(size))
    throw std::invalid_argument("FaceRenderer: image size must be " +
                                std::to_string(kMinImageSide) + ".." +
                                std::to_string(kMaxImageSide) + " pixels per side");
}

}  // namespace

struct FaceRenderer::State {
  std::shared_ptr<OgreRuntime> runtime;
  std::unique_ptr<FaceScene> scene;
  Ogre::TexturePtr target;
  QSize size;
  int samples = FaceRenderer::kDefaultSamples;
  RenderTimes times;

  ~State() { releaseTarget(); }

  void releaseTarget() {
    if (!target) return;
    const std::string name = target->getName(), group = target->getGroup();
    target.reset();
    Ogre::TextureManager::getSingleton().remove(name, group);
  }

  // Renders the scene's viewport and reads its pixels into an image of `format` (4 bytes a pixel).
  QImage renderInto(QImage::Format format) {
    Ogre::RenderTarget* rt = target->getBuffer()->getRenderTarget();
    auto start = SteadyClock::now();
    rt->update(true);  // with multisampling, the "swap" resolves the samples into the texture
    times.render = millisecondsSince(start);
    start = SteadyClock::now();
    QImage image(size, format);
    const Ogre::PixelBox box(static_cast<Ogre::uint32>(size.width()),
                             static_cast<Ogre::uint32>(size.height()), 1, Ogre::PF_BYTE_RGBA,
                             image.bits());
    rt->copyContentsToMemory(Ogre::Box(0, 0, static_cast<Ogre::uint32>(size.width()),
                                       static_cast<Ogre::uint32>(size.height())),
                             box, Ogre::RenderTarget::FB_AUTO);
    times.readback = millisecondsSince(start);
    return image;
  }

  void createTarget() {
    releaseTarget();
    target = Ogre::TextureManager::getSingleton().createManual(
        runtime->uniqueName("render-target"), runtime->resourceGroup(), Ogre::TEX_TYPE_2D,
        static_cast<Ogre::uint>(size.width()), static_cast<Ogre::uint>(size.height()), 0,
        Ogre::PF_BYTE_RGBA, Ogre::TU_RENDERTARGET, nullptr, false,
        static_cast<Ogre::uint>(samples));
    Ogre::RenderTarget* rt = target->getBuffer()->getRenderTarget();
    rt->setAutoUpdated(false);
    scene->attach(*rt);
  }
};

FaceRenderer::FaceRenderer(const HeadMesh& neutral, QSize size)
    : state_(std::make_unique<State>()) {
  checkSize(size);
  state_->runtime = OgreRuntime::acquire();
  state_->scene = std::make_unique<FaceScene>(state_->runtime, neutral);
  state_->size = size;
  state_->createTarget();
}

FaceRenderer::~FaceRenderer() {
  // The render target before the scene whose camera it shows, the scene before the runtime.
  state_->releaseTarget();
  state_->scene.reset();
}

void FaceRenderer::resize(QSize size) {
  if (size == state_->size) return;
  checkSize(size);
  state_->size = size;
  state_->createTarget();
}

QSize FaceRenderer::size() const { return state_->size; }

void FaceRenderer::setSamples(int samples) {
  samples = samples >= 4 ? 4 : samples >= 2 ? 2 : 0;
  if (samples == state_->samples) return;
  state_->samples = samples;
  state_->createTarget();
}

int FaceRenderer::samples() const { return state_->samples; }

void FaceRenderer::show(const playback::FrameView& view) {
  const auto start = SteadyClock::now();
  state_->scene->show(view);
  state_->times.upload = millisecondsSince(start);
}

QImage FaceRenderer::render() {
  return state_->renderInto(state_->scene->transparentBackground()
                                ? QImage::Format_RGBA8888_Premultiplied
                                : QImage::Format_RGBA8888);
}

QImage FaceRenderer::renderMask() {
  State& s = *state_;
  Ogre::Viewport* viewport = s.target->getBuffer()->getRenderTarget()->getViewport(0);
  const Ogre::ColourValue background = viewport->getBackgroundColour();
  const unsigned int buffers = viewport->getClearBuffers();
  viewport->setMaterialScheme("LacrimaMask");
  viewport->setBackgroundColour(Ogre::ColourValue::Black);
  viewport->setClearEveryFrame(true, Ogre::FBT_COLOUR | Ogre::FBT_DEPTH | Ogre::FBT_STENCIL);
  const QImage ids = s.renderInto(QImage::Format_RGBA8888);
  viewport->setMaterialScheme(Ogre::MaterialManager::DEFAULT_SCHEME_NAME);
  viewport->setBackgroundColour(background);
  viewport->setClearEveryFrame(true, buffers);
  return ids.convertToFormat(QImage::Format_Grayscale8);
}

void FaceRenderer::resetView() { state_->scene->resetView(); }

void FaceRenderer::orbit(double yawDegrees, double pitchDegrees) {
  OrbitView view = state_->scene->view();
  view.orbit(yawDegrees, pitchDegrees);
  state_->scene->setView(view);
}

void FaceRenderer::zoom(double factor) {
  OrbitView view = state_->scene->view();
  view.zoom(factor);
  state_->scene->setView(view);
}

void FaceRenderer::pan(double right, double up) {
  OrbitView view = state_->scene->view();
  view.pan(right, up);
  state_->scene->setView(view);
}

QPointF FaceRenderer::project(const Eigen::Vector3d& headPoint) const {
  return state_->scene->project(headPoint, state_->size);
}

std::optional<Ray> FaceRenderer::rayAt(QPointF pixel) const {
  return state_->scene->rayAt(pixel, state_->size);
}

const RenderTimes& FaceRenderer::lastTimes() const { return state_->times; }

FaceScene& FaceRenderer::scene() { return *state_->scene; }

}  // namespace lacrima::scene
