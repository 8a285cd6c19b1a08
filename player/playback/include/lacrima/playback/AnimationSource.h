#pragma once
// Where the frames a player shows come from: a file (Playback: seekable, every time shows the
// same picture bit for bit) or a live stream (LiveSource: not seekable, the newest frame wins and
// the tears simulate at the display's pace). The player's transport, effects and status bar talk
// to this interface only; opening a file or listening is what knows which one it has.
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/FrameView.h>

namespace lacrima::playback {

class AnimationSource {
 public:
  virtual ~AnimationSource() = default;

  // A file goes to any time; a stream only forwards, with the display's clock.
  virtual bool seekable() const = 0;

  // Shows time `seconds` of the display clock. A file: the tears at the last whole frame <= t,
  // the face interpolated at t (clamped to the animation). A stream: the newest frame, the
  // tears advanced by the time since the last call.
  virtual const FrameView& seek(double seconds) = 0;
  virtual const FrameView& view() const = 0;
  virtual double currentTime() const = 0;
  // A file: the last whole frame the tears have reached. A stream: frames shown so far.
  virtual int currentFrame() const = 0;
  // A file: its frames, rate and length. A stream: frames received, the rate it names (or 0)
  // and 0 s (it has no end).
  virtual int frameCount() const = 0;
  virtual double frameRate() const = 0;
  virtual double duration() const = 0;
  // True when a tear channel is driven: by the file, or (for a stream) ever so far.
  virtual bool hasTears() const = 0;

  // Effects, tear parameters and quality; a change of the simulation restarts the tears.
  virtual void setScene(const SceneSettings& scene) = 0;
  virtual const SceneSettings& scene() const = 0;
  virtual void setSimulationThreads(int threads) = 0;
  // Neutral face, every tear gone, time 0.
  virtual void reset() = 0;
  virtual const FrameProducer& producer() const = 0;
};

}  // namespace lacrima::playback
