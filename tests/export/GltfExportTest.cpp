// lacrima-player --export-gltf proven with real clients: the Khronos glTF Validator reports no
// error, and Blender's own importer (blender -b) finds the shape keys by FAP name, an action of
// the file's length, the shape-key values, eye turns and deformed head Lacrima's playback shows
// at two frames, and the tear objects at exactly the frames where the player shows tears. Also:
// a file without tear channels exports no tears, bad ranges and paths fail clearly, a cancelled
// export leaves no file.
#include "../support/MissingData.h"
#include "../support/RunProcess.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/common/HeadTurns.h>
#include <lacrima/export/GltfAnimationExport.h>
#include <lacrima/exporters/RigExport.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");
constexpr int kFrames = 40;  // 1.8 s at 22 fps
constexpr int kTearsFrom = 3, kTearsTo = 24;
// The frames compared in Blender: the eyes and head well turned, and tears on the face.
constexpr int kCheckedFrames[] = {12, 31};

testsupport::ProcessRun run(const QString& program, const QStringList& arguments) {
  return testsupport::runProcess(program, arguments, 600000);
}

void setValue(FapValues& v, int fap, float value) {
  v[static_cast<std::size_t>(channelIndex(fap))] = value;
}

// The jaw opens, the brow rises and a lip corner falls, the eyes look left and down, the head
// turns; with tears, both eyes weep from frame 3 to 24.
FapAnimation shortShot(bool tears) {
  FapAnimation a;
  a.name = "short";
  a.fps = 22;
  for (int f = 0; f < kFrames; ++f) {
    FapValues v{};
    setValue(v, *fapByName("open_jaw"), 12.0f * static_cast<float>(f));
    setValue(v, *fapByName("raise_l_i_eyebrow"), 8.0f * static_cast<float>(f));
    setValue(v, *fapByName("raise_l_cornerlip"), -6.0f * static_cast<float>(f));  // negative
    setValue(v, 23, 900.0f * static_cast<float>(f));                              // left eye yaw
    setValue(v, 26, 500.0f * static_cast<float>(f));                              // right eye pitch
    setValue(v, 49, -250.0f * static_cast<float>(f));                             // head yaw
    if (tears && f >= kTearsFrom && f <= kTearsTo)
      setValue(v, kTearLeftFap, 25), setValue(v, kTearRightFap, 25);
    a.frames.push_back(v);
  }
  return a;
}

QJsonArray quaternion(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }

// The JSON chunk of a .glb.
QJsonObject glbJson(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  const QByteArray bytes = file.readAll();
  if (bytes.size() < 20) return {};
  quint32 length = 0;
  std::memcpy(&length, bytes.constData() + 12, 4);
  return QJsonDocument::fromJson(bytes.mid(20, static_cast<qsizetype>(length))).object();
}

}  // namespace

class GltfExportTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString withTears_, withoutTears_, glb_;
  std::unique_ptr<playback::HeadRig> rig_;

  // What Lacrima's playback shows: the frames with tear geometry, and at the checked frames the
  // morph weights, the eyes' turns and the deformed head, in the file's metres.
  QJsonObject expectations() {
    playback::Playback playback(*rig_);
    playback.open(withTears_.toStdString());
    const double metres =
        rig_->rig.fapu.es0 > 0 ? exporting::kMeanEyeSeparationMetres / rig_->rig.fapu.es0 : 1.0;
    QJsonArray tearFrames, samples;
    for (int f = 0; f < kFrames; ++f) {
      const playback::FrameView& view = playback.seek(f / playback.frameRate());
      if (view.surface || view.drops || view.trails) tearFrames.append(f);
      if (std::find(std::begin(kCheckedFrames), std::end(kCheckedFrames), f) ==
          std::end(kCheckedFrames))
        continue;
      const FapValues& values = playback.animation().frames[static_cast<std::size_t>(f)];
      // Weights are never negative: a FAP's negative values drive its "_negative" target.
      QJsonObject weights;
      for (const char* name : {"open_jaw", "raise_l_i_eyebrow", "raise_l_cornerlip"}) {
        const float value = values[static_cast<std::size_t>(channelIndex(*fapByName(name)))];
        weights[name] = std::max(0.0f, value) / exporters::kExportedPoseValue;
      }
      weights["raise_l_cornerlip_negative"] =
          -values[static_cast<std::size_t>(channelIndex(*fapByName("raise_l_cornerlip")))] /
          exporters::kExportedPoseValue;
      const Eigen::Quaterniond head = headTurn(values);
      QJsonArray positions;
      for (Eigen::Index v = 0; v < view.positions->cols(); ++v) {
        const Eigen::Vector3d p = view.positions->col(v).cast<double>() * metres;
        positions.append(QJsonArray{p.x(), p.y(), p.z()});
      }
      samples.append(QJsonObject{
          {"frame", f},
          {"values", weights},
          {"eyes", QJsonObject{{"eye_left", quaternion(head * eyeTurn(values, EyeSide::Left))},
                               {"eye_right", quaternion(head * eyeTurn(values, EyeSide::Right))}}},
          {"positions", positions}});
    }
    return {{"fps", 22},
            {"lastFrame", kFrames - 1},
            {"weights", samples},
            {"tearFrames", tearFrames},
            // Weights are stored as float: value / 1024 to 7 digits.
            {"weightTolerance", 1e-5},
            // The turn's quaternion through float and the importer's bone conversion.
            {"angleTolerance", 1e-4},
            // Morph deltas and skinning in float, in metres: 0.05 mm. The eyes turn about
            // their rest centres, which is exact while no eye thrust (27/28) moves them.
            {"positionTolerance", 5e-5}};
  }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    QVERIFY(dir_.isValid());
    withTears_ = dir_.filePath("short.fap");
    withoutTears_ = dir_.filePath("dry.fap");
    FapWriter::save(shortShot(true), withTears_.toStdString());
    FapWriter::save(shortShot(false), withoutTears_.toStdString());
    rig_ = playback::loadDefaultHeadRig();
    glb_ = dir_.filePath("short.glb");
    const testsupport::ProcessRun r = run(kPlayer, {"--export-gltf", glb_, withTears_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.err.contains("40 frames"), qPrintable(r.err));
    QVERIFY(QFile::exists(glb_));
  }

  void structureCarriesTheAnimation() {
    const QJsonObject gltf = glbJson(glb_);
    const QJsonArray animations = gltf["animations"].toArray();
    QCOMPARE(animations.size(), 1);
    QStringList paths;
    for (const QJsonValue& c : animations[0]["channels"].toArray())
      paths << c["target"]["path"].toString();
    QVERIFY(paths.contains("weights"));
    QCOMPARE(paths.count("rotation"), 3);  // head and both eyes
    const QJsonArray names = gltf["meshes"][0]["extras"]["targetNames"].toArray();
    QVERIFY(names.contains("open_jaw"));
    // Negative in the clip: its negative values have a target of their own.
    QVERIFY(names.contains("raise_l_cornerlip_negative"));
    QVERIFY(!names.contains("open_jaw_negative"));
    QVERIFY(gltf["extensionsUsed"].toArray().contains("KHR_materials_transmission"));
  }

  void validatorReportsNoErrors() {
    const QString validator = QStringLiteral(LACRIMA_GLTF_VALIDATOR_DIR);
    const QString remedy =
        "bash packaging/fetch-gltf-validator.sh " + validator + "; apt-get install nodejs";
    if (!QFile::exists(validator + "/node_modules/gltf-validator/package.json") ||
        QStringLiteral(LACRIMA_NODE).isEmpty())
      LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("the glTF validator or node is not installed"),
                                remedy);
    for (const QString& file : {glb_, exportDry()}) {
      const testsupport::ProcessRun r = run(
          QStringLiteral(LACRIMA_NODE),
          {QStringLiteral(LACRIMA_SOURCE_DIR "/tests/export/validate-glb.js"), validator, file});
      QVERIFY2(r.exitCode == 0, qPrintable(r.err));
      const QJsonObject issues = QJsonDocument::fromJson(r.out.toUtf8()).object();
      QVERIFY2(issues.contains("numErrors"), qPrintable(r.out));
      QVERIFY2(issues["numErrors"].toInt() == 0, qPrintable(r.out.left(4000)));
      QVERIFY2(issues["numWarnings"].toInt() == 0, qPrintable(r.out.left(4000)));
    }
  }

  void blenderPlaysItAsLacrimaDoes() {
    if (QStringLiteral(LACRIMA_BLENDER).isEmpty())
      LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("Blender is not installed"),
                                QStringLiteral("apt-get install blender"));
    const QString expected = dir_.filePath("expected.json"), result = dir_.filePath("result.json");
    QFile file(expected);
    QVERIFY(file.open(QIODevice::WriteOnly));
    const QJsonObject expect = expectations();
    QVERIFY(!expect["tearFrames"].toArray().isEmpty());
    file.write(QJsonDocument(expect).toJson(QJsonDocument::Compact));
    file.close();
    const testsupport::ProcessRun r =
        run(QStringLiteral(LACRIMA_BLENDER),
            {"-b", "--factory-startup", "--python-exit-code", "1", "--python",
             QStringLiteral(LACRIMA_SOURCE_DIR "/tests/export/blender-check-glb.py"), "--", glb_,
             expected, result});
    QFile measured(result);
    if (measured.open(QIODevice::ReadOnly)) qInfo("%s", measured.readAll().left(3000).constData());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err.right(4000) + r.out.right(4000)));
    QVERIFY(QFile::exists(result));
  }

  // No tear channel: no simulation, no tear nodes, no water materials.
  void dryFileExportsNoTears() {
    const QJsonObject gltf = glbJson(exportDry());
    for (const QJsonValue& node : gltf["nodes"].toArray())
      QVERIFY2(!node["name"].toString().startsWith("tears_"), qPrintable(node["name"].toString()));
    QVERIFY(!gltf["extensionsUsed"].toArray().contains("KHR_materials_transmission"));
  }

  void frameRangeExportsPartOfTheFile() {
    const QString out = dir_.filePath("part.glb");
    const testsupport::ProcessRun r =
        run(kPlayer, {"--export-gltf", out, "--frames", "5-9", withoutTears_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QJsonObject gltf = glbJson(out);
    const int input = gltf["animations"][0]["samplers"][0]["input"].toInt();
    QCOMPARE(gltf["accessors"][input]["count"].toInt(), 5);
  }

  void badInputFailsClearly() {
    testsupport::ProcessRun r =
        run(kPlayer, {"--export-gltf", dir_.filePath("x.glb"), "--frames", "10-99", withoutTears_});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("frames 10 to 99") && r.err.contains("0 to 39"), qPrintable(r.err));
    r = run(kPlayer, {"--export-gltf", dir_.filePath("x.glb"), "--frames", "nine", withoutTears_});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("--frames"), qPrintable(r.err));
    const QString unwritable = dir_.filePath("no/such/folder/x.glb");
    r = run(kPlayer, {"--export-gltf", unwritable, withoutTears_});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(unwritable), qPrintable(r.err));
    QVERIFY(!QFile::exists(dir_.filePath("x.glb")));
  }

  void cancelledExportLeavesNoFile() {
    exporting::ExportOptions options;
    options.input = withTears_.toStdString();
    options.output = dir_.filePath("cancelled.glb").toStdString();
    int calls = 0;
    options.progress = [&](int done, int) { return ++calls, done < 5; };
    QVERIFY_THROWS_EXCEPTION(exporting::ExportCancelled,
                             exporting::exportGltfAnimation(*rig_, options));
    QCOMPARE(calls, 5);
    QVERIFY(!QFile::exists(dir_.filePath("cancelled.glb")));
    QCOMPARE(QDir(dir_.path()).entryList({"cancelled*"}).size(), 0);
  }

 private:
  QString exportDry() {
    const QString out = dir_.filePath("dry.glb");
    if (!QFile::exists(out)) {
      const testsupport::ProcessRun r = run(kPlayer, {"--export-gltf", out, withoutTears_});
      if (r.exitCode != 0) qWarning("%s", qPrintable(r.err));
      if (!r.err.contains("tears in 0 frames")) qWarning("%s", qPrintable(r.err));
    }
    return out;
  }
};

QTEST_GUILESS_MAIN(GltfExportTest)
#include "GltfExportTest.moc"
