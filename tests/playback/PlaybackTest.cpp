// The playback layer on the real default head, offscreen (no OGRE): deterministic seeking,
// effects on demand, bad files, the texture-blend weights and the effect toggles.
// Skipped when the default head has not been fetched.
#include "PlaybackTestSupport.h"

#include <lacrima/common/FapWriter.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailBuilder.h>

#include <Eigen/Geometry>
#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <fstream>
#include <limits>
#include <map>

using namespace lacrima;
using namespace lacrima::playback;
using namespace lacrima::playback::test;

namespace {

void writeText(const QString& path, const std::string& text) {
  std::ofstream out(path.toStdString(), std::ios::binary);
  out << text;
}

double seconds(int frame) { return frame / kFps; }

}  // namespace

class PlaybackTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadRig> rig_;
  QTemporaryDir dir_;

  // The particles of a plain play (no checkpoint but frame 0's) at `frames`, in increasing order.
  std::map<int, tears::ParticleSet> straightPlay(const FapAnimation& animation,
                                                 const SceneSettings& scene,
                                                 std::initializer_list<int> frames) {
    Playback straight(*rig_, 1000);
    straight.setAnimation(animation, scene);
    std::map<int, tears::ParticleSet> particles;
    for (int f : frames) {
      straight.seek(seconds(f));
      particles[f] = *straight.view().particles;
    }
    return particles;
  }

 private slots:
  void initTestCase() {
    LOAD_DEFAULT_HEAD_RIG(rig_);
    QVERIFY(dir_.isValid());
  }

  // Going back restores the nearest earlier checkpoint and replays: the particles are bit for
  // bit those of a straight play, and only the frames after that checkpoint are replayed.
  void seekBackIsBitwiseIdentical() {
    const FapAnimation animation = cryingAnimation(70, 40);
    SceneSettings scene;
    scene.particles = true;
    auto reference = straightPlay(animation, scene, {25, 47, 60});
    QCOMPARE(reference[60].size(), 80);

    Playback scrubbed(*rig_, 10);
    scrubbed.setAnimation(animation, scene);
    scrubbed.seek(seconds(60));  // forward in one jump: steps every frame
    QCOMPARE(scrubbed.currentFrame(), 60);
    QCOMPARE(scrubbed.framesSimulated(), 61LL);
    QCOMPARE(scrubbed.checkpointCount(), 7);  // before frames 0, 10, ..., 60
    QVERIFY(sameParticles(*scrubbed.view().particles, reference[60]));

    long long before = scrubbed.framesSimulated();
    scrubbed.seek(seconds(25) + 0.01);  // between frames 25 and 26
    QCOMPARE(scrubbed.currentFrame(), 25);
    QCOMPARE(scrubbed.framesSimulated() - before,
             6LL);  // restored before frame 20, replayed 20..25
    QVERIFY2(sameParticles(*scrubbed.view().particles, reference[25]),
             "restoring a checkpoint changed the tears");
    before = scrubbed.framesSimulated();
    scrubbed.seek(seconds(60));  // on from the restored state
    QCOMPARE(scrubbed.framesSimulated() - before, 35LL);
    QVERIFY2(sameParticles(*scrubbed.view().particles, reference[60]),
             "playing on after a restore changed the tears");
    scrubbed.seek(seconds(47));
    QVERIFY(sameParticles(*scrubbed.view().particles, reference[47]));
    scrubbed.seek(seconds(12));
    scrubbed.seek(seconds(47));
    QVERIFY(sameParticles(*scrubbed.view().particles, reference[47]));
    scrubbed.reset();  // the same simulation object, back to no tears
    scrubbed.seek(seconds(60));
    QVERIFY2(sameParticles(*scrubbed.view().particles, reference[60]),
             "a reset left something of the old tears");
  }

  // Checkpoints never hold more than their budget: over it, every other one goes and the
  // interval doubles. Seeking back still gives a straight play's particles, bit for bit.
  void checkpointsStayWithinTheirBudget() {
    const FapAnimation animation = cryingAnimation(70, 40);
    SceneSettings scene;
    scene.particles = true;
    auto reference = straightPlay(animation, scene, {13, 50, 60});

    Playback unbounded(*rig_, 2, std::numeric_limits<std::size_t>::max());
    unbounded.setAnimation(animation, scene);
    unbounded.seek(seconds(60));
    QCOMPARE(unbounded.checkpointCount(), 31);  // before frames 0, 2, ..., 60
    QCOMPARE(unbounded.checkpointInterval(), 2);
    const std::size_t each = unbounded.checkpointBytes() / 31;
    QVERIFY(each > 0);

    const std::size_t budget = 7 * each;
    Playback bounded(*rig_, 2, budget);
    bounded.setAnimation(animation, scene);
    for (int f = 0; f <= 60; ++f) {
      bounded.seek(seconds(f));
      QVERIFY2(bounded.checkpointBytes() <= budget, "the checkpoints outgrew their budget");
    }
    QVERIFY(bounded.checkpointCount() >= 3);
    QVERIFY(bounded.checkpointInterval() > 2);
    QCOMPARE(bounded.checkpointInterval() % 2, 0);
    QCOMPARE(bounded.framesSimulated(), 61LL);
    for (int f : {13, 50, 60}) {
      bounded.seek(seconds(f));
      QVERIFY2(sameParticles(*bounded.view().particles, reference[f]),
               "a thinned checkpoint list changed the tears");
    }
    // A scene change that restarts the tears starts the checkpoints over at the first interval
    // (at frame 0, so that the replay to where we were takes none but frame 0's).
    bounded.seek(0);
    SceneSettings other = scene;
    other.quality.level = TearQuality::Preview;
    bounded.setScene(other);
    QCOMPARE(bounded.checkpointInterval(), 2);
    QCOMPARE(bounded.checkpointCount(), 1);
  }

  // The eyes are part of the tears' collision surface: tears welling up at the upper lid, over
  // the cornea, stay on the eye's surface, never inside the eyeball (the skin alone has a hole
  // there, and without the eyes the first particles already appear inside).
  void tearsStayOutOfTheEyes() {
    struct Ball {
      Eigen::Vector3d centre, front;
      double radius;
    };
    std::array<Ball, 2> balls;
    for (int e = 0; e < 2; ++e) {
      const HeadSubmesh* eye = rig_->head.findSubmesh(e == 0 ? "eye_l" : "eye_r");
      QVERIFY(eye);
      Eigen::AlignedBox3d box;
      for (int v = eye->firstVertex; v < eye->firstVertex + eye->vertexCount; ++v)
        box.extend(rig_->head.positions.col(v).cast<double>());
      const double radius = 0.5 * std::max(box.sizes().x(), box.sizes().y());
      balls[static_cast<std::size_t>(e)] = {
          Eigen::Vector3d(box.center().x(), box.center().y(), box.max().z() - radius),
          Eigen::Vector3d(box.center().x(), box.center().y(), box.max().z()), radius};
    }
    QVERIFY(!eyeTriangles(*rig_).empty());
    TearSources sources;
    sources.left = balls[0].front + Eigen::Vector3d(0, 0.5 * balls[0].radius, 0);
    sources.right = balls[1].front + Eigen::Vector3d(0, 0.5 * balls[1].radius, 0);
    SceneSettings scene;
    scene.particles = true;
    Playback playback(*rig_);
    playback.setAnimation(cryingAnimation(44, 40), scene, sources);
    int checked = 0;
    for (int f = 0; f < 44; ++f) {
      const FrameView& v = playback.seek(seconds(f) + 0.01);
      if (!v.particles) continue;
      for (const Eigen::Vector3d& x : v.particles->position) {
        for (const Ball& b : balls)
          QVERIFY2((x - b.centre).norm() > 0.9 * b.radius,
                   qPrintable(QString("frame %1: a tear particle inside an eyeball").arg(f)));
        ++checked;
      }
    }
    QVERIFY(checked > 40 * 40);
  }

  // A file without tear channels: no simulation, no surface, no trails, ever.
  void noTearsNoSimulation() {
    Playback playback(*rig_);
    SceneSettings scene;
    scene.particles = scene.surface = scene.trails = true;
    playback.setAnimation(dryAnimation(60), scene);
    QVERIFY(!playback.hasTears());
    for (int f = 0; f < 60; ++f) {
      const FrameView& v = playback.seek(seconds(f) + 0.02);
      QVERIFY(!v.particles && !v.surface && !v.trails);
    }
    playback.seek(0);  // back and forth again
    playback.seek(playback.duration());
    const ProducerCounters& c = playback.producer().counters();
    QVERIFY(c.frames >= 60);
    QVERIFY(c.blends >= 60);
    QCOMPARE(c.simulationSteps, 0LL);
    QCOMPARE(c.surfaceRuns, 0LL);
    QCOMPARE(c.trailRuns, 0LL);
    QCOMPARE(playback.producer().particleCount(), 0);
    QCOMPARE(playback.view().overlays.wetEyes[0], 0.0);
  }

  // The simulation runs while tears are commanded or present, and stops once they are gone.
  void simulationStopsWhenTearsAreGone() {
    Playback playback(*rig_);
    playback.setAnimation(cryingAnimation(60, 30, 0, 20));
    playback.seek(playback.duration());
    const ProducerCounters& c = playback.producer().counters();
    // Frames 0-19 command tears, frame 20 removes them all (the oldest first), then nothing.
    QCOMPARE(c.simulationSteps, 21LL);
    QCOMPARE(c.surfaceRuns, 20LL);  // frame 20 ends with no particles: nothing to mesh
    QVERIFY(c.trailRuns >= 20);     // trails go on drying after the tears
    QCOMPARE(playback.producer().particleCount(), 0);
    QVERIFY(!playback.view().surface && !playback.view().particles);
  }

  // A malformed file is an error naming the file and line, and the loaded animation stays.
  void badFileKeepsPreviousAnimation() {
    const QString good = dir_.filePath("good.fap");
    FapWriter::save(cryingAnimation(30, 10), good.toStdString());
    Playback playback(*rig_);
    playback.open(good.toStdString());
    QCOMPARE(playback.frameCount(), 30);
    playback.seek(seconds(12));

    const QString bad = dir_.filePath("bad.fap");
    std::string mask;
    for (int fap = 1; fap <= 68; ++fap)
      mask += std::string(fap > 1 ? " " : "") + (fap == 3 ? "1" : "0");
    // Line 3, the first value line, has a word where open_jaw's value should be.
    const std::string text = "2.1 bad 22 2\n" + mask + "\n0 wide\n";
    writeText(bad, text);
    try {
      playback.open(bad.toStdString());
      QFAIL("a malformed FAP file was accepted");
    } catch (const FileError& e) {
      QCOMPARE(QString::fromStdString(e.where().file), bad);
      QCOMPARE(e.where().line, 3);
      QVERIFY(QString(e.what()).startsWith(bad + ":3"));
    }
    QCOMPARE(QString::fromStdString(playback.path()), good);
    QCOMPARE(playback.frameCount(), 30);
    QCOMPARE(playback.currentFrame(), 12);
    playback.seek(seconds(20));
    QCOMPARE(playback.currentFrame(), 20);

    const QString badProject = dir_.filePath("bad.json");
    writeText(badProject,
              "{\n  \"format\": \"lacrima-project\",\n  \"version\": 1,\n  \"fps\": 22,\n  "
              "\"keys\": [ }\n");
    try {
      playback.open(badProject.toStdString());
      QFAIL("a malformed project was accepted");
    } catch (const FileError& e) {
      QCOMPARE(QString::fromStdString(e.where().file), badProject);
      QCOMPARE(e.where().line, 5);
    }
    QCOMPARE(QString::fromStdString(playback.path()), good);

    // 140 bytes asking for 16 million frames (4.5 GB) are refused before the bake, at the key
    // that sets the length.
    const QString longProject = dir_.filePath("long.json");
    writeText(
        longProject,
        R"({"format": "lacrima-project", "version": 1, "fps": 1000, "keys": [)"
        "\n"
        R"({"time": 0, "values": {"open_jaw": 1}}, {"time": 16000, "values": {"open_jaw": 2}}]})");
    try {
      playback.open(longProject.toStdString());
      QFAIL("a project of 16 million frames was accepted");
    } catch (const FileError& e) {
      QCOMPARE(QString::fromStdString(e.where().file), longProject);
      QCOMPARE(e.where().line, 2);
      QVERIFY2(QString(e.what()).contains("keys[1].time") &&
                   QString(e.what()).contains("at most 1048576 frames"),
               e.what());
    }
    QCOMPARE(QString::fromStdString(playback.path()), good);

    try {
      playback.open(dir_.filePath("missing.fap").toStdString());
      QFAIL("a missing file was accepted");
    } catch (const FileError& e) {
      QVERIFY(QString(e.what()).contains("missing.fap"));
    }
    QCOMPARE(playback.frameCount(), 30);
  }

  // A project brings its scene settings and tear sources.
  void projectBringsItsScene() {
    const QString path = dir_.filePath("scene.json");
    writeText(path, R"({
  "format": "lacrima-project", "version": 1, "name": "t", "fps": 22, "interpolation": "linear",
  "keys": [ { "time": 0, "values": { "open_jaw": 0, "tears_l_eye": 20 } },
            { "time": 1, "values": { "open_jaw": 200, "tears_l_eye": 20 } } ],
  "tearSources": { "left": [0.3, 7.0, 1.0], "right": null },
  "scene": { "particles": true, "surface": false, "trails": false, "textureBlending": true,
             "redness": "tears", "blush": true, "simulation": { "adhesion": 40 } }
})");
    Playback playback(*rig_);
    playback.open(path.toStdString());
    QCOMPARE(playback.frameCount(), 23);
    QVERIFY(playback.scene().particles && !playback.scene().surface);
    QCOMPARE(playback.scene().redness, SceneSettings::Redness::Tears);
    QCOMPARE(playback.scene().simulation.at("adhesion"), 40.0);
    QVERIFY(playback.tearSources().left.has_value());
    QVERIFY(!playback.tearSources().right.has_value());
    const FrameView& v = playback.seek(playback.duration());
    QVERIFY(v.particles && !v.surface && !v.trails);
    QCOMPARE(playback.producer().counters().surfaceRuns, 0LL);
  }

  // Redness follows the animation (2009) or the tears shed; the eyes are wet while tears are
  // there; the blush follows the redness when asked for; texture blending off zeroes them all.
  void overlayWeights() {
    Playback playback(*rig_);
    playback.setAnimation(cryingAnimation(89, 30, 10, 50));  // 4 s
    double last = -1;
    for (int f = 0; f < 89; ++f) {
      const OverlayWeights& w = playback.seek(seconds(f)).overlays;
      QVERIFY(w.redness >= last);
      last = w.redness;
      if (f == 0) QCOMPARE(w.redness, 0.0);
      if (f < 10) QVERIFY(w.wetEyes[0] == 0 && w.wetEyes[1] == 0);
      if (f == 30) QVERIFY(w.wetEyes[0] > 0.25 && w.wetEyes[1] > 0.25);
      if (f == 80) QVERIFY(w.wetEyes[0] == 0 && w.wetEyes[1] == 0);
      QCOMPARE(w.blush, 0.0);
    }
    QCOMPARE(last, 1.0);
    QCOMPARE(playback.seek(playback.duration() / 2).overlays.redness, 0.5);

    SceneSettings scene;
    scene.redness = SceneSettings::Redness::Tears;
    scene.blush = true;
    playback.setAnimation(cryingAnimation(89, 30, 10, 50), scene);
    last = 0;
    for (int f = 0; f < 89; ++f) {
      const OverlayWeights& w = playback.seek(seconds(f)).overlays;
      if (f < 10) QCOMPARE(w.redness, 0.0);  // no tears yet
      QVERIFY(w.redness >= last);
      QCOMPARE(w.blush, w.redness);
      last = w.redness;
    }
    QVERIFY2(last > 0.05, QByteArray::number(last));

    scene.textureBlending = false;
    playback.setScene(scene);
    const FrameView& v = playback.seek(seconds(30));
    QVERIFY(!v.textureBlending);
    QCOMPARE(v.overlays, OverlayWeights{});
  }

  // A project's keyed colours (a generated take's, docs/decisions/0019) replace the computed
  // redness and blush, read at project time; without them nothing changes.
  void keyedColoursReplaceTheComputedOnes() {
    const QString path = dir_.filePath("colours.lacrima");
    writeText(path, R"({
  "format": "lacrima-project", "version": 2, "name": "t", "fps": 22, "interpolation": "linear",
  "keys": [ { "time": 1, "values": { "open_jaw": 0 } }, { "time": 3, "values": { "open_jaw": 50 } } ],
  "scene": { "redness": "animation", "blush": true },
  "colours": { "redness": [ { "time": 1, "value": 0.2, "interpolation": "linear" },
                            { "time": 3, "value": 0.6, "interpolation": "linear" } ],
               "blush": [ { "time": 0, "value": 0.7, "interpolation": "linear" } ] }
})");
    Playback playback(*rig_);
    playback.open(path.toStdString());
    QCOMPARE(playback.frameCount(), 45);  // frame 0 is the first key, at 1 s
    // Curves hold floats, as every channel does.
    QVERIFY(std::abs(playback.view().overlays.redness - 0.2) < 1e-6);
    const OverlayWeights middle = playback.seek(1.0).overlays;  // project time 2 s
    QVERIFY(std::abs(middle.redness - 0.4) < 1e-6);
    QVERIFY(std::abs(middle.blush - 0.7) < 1e-6);
    QVERIFY(std::abs(playback.seek(2.0).overlays.redness - 0.6) < 1e-6);
    // Played frame by frame the same.
    playback.reset();
    QVERIFY(std::abs(playback.seek(1.0).overlays.redness - 0.4) < 1e-6);
    // Without the blush effect no blush, keyed or not.
    SceneSettings scene = playback.scene();
    scene.blush = false;
    playback.setScene(scene);
    QCOMPARE(playback.seek(1.0).overlays.blush, 0.0);
    // An animation set from memory has no colours: the 2009 ramp again.
    playback.setAnimation(cryingAnimation(89, 30, 10, 50));
    QCOMPARE(playback.seek(playback.duration() / 2).overlays.redness, 0.5);
  }

  // A project's crying layer plays as the editor evaluates it: its channels in the frames, its
  // colours in place of the keyed ones within its range (docs/mood.md#the-mood-layer).
  void aMoodLayerPlaysAsTheEditorEvaluatesIt() {
    const QString path = dir_.filePath("layer.lacrima");
    writeText(path, R"({
  "format": "lacrima-project", "version": 2, "name": "t", "fps": 22,
  "keys": [ { "time": 0, "values": { "open_jaw": 10 } } ],
  "scene": { "redness": "animation", "blush": true },
  "colours": { "redness": [ { "time": 0, "value": 0.3, "interpolation": "linear" } ] },
  "moods": { "sadness": [ { "time": 0, "value": 0.9 } ], "shame": [ { "time": 0, "value": 0.8 } ] },
  "moodLayer": { "seed": 3, "start": 1, "end": 12 }
})");
    const ProjectDocument document = ProjectDocument::load(path.toStdString());
    MoodLayerCache cache;
    Playback playback(*rig_);
    playback.open(path.toStdString());
    QCOMPARE(playback.frameCount(), 12 * 22 + 1);
    for (int f : {0, 30, 200, 264})
      QVERIFY(playback.animation().frames[static_cast<std::size_t>(f)] ==
              document.evaluate(f / 22.0, cache));
    const KeyedColours expected = document.coloursAt(10, cache);
    const OverlayWeights shown = playback.seek(10).overlays;
    QVERIFY2(std::abs(shown.blush - *expected.blush) < 1e-6 && *expected.blush > 0.5,
             qPrintable(QString("%1 %2").arg(shown.blush).arg(*expected.blush)));
    QVERIFY(std::abs(shown.redness - *expected.redness) < 1e-6);
    QVERIFY(std::abs(playback.seek(0.5).overlays.redness - 0.3) < 1e-6);  // before the layer
  }

  // Toggles switch the work and the pointers; the revision moves only when something changed.
  void togglesRespected() {
    Playback playback(*rig_);
    SceneSettings scene;
    scene.particles = false;
    scene.surface = true;
    scene.trails = true;
    playback.setAnimation(cryingAnimation(80, 40), scene);
    const FrameView* v = &playback.seek(seconds(40));
    QVERIFY(!v->particles && v->surface && v->trails);
    QVERIFY(v->surface->triangleCount() > 0 && v->trails->triangleCount() > 0);

    const long long revision = v->revision;
    playback.seek(seconds(40));
    QCOMPARE(playback.view().revision, revision);  // nothing changed: a static scene
    playback.seek(seconds(40) + 0.02);
    QVERIFY(playback.view().revision > revision);  // the face moved between frames

    scene.surface = false;
    scene.particles = true;
    playback.setScene(scene);
    const long long surfaceRuns = playback.producer().counters().surfaceRuns;
    v = &playback.seek(seconds(50));
    QVERIFY(v->particles && !v->surface && v->trails);
    QVERIFY(v->particleRadius > 0);
    QCOMPARE(playback.producer().counters().surfaceRuns, surfaceRuns);

    scene.trails = false;
    playback.setScene(scene);
    const long long trailRuns = playback.producer().counters().trailRuns;
    v = &playback.seek(seconds(60));
    QVERIFY(!v->trails);
    QCOMPARE(playback.producer().counters().trailRuns, trailRuns);

    scene.surface = true;  // on again while paused: meshed at once
    playback.setScene(scene);
    QVERIFY(playback.view().surface && playback.view().surface->triangleCount() > 0);
    scene.trails = true;  // trails start again from the drops' current places
    playback.setScene(scene);
    v = &playback.seek(seconds(75));
    QVERIFY(v->trails && v->trails->triangleCount() > 0);
  }

  // Reset: neutral face, no tears, time 0; playing again starts from the first frame.
  void resetGivesNeutralFace() {
    Playback playback(*rig_);
    playback.setAnimation(cryingAnimation(40, 30));
    playback.seek(seconds(35));
    QVERIFY(playback.producer().particleCount() > 0);
    playback.reset();
    QCOMPARE(playback.currentFrame(), 0);
    QCOMPARE(playback.currentTime(), 0.0);
    QCOMPARE(playback.producer().particleCount(), 0);
    const FrameView& v = playback.view();
    QVERIFY(*v.positions == rig_->head.positions);
    QVERIFY(!v.particles && !v.surface && !v.trails);
    QCOMPARE(v.overlays, OverlayWeights{});
    playback.seek(seconds(3));
    QCOMPARE(playback.currentFrame(), 3);
    QVERIFY(playback.producer().particleCount() > 0);
  }

  // New tear parameters restart the tears: the picture is a straight play's with them.
  void parameterChangeReplays() {
    const FapAnimation animation = cryingAnimation(50, 30);
    SceneSettings scene;
    scene.particles = true;
    Playback changed(*rig_, 10);
    changed.setAnimation(animation, scene);
    changed.seek(seconds(40));
    scene.simulation["adhesion"] = 60;
    scene.simulation["viscosity"] = 2;
    changed.setScene(scene);
    QCOMPARE(changed.currentFrame(), 40);

    Playback fresh(*rig_, 10);
    fresh.setAnimation(animation, scene);
    fresh.seek(seconds(40));
    QVERIFY(sameParticles(*changed.view().particles, *fresh.view().particles));

    scene.simulation["adhesion"] = -5;  // out of range: refused, nothing changes
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, changed.setScene(scene));
    QCOMPARE(changed.scene().simulation.at("adhesion"), 60.0);
  }

  // --threads reaches the simulation as SimulationOptions::threads, through a new animation and
  // a quality change (which rebuild the options); the same tears with one thread or three.
  void simulationThreadsReachTheOptions() {
    const FapAnimation animation = cryingAnimation(20, 30);
    SceneSettings scene;
    scene.particles = true;
    Playback three(*rig_, 10);
    QCOMPARE(three.producer().simulationOptions().threads, 0);  // the simulation's own choice
    three.setSimulationThreads(3);
    three.setAnimation(animation, scene);
    QCOMPARE(three.producer().simulationOptions().threads, 3);
    scene.quality.level = TearQuality::Reference;
    three.setScene(scene);
    QCOMPARE(three.producer().simulationOptions().threads, 3);
    three.seek(seconds(15));

    Playback one(*rig_, 10);
    one.setSimulationThreads(1);
    one.setAnimation(animation, scene);
    one.seek(seconds(15));
    QVERIFY(sameParticles(*three.view().particles, *one.view().particles));
  }

  // Bringing your own head: a missing mesh is an error naming it.
  void missingHeadFileIsNamed() {
    try {
      loadHeadRig(dir_.filePath("nohead.obj").toStdString(),
                  dir_.filePath("nohead.fdp.json").toStdString());
      QFAIL("a missing head file was accepted");
    } catch (const FileError& e) {
      QVERIFY(QString(e.what()).contains("nohead.obj"));
    }
  }
};

QTEST_GUILESS_MAIN(PlaybackTest)
#include "PlaybackTest.moc"
