#include <lacrima/common/FapTable.h>
#include <lacrima/common/mood/LaughterRhythm.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {

void LaughterRhythm::advance(double seconds, double joy) {
  const double d = depth(joy);
  if (inBout_ && seconds >= boutStart_ + boutNotes_ * kNoteInterval) {
    inBout_ = false;
    waiting_ = true;
    next_ = boutStart_ + boutNotes_ * kNoteInterval + random_.uniform(1, 4) / std::max(d, 0.25);
  }
  if (!inBout_) {
    pulse_ = 0;
    if (d <= 0) {
      waiting_ = false;  // joy gone: the next laugh starts when it returns
      return;
    }
    if (waiting_ && seconds < next_) return;
    boutStart_ = waiting_ ? next_ : seconds;
    if (seconds >= boutStart_ + kNoteInterval * 3) boutStart_ = seconds;  // a long frame
    waiting_ = false;
    boutNotes_ = 3 + static_cast<int>(random_.uniform() * (1 + 6 * d));
    depth_ = d * random_.uniform(0.8, 1.1);
    inBout_ = true;
    ++bouts_;
  }
  const double sinceStart = seconds - boutStart_;
  const int note = std::min(boutNotes_ - 1, static_cast<int>(sinceStart / kNoteInterval));
  const double inNote = sinceStart - note * kNoteInterval;
  // rise over the note, fall over the silence after it
  const double shape = inNote < kNoteRise
                           ? smoothstep(inNote / kNoteRise)
                           : 1 - smoothstep((inNote - kNoteRise) / (kNoteInterval - kNoteRise));
  const double loudness = 1 - 0.5 * note / std::max(1, boutNotes_ - 1);
  pulse_ = depth_ * loudness * shape;
}

void LaughterRhythm::apply(FapValues& face) const {
  if (pulse_ == 0) return;
  const auto add = [&](int fap, double perPulse) {
    face[channelIndex(fap)] += static_cast<float>(perPulse * pulse_);
  };
  add(3, 170);                                    // open_jaw
  add(48, -1500);                                 // head_pitch: back with each note
  for (int fap : {41, 42}) add(fap, 120);         // lift cheeks
  for (int fap : {12, 13, 59, 60}) add(fap, 90);  // lip corners up
  for (int fap : {6, 7, 53, 54}) add(fap, 50);    // and back
  for (int fap : {21, 22}) add(fap, 60);          // lower lids crinkle
}

}  // namespace lacrima::inline common
