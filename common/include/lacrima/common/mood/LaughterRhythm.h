#pragma once
// Laughter's own rhythm for joy (docs/mood.md#laughter): bouts of laugh notes, one every
// kNoteInterval seconds, each rising over kNoteRise, louder first and fading along the bout
// (the decrescendo Provine and Yong measured), with pauses between bouts.
//
// Above joy 0.4 the depth is d = smoothstep((joy - 0.4) / 0.5). A bout has 3 to 3 + 6d notes;
// the pause after it is a draw in [1, 4] s divided by d (judged). Each note opens the jaw, tips
// the head back a little, lifts the cheeks, pulls the lip corners up and back and crinkles the
// lower lids.
// Bouts and notes fall at the same times at any frame rate.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/MoodRandom.h>

#include <cstdint>

namespace lacrima::inline common {

class LaughterRhythm {
 public:
  static constexpr double kNoteInterval = 0.214;  // s, Provine and Yong 1991: 210-218 ms
  static constexpr double kNoteRise = 0.075;      // s, their mean note length

  explicit LaughterRhythm(std::uint64_t seed) : random_(seed) {}

  static double depth(double joy) { return smoothstep((joy - 0.4) / 0.5); }

  void advance(double seconds, double joy);
  void apply(FapValues& face) const;

  int boutsStarted() const { return bouts_; }
  double pulse() const { return pulse_; }

 private:
  MoodRandom random_;
  bool inBout_ = false;
  bool waiting_ = false;  // a pause is running until next_
  double next_ = 0;       // start of the next bout (when waiting)
  double boutStart_ = 0;
  int boutNotes_ = 0;
  double depth_ = 0;
  int bouts_ = 0;
  double pulse_ = 0;
};

}  // namespace lacrima::inline common
