#pragma once
// A project's procedural crying layer (docs/mood.md#the-mood-layer): the crying generator with a
// seed over a time range of the project, following the project's mood curves. It is evaluated,
// never stored as keys, so a mood key edited in the Moods view changes the face at once.
//
// Its take is generateMoodTake at the project's frame rate, frame i at start + i / fps with the
// moods of the curves at that project time: exactly the take the editor's Generate crying...
// writes as keys over the same range. Between frames the take is read linearly (the reduced
// keys of a bake are linear too); from its last frame to `end` the last frame holds; outside
// [start, end] the layer adds nothing. Its output mixes by mixLayers' rule (PoseLayer.h): each
// channel it moves is added to the keys and pose layers, and the tear channels are then rounded
// to whole particles in [0, kMaxTearParticles]. Its face colours replace the keyed (or the
// player's computed) redness and blush within its range. A muted layer adds nothing.
//
// Every reader uses these functions (ProjectDocument::evaluate, bake and coloursAt): the editor's
// preview, the player, lacrima-fap and the exports give the same values.
#include <lacrima/common/FaceColours.h>
#include <lacrima/common/mood/MoodCurves.h>
#include <lacrima/common/mood/MoodGenerator.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace lacrima::inline common {

struct MoodLayer {
  // A JSON number holds every whole number up to 2^53 exactly; the layer's seed stays below.
  static constexpr std::uint64_t kMaxSeed = (std::uint64_t{1} << 53) - 1;

  std::uint64_t seed = 1;
  double start = 0, end = 10;  // project seconds, 0 <= start < end <= kMaxMoodSeconds
  bool muted = false;
  bool operator==(const MoodLayer&) const = default;
};

// The generated frames of a layer: what evaluation reads.
class MoodLayerTake {
 public:
  // Throws std::invalid_argument as generateMoodTake (a range that does not run forward, too
  // many frames) before allocating the frames.
  MoodLayerTake(const MoodCurves& curves, const MoodLayer& layer, double fps);

  // Whether this take is the one these inputs give (the layer's mute does not matter).
  bool generatedFrom(const MoodCurves& curves, const MoodLayer& layer, double fps) const;

  bool covers(double seconds) const { return seconds >= start_ && seconds <= end_; }
  // The generated channels and colours at project time `seconds` within the range.
  FapValues channelsAt(double seconds) const;
  FaceColours coloursAt(double seconds) const;
  const ChannelMask& channels() const { return take_.animation.animated; }
  double start() const { return start_; }
  double end() const { return end_; }
  int frameCount() const { return take_.animation.frameCount(); }
  const MoodTake& take() const { return take_; }
  std::size_t bytes() const;  // the frames and colours held

 private:
  struct Position {
    std::size_t frame;
    double fraction;
  };
  Position position(double seconds) const;

  MoodCurves curves_;
  std::uint64_t seed_;
  double start_, end_, fps_;
  MoodTake take_;
};

// `below` (the keys and pose layers at `seconds`) with the take's channels added, as mixLayers
// adds a layer; nothing without a take or outside its range.
FapValues mixMoodLayer(const FapValues& below, const MoodLayerTake* take, double seconds);
// One frame's worth of that rule: `generated`'s `channels` added to `below`, tears rounded.
FapValues addMoodFrame(const FapValues& below, const FapValues& generated,
                       const ChannelMask& channels);
// The keyed colours with the take's redness and blush in place of them within its range.
KeyedColours mixMoodColours(const KeyedColours& keyed, const MoodLayerTake* take, double seconds);

// Colours change slowly: a key per frame would make a ten-minute project's colours 26,000 keys
// of JSON for nothing. A key every kColourKeyStep seconds (and on the last frame), linear
// between, keeps them within a hundredth of the generated values.
inline constexpr double kColourKeyStep = 0.25;
// One colour of `take` as such keys, frame i at start + i / fps.
std::vector<IntensityKey> moodColourKeys(const MoodTake& take, double FaceColours::*colour,
                                         double start = 0);
// `keyed` with the take's colours keyed over its range in place of the keys there (a bake).
FaceColourCurves bakeMoodColours(const FaceColourCurves& keyed, const MoodLayerTake& take);

// Keeps the last take and generates again only when the curves, seed, range or rate change.
class MoodLayerCache {
 public:
  // The take of `layer`; nullptr without one or while it is muted. Throws as MoodLayerTake.
  const MoodLayerTake* take(const MoodCurves& curves, const std::optional<MoodLayer>& layer,
                            double fps);
  // The take last returned, to keep beyond the cache (the player holds it while playing).
  std::shared_ptr<const MoodLayerTake> shared() const { return shown_; }
  int generations() const { return generations_; }  // how often a take was generated

 private:
  std::shared_ptr<const MoodLayerTake> take_;   // kept while muted, so unmuting is instant
  std::shared_ptr<const MoodLayerTake> shown_;  // take_ or nothing
  int generations_ = 0;
};

}  // namespace lacrima::inline common
