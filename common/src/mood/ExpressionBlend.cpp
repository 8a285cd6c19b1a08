#include <lacrima/common/FapTable.h>
#include <lacrima/common/mood/ExpressionBlend.h>
#include <lacrima/common/mood/MoodRandom.h>

#include <array>
#include <initializer_list>
#include <string_view>
#include <utility>

namespace lacrima::inline common {
namespace {

using Pose = std::initializer_list<std::pair<std::string_view, float>>;

// The values of media/presets/presets.json (tears left to TearProduction).
const Pose kSadness{{"raise_l_i_eyebrow", 220},    {"raise_r_i_eyebrow", 220},
                    {"raise_l_o_eyebrow", -80},    {"raise_r_o_eyebrow", -80},
                    {"squeeze_l_eyebrow", 60},     {"squeeze_r_eyebrow", 60},
                    {"close_t_l_eyelid", 250},     {"close_t_r_eyelid", 250},
                    {"raise_l_cornerlip", -120},   {"raise_r_cornerlip", -120},
                    {"raise_l_cornerlip_o", -140}, {"raise_r_cornerlip_o", -140},
                    {"raise_b_midlip", 50},        {"push_b_lip", 60},
                    {"depress_chin", 80}};
const Pose kSadCrying{{"raise_l_i_eyebrow", 300},
                      {"raise_r_i_eyebrow", 300},
                      {"raise_l_o_eyebrow", -90},
                      {"raise_r_o_eyebrow", -90},
                      {"squeeze_l_eyebrow", 80},
                      {"squeeze_r_eyebrow", 80},
                      {"close_t_l_eyelid", 350},
                      {"close_t_r_eyelid", 350},
                      {"close_b_l_eyelid", 60},
                      {"close_b_r_eyelid", 60},
                      {"open_jaw", 120},
                      {"stretch_l_cornerlip", 80},
                      {"stretch_r_cornerlip", 80},
                      {"raise_l_cornerlip", -200},
                      {"raise_r_cornerlip", -200},
                      {"raise_l_cornerlip_o", -210},
                      {"raise_r_cornerlip_o", -210},
                      {"raise_b_midlip", 40},
                      {"depress_chin", 140},
                      {"lift_l_cheek", 120},
                      {"lift_r_cheek", 120}};
const Pose kAnger{
    {"raise_l_i_eyebrow", -200}, {"raise_r_i_eyebrow", -200}, {"raise_l_m_eyebrow", -120},
    {"raise_r_m_eyebrow", -120}, {"squeeze_l_eyebrow", 130},  {"squeeze_r_eyebrow", 130},
    {"close_t_l_eyelid", -150},  {"close_t_r_eyelid", -150},  {"close_b_l_eyelid", 80},
    {"close_b_r_eyelid", 80},    {"lower_t_midlip", 60},      {"raise_b_midlip", 80},
    {"raise_l_cornerlip", -40},  {"raise_r_cornerlip", -40},  {"stretch_l_nose", 80},
    {"stretch_r_nose", 80},      {"depress_chin", 60}};
const Pose kAngryCrying{{"raise_l_i_eyebrow", -180},
                        {"raise_r_i_eyebrow", -180},
                        {"raise_l_m_eyebrow", -100},
                        {"raise_r_m_eyebrow", -100},
                        {"squeeze_l_eyebrow", 140},
                        {"squeeze_r_eyebrow", 140},
                        {"close_t_l_eyelid", 250},
                        {"close_t_r_eyelid", 250},
                        {"close_b_l_eyelid", 150},
                        {"close_b_r_eyelid", 150},
                        {"open_jaw", 200},
                        {"lower_t_midlip", -150},
                        {"stretch_l_cornerlip", 150},
                        {"stretch_r_cornerlip", 150},
                        {"raise_l_cornerlip", -60},
                        {"raise_r_cornerlip", -60},
                        {"stretch_l_nose", 100},
                        {"stretch_r_nose", 100},
                        {"depress_chin", 80},
                        {"lift_l_cheek", 100},
                        {"lift_r_cheek", 100}};
const Pose kJoy{{"open_jaw", 110},
                {"lower_t_midlip", -40},
                {"raise_b_midlip", -50},
                {"stretch_l_cornerlip", 150},
                {"stretch_r_cornerlip", 150},
                {"raise_l_cornerlip", 200},
                {"raise_r_cornerlip", 200},
                {"stretch_l_cornerlip_o", 160},
                {"stretch_r_cornerlip_o", 160},
                {"raise_l_cornerlip_o", 220},
                {"raise_r_cornerlip_o", 220},
                {"lift_l_cheek", 160},
                {"lift_r_cheek", 160},
                {"close_b_l_eyelid", 120},
                {"close_b_r_eyelid", 120},
                {"raise_l_m_eyebrow", 30},
                {"raise_r_m_eyebrow", 30}};
// The Tears of joy preset with the smile kept: the preset lowers the lip corners below Joy's, so
// as the crying form took over the smile flattened and joy with tears read as neutral. Here the
// corners stay at least as high as Joy's (judged on rendered frames, docs/mood.md) and the
// preset's heavy upper lids are lighter (the raised cheeks already narrow the eyes).
const Pose kTearsOfJoy{{"open_jaw", 160},
                       {"lower_t_midlip", -60},
                       {"raise_b_midlip", -70},
                       {"stretch_l_cornerlip", 160},
                       {"stretch_r_cornerlip", 160},
                       {"raise_l_cornerlip", 220},
                       {"raise_r_cornerlip", 220},
                       {"stretch_l_cornerlip_o", 170},
                       {"stretch_r_cornerlip_o", 170},
                       {"raise_l_cornerlip_o", 240},
                       {"raise_r_cornerlip_o", 240},
                       {"lift_l_cheek", 260},
                       {"lift_r_cheek", 260},
                       {"close_t_l_eyelid", 120},
                       {"close_t_r_eyelid", 120},
                       {"close_b_l_eyelid", 220},
                       {"close_b_r_eyelid", 220},
                       {"raise_l_i_eyebrow", 40},
                       {"raise_r_i_eyebrow", 40}};
// Judged (no preset): the head bowed and turned aside, heavier lids (GazeModel lowers the eyes),
// inner brows a little up, lips pressed, chin raised.
const Pose kShame{{"head_pitch", 12000},      {"head_yaw", 6000},        {"close_t_l_eyelid", 280},
                  {"close_t_r_eyelid", 280},  {"raise_l_i_eyebrow", 70}, {"raise_r_i_eyebrow", 70},
                  {"raise_b_midlip", 60},     {"lower_t_midlip", 40},    {"raise_l_cornerlip", -50},
                  {"raise_r_cornerlip", -50}, {"depress_chin", 70}};

FapValues toValues(const Pose& pose) {
  FapValues values{};
  for (const auto& [name, value] : pose) values[channelIndex(*fapByName(name))] = value;
  return values;
}

struct PoseTable {
  std::array<FapValues, kMoodCount> expression, crying;
};

const PoseTable& poses() {
  static const PoseTable table = [] {
    PoseTable t;
    t.expression = {toValues(kSadness), toValues(kAnger), toValues(kJoy), toValues(kShame)};
    t.crying = {toValues(kSadCrying), toValues(kAngryCrying), toValues(kTearsOfJoy),
                toValues(kShame)};
    return t;
  }();
  return table;
}

constexpr double kVariation = 0.08;     // of each moved channel's value
constexpr double kVariationTime = 1.3;  // seconds per wiggle
constexpr double kSway = 600;           // AU of idle head motion
constexpr double kSwayTime = 3.5;

}  // namespace

FapValues ExpressionBlend::pose(Mood mood, double crying) {
  const int m = static_cast<int>(mood);
  FapValues values{};
  for (int i = 0; i < kChannelCount; ++i)
    values[i] =
        static_cast<float>((1 - crying) * poses().expression[m][i] + crying * poses().crying[m][i]);
  return values;
}

void ExpressionBlend::apply(const MoodLevels& levels, double crying, double seconds,
                            FapValues& face) const {
  double total = 0;
  for (double level : levels.level) total += level;
  const double scale = total > 1 ? 1 / total : 1;
  std::array<double, kChannelCount> blend{};
  for (Mood mood : kMoods) {
    const double w = levels[mood] * scale;
    if (w == 0) continue;
    const int m = static_cast<int>(mood);
    for (int i = 0; i < kChannelCount; ++i)
      blend[i] += w * ((1 - crying) * poses().expression[m][i] + crying * poses().crying[m][i]);
  }
  for (int i = 0; i < kChannelCount; ++i) {
    if (blend[i] == 0) continue;
    const double wander = smoothNoise(streamSeed(seed_, 100 + i), seconds / kVariationTime);
    face[i] += static_cast<float>(blend[i] * (1 + kVariation * wander));
  }
  for (int fap : {48, 49, 50}) {
    const double sway = smoothNoise(streamSeed(seed_, 200 + fap), seconds / kSwayTime);
    face[channelIndex(fap)] += static_cast<float>(kSway * sway);
  }
}

}  // namespace lacrima::inline common
