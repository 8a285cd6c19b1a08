// LiveSource: a stream on the default head. The newest frame wins (the others are counted as
// dropped), the face follows it, the tears run at the display's pace between frames and after
// the stream stops, and streams without tear channels weep what the player sets. Moods drive
// the face through the crying generator, easing in, with no tears simulated before its onset.
#include "PlaybackTestSupport.h"

#include <lacrima/common/mood/MoodGenerator.h>

#include <lacrima/playback/LiveSource.h>

using namespace lacrima;
using namespace lacrima::playback;
using namespace lacrima::playback::test;

namespace {

ChannelMask maskOf(std::initializer_list<const char*> names) {
  ChannelMask mask;
  for (const char* name : names) mask.set(static_cast<std::size_t>(channelIndex(*fapByName(name))));
  return mask;
}

double largestMove(const FrameView& view, const HeadMesh& neutral) {
  return double(((*view.positions) - neutral.positions).colwise().norm().maxCoeff());
}

}  // namespace

class LiveSourceTest : public QObject {
  Q_OBJECT
  std::unique_ptr<HeadRig> rig_;

 private slots:
  void initTestCase() { LOAD_DEFAULT_HEAD_RIG(rig_); }

  void newestFrameWinsAndTheHeadTurns() {
    LiveSource live(*rig_);
    QVERIFY(!live.seekable());
    QCOMPARE(live.duration(), 0.0);
    FapValues a{}, b{};
    channel(a, "open_jaw") = 200;
    channel(b, "head_yaw") = 20000;
    live.push(a, maskOf({"open_jaw"}), 1.0);
    live.push(b, maskOf({"head_yaw"}), 1.01);  // before any display: a is dropped
    const FrameView& view = live.seek(0.0);
    QCOMPARE(live.framesReceived(), 2LL);
    QCOMPARE(live.framesDropped(), 1LL);
    QCOMPARE(live.shownArrival(), 1.01);
    QCOMPARE(live.shownValues()[channelIndex(49)], 20000.0F);
    QCOMPARE(live.shownValues()[channelIndex(3)], 0.0F);
    QVERIFY(largestMove(view, rig_->head) > 1e-3);  // the head turned
    const auto revision = view.revision;
    live.seek(0.001);  // nothing new, no tears: the same picture
    QCOMPARE(live.view().revision, revision);
    QCOMPARE(live.shownArrival(), -1.0);
  }

  // A stream without tear channels weeps what the player sets; the tears go on between frames
  // and after the stream stops, stepped by the display clock (capped per call).
  void tearsRunAtTheDisplaysPace() {
    LiveSource live(*rig_);
    live.setTears(40, 30);
    FapValues v{};
    channel(v, "open_jaw") = 100;
    live.push(v, maskOf({"open_jaw"}), 0);
    double t = 0;
    live.seek(t);
    for (int i = 0; i < 30; ++i) live.seek(t += 1.0 / 60);
    QCOMPARE(live.shownValues()[channelIndex(kTearLeftFap)], 40.0F);
    const int particles = live.producer().particleCount();
    QVERIFY2(particles > 0, "no tears from the player's own counts");
    QVERIFY(live.hasTears());
    const long long steps = live.producer().counters().simulationSteps;
    live.seek(t += 5.0);  // a stalled display: one capped step, not five seconds at once
    QCOMPARE(live.producer().counters().simulationSteps, steps + 1);

    // A frame that carries tear channels wins over the player's counts.
    FapValues dry{};
    live.push(dry, maskOf({"open_jaw", "tears_l_eye", "tears_r_eye"}), 1);
    live.seek(t += 1.0 / 60);
    QCOMPARE(live.shownValues()[channelIndex(kTearLeftFap)], 0.0F);

    live.reset();
    QCOMPARE(live.producer().particleCount(), 0);
  }

  // The crying generator on the display's clock: a change of moods eases in (no jump), no tear
  // is simulated while it makes no tear channel, its tears come after the onset, its colours
  // replace the computed ones, and a frame takes the face back until the next moods.
  void moodsDriveTheFaceLive() {
    LiveSource live(*rig_);
    QVERIFY(!live.moodDriven());
    live.setMoods(MoodLevels{});
    QVERIFY(live.moodDriven());
    const auto brow = static_cast<std::size_t>(channelIndex(31));  // raise_l_i_eyebrow
    const auto tear = static_cast<std::size_t>(channelIndex(kTearLeftFap));
    double t = 0;
    const double step = 1.0 / 30;
    for (; t < 1.0; t += step) live.seek(t);
    const float neutral = live.shownValues()[brow];
    live.setMoods(MoodLevels{{0.8, 0, 0, 0}});
    QCOMPARE(live.moods()[Mood::Sadness], 0.8);
    live.seek(t += step);
    const float first = live.shownValues()[brow];
    double later = 0;
    int n = 0;
    for (; t < 2.5; t += step, ++n) {
      live.seek(t);
      later += live.shownValues()[brow];
      QCOMPARE(live.shownValues()[tear], 0.0F);  // before the onset: no tear channel
    }
    later /= n;
    QVERIFY2(later > neutral + 40, qPrintable(QString("brow %1 -> %2").arg(neutral).arg(later)));
    QVERIFY2(std::abs(first - neutral) < 0.2 * (later - neutral),
             qPrintable(QString("jumped %1 of %2").arg(first - neutral).arg(later - neutral)));
    QCOMPARE(live.producer().counters().simulationSteps, 0LL);  // nothing asked for tears
    QVERIFY(!live.hasTears());
    for (; t < 6 && live.shownValues()[tear] < 1; t += step) live.seek(t);
    QVERIFY2(live.shownValues()[tear] >= 1, "the generator's tears never came");
    for (int i = 0; i < 5; ++i) live.seek(t += step);
    QVERIFY(live.producer().particleCount() > 0);
    QVERIFY(live.hasTears());
    QVERIFY(live.view().overlays.redness > 0);  // the generator's redness, after the tears

    // A frame takes the face back; the next moods take it again.
    FapValues jaw{};
    channel(jaw, "open_jaw") = 300;
    live.push(jaw, maskOf({"open_jaw"}), t);
    live.seek(t += step);
    QVERIFY(!live.moodDriven());
    QCOMPARE(live.shownValues()[channelIndex(3)], 300.0F);
    live.setMoods(MoodLevels{{0.8, 0, 0, 0}});
    live.seek(t += step);
    QVERIFY(live.moodDriven());
    QVERIFY(live.shownValues()[channelIndex(3)] != 300.0F);
  }

  // The same seed gives the same take at the same display times; another seed another one.
  void moodSeedChoosesTheTake() {
    const auto take = [this](std::uint64_t seed) -> std::vector<FapValues> {
      LiveSource live(*rig_);
      live.setMoodSeed(seed);
      live.setMoods(MoodLevels{{0, 0.5, 0, 0.6}});
      std::vector<FapValues> frames;
      for (double t = 0; t < 2; t += 1.0 / 30) {
        live.seek(t);
        frames.push_back(live.shownValues());
      }
      if (live.moodSeed() != seed) return {};
      return frames;
    };
    QVERIFY(!take(7).empty());
    QVERIFY(take(7) == take(7));
    QVERIFY(take(7) != take(8));
  }
};

QTEST_GUILESS_MAIN(LiveSourceTest)
#include "LiveSourceTest.moc"
