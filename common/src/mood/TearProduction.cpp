#include <lacrima/common/mood/TearProduction.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {
namespace {

double angerDrive(double anger) { return 0.7 * smoothstep((anger - 0.5) / 0.5); }
double joyDrive(double joy) { return 0.5 * smoothstep((joy - 0.6) / 0.4); }

}  // namespace

TearProduction::TearProduction(std::uint64_t seed) {
  MoodRandom random(seed);
  const int lesser = random.uniform() < 0.5 ? 0 : 1;
  share_[lesser] = random.uniform(0.85, 1.0);
}

double TearProduction::drive(const MoodLevels& levels) {
  return std::min(
      1.0, levels[Mood::Sadness] + angerDrive(levels[Mood::Anger]) + joyDrive(levels[Mood::Joy]));
}

void TearProduction::advance(double dt, const MoodLevels& levels) {
  const double sad = levels[Mood::Sadness];
  const double angry = angerDrive(levels[Mood::Anger]);
  const double joyful = joyDrive(levels[Mood::Joy]);
  const double d = std::min(1.0, sad + angry + joyful);
  if (sad + angry + joyful > 0)
    onset_ = (sad * kSadOnset + angry * kAngryOnset + joyful * kJoyOnset) / (sad + angry + joyful);
  // The clock stops a few seconds past full spilling, so tears start to dry soon after the mood
  // falls however long the crying lasted.
  const double full = onset_ + kSpillAfter + 4;
  clock_ = d > kThreshold ? std::min(full, clock_ + dt) : std::max(0.0, clock_ - 2 * dt);
  welling_ = smoothstep((clock_ - onset_) / 2);
  spilling_ = smoothstep((clock_ - onset_ - kSpillAfter) / 3);
  const double target = kWelling * welling_ + kSpilling * spilling_ * d;
  for (int eye = 0; eye < 2; ++eye) {
    const double wanted = target * share_[eye];
    double& count = count_[eye];
    if (wanted > count)
      count = std::min(wanted, count + kGrowth * (1 + 3 * d) * dt);
    else
      count = approach(count, wanted, dt, kTaper);
    rounded_[eye] = static_cast<int>(std::round(count));
  }
}

double TearProduction::tearful() const { return std::min(1.0, 0.005 * (count_[0] + count_[1])); }

}  // namespace lacrima::inline common
