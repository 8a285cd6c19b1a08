// Presets applied as layers: each adds its pose times its intensity curve onto the keys.
#include "../support/KeyBuilders.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/ProjectDocument.h>

#include <QtTest>

#include <cmath>

using namespace lacrima;
using lacrima::test::keyAt;

namespace {

constexpr int kOpenJaw = 3;
constexpr int kRaiseBLip = 5;
constexpr int kTearsLeft = 69;

PoseLayer rampLayer(const char* name, std::initializer_list<std::pair<int, float>> pose,
                    double from, double to) {
  PoseLayer layer;
  layer.name = name;
  for (const auto& [fap, value] : pose) layer.setPoseValue(fap, value);
  layer.setIntensityKeys({{from, 0.0, Interpolation::Linear}, {to, 1.0, Interpolation::Linear}});
  return layer;
}

}  // namespace

class PoseLayerTest : public QObject {
  Q_OBJECT

 private slots:
  void layersAddTheirPoseTimesTheirIntensity() {
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, 10.0f}}), keyAt(2.0, {{kOpenJaw, 30.0f}})});
    const std::vector<PoseLayer> layers{rampLayer("a", {{kOpenJaw, 100.0f}}, 1.0, 2.0),
                                        rampLayer("b", {{kRaiseBLip, -40.0f}}, 0.0, 4.0)};
    const FapValues at = mixLayers(keys.evaluate(1.5), layers, 1.5);
    QCOMPARE(at[channelIndex(kOpenJaw)], 25.0f + 0.5f * 100.0f);
    QCOMPARE(at[channelIndex(kRaiseBLip)], 0.375f * -40.0f);
    // Before its first intensity key a layer holds that key's intensity (here 0).
    QCOMPARE(mixLayers(keys.evaluate(0.5), layers, 0.5)[channelIndex(kOpenJaw)], 15.0f);
  }

  void mutedLayersAndLayersWithoutIntensityAddNothing() {
    PoseLayer muted = rampLayer("m", {{kOpenJaw, 100.0f}}, 0.0, 1.0);
    muted.muted = true;
    PoseLayer empty;
    empty.setPoseValue(kOpenJaw, 50.0f);
    const FapValues keyed{};
    QCOMPARE(mixLayers(keyed, std::vector{muted, empty}, 1.0)[channelIndex(kOpenJaw)], 0.0f);
  }

  void tearsStayWholeAndWithinTheirRange() {
    std::vector<PoseLayer> layers{rampLayer("t", {{kTearsLeft, 33.0f}}, 0.0, 1.0)};
    FapValues keyed{};
    keyed[channelIndex(kTearsLeft)] = 2.0f;
    QCOMPARE(mixLayers(keyed, layers, 0.5)[channelIndex(kTearsLeft)], 19.0f);  // 2 + 16.5
    layers[0].setPoseValue(kTearsLeft, -500.0f);
    QCOMPARE(mixLayers(keyed, layers, 1.0)[channelIndex(kTearsLeft)], 0.0f);
    layers[0].setPoseValue(kTearsLeft, 1e9f);
    QCOMPARE(mixLayers(keyed, layers, 1.0)[channelIndex(kTearsLeft)],
             static_cast<float>(kMaxTearParticles));
  }

  void codesCannotBeLayered() {
    PoseLayer layer;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, layer.setPoseValue(1, 3.0f));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, layer.setPoseValue(2, 3.0f));
  }

  // The bake spans keys and layers alike; every frame is the keys' value plus the layers'.
  void documentBakeMixesLayersOverTheWholeRange() {
    ProjectDocument document;
    document.fps = 10.0;
    document.keys =
        KeyframeSequence({keyAt(1.0, {{kOpenJaw, 10.0f}}), keyAt(2.0, {{kOpenJaw, 20.0f}})});
    document.layers = {rampLayer("sob", {{kOpenJaw, 50.0f}, {kTearsLeft, 10.0f}}, 2.0, 3.0)};
    const FapAnimation baked = document.bake();
    QCOMPARE(baked.frameCount(), 21);  // 1 s .. 3 s at 10 fps
    QVERIFY(baked.animated.test(channelIndex(kTearsLeft)));
    for (int f = 0; f < baked.frameCount(); ++f) {
      const double t = 1.0 + f / 10.0;
      const double w = std::clamp(t - 2.0, 0.0, 1.0);
      const double keyed = t < 2.0 ? 10.0 + 10.0 * (t - 1.0) : 20.0;
      QVERIFY(std::abs(baked.frames[f][channelIndex(kOpenJaw)] - (keyed + 50.0 * w)) < 1e-4);
      QCOMPARE(baked.frames[f][channelIndex(kTearsLeft)], static_cast<float>(std::round(10.0 * w)));
    }
    // Muting the layer gives back the keys' own animation, frame for frame.
    document.layers[0].muted = true;
    QVERIFY(document.bake().frames == document.keys.bake(10.0).frames);
  }

  void aLayerAloneAnimatesANeutralFace() {
    ProjectDocument document;
    document.fps = 4.0;
    document.layers = {rampLayer("smile", {{kRaiseBLip, 8.0f}}, 0.0, 1.0)};
    const FapAnimation baked = document.bake();
    QCOMPARE(baked.frameCount(), 5);
    QCOMPARE(baked.frames.back()[channelIndex(kRaiseBLip)], 8.0f);
    QCOMPARE(baked.frames[2][channelIndex(kRaiseBLip)], 4.0f);
  }

  void layersRoundTripThroughTheProjectFile() {
    ProjectDocument document;
    document.keys = KeyframeSequence({keyAt(0.0, {{kOpenJaw, 1.0f}})});
    PoseLayer sob = rampLayer("sob \"loud\"", {{kOpenJaw, 0.1f}, {kTearsLeft, 40.0f}}, 0.5, 1.25);
    sob.setIntensityKeys({{0.5, 0.0, Interpolation::Smooth},
                          {1.25, 0.7, Interpolation::Bezier},
                          {3.0, -0.25, Interpolation::Constant}});
    PoseLayer quiet = rampLayer("quiet", {{kRaiseBLip, -3.5f}}, 0.0, 0.1);
    quiet.muted = true;
    document.layers = {sob, quiet};
    const std::string json = document.toJson();
    const ProjectDocument back = ProjectDocument::fromJson(json, "layers.json");
    QVERIFY(back == document);
    QCOMPARE(back.toJson(), json);
  }

  void badLayersAreRefusedNamingTheirPlace_data() {
    QTest::addColumn<QString>("layers");
    QTest::addColumn<int>("version");
    QTest::addColumn<QString>("message");
    QTest::newRow("layers in version 1")
        << R"([])" << 1 << "layers: layers need a project of version 2";
    QTest::newRow("a code in the pose")
        << R"([{"pose": {"viseme": 3}, "intensity": []}])" << 2
        << "layers[0].pose.viseme: viseme and expression codes cannot be layered";
    QTest::newRow("intensity beyond 100")
        << R"([{"pose": {}, "intensity": [{"time": 0, "value": 1e6}]}])" << 2
        << "layers[0].intensity[0].value: expected a number in [-100, 100]";
    QTest::newRow("negative time")
        << R"([{"pose": {}, "intensity": [{"time": -1, "value": 1}]}])" << 2
        << "layers[0].intensity[0].time: expected a time in seconds from 0 to 86400";
    QTest::newRow("no intensity") << R"([{"pose": {"open_jaw": 1}}])" << 2
                                  << "layers[0]: missing field \"intensity\"";
  }

  void badLayersAreRefusedNamingTheirPlace() {
    QFETCH(QString, layers);
    QFETCH(int, version);
    QFETCH(QString, message);
    const std::string json = R"({"format": "lacrima-project", "version": )" +
                             std::to_string(version) + R"(, "keys": [], "layers": )" +
                             layers.toStdString() + "}";
    try {
      ProjectDocument::fromJson(json, "doc.json");
      QFAIL("accepted");
    } catch (const FileError& error) {
      QVERIFY2(QString::fromStdString(error.message()).startsWith(message),
               qPrintable(QString::fromStdString(error.message())));
      QCOMPARE(error.where().line, 1);
    }
  }
};

QTEST_GUILESS_MAIN(PoseLayerTest)
#include "PoseLayerTest.moc"
