// Project documents: exact JSON round trips, precise errors, atomic saves; and the tear
// parameter table the documents validate against.
#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/common/TearParameters.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>

using namespace lacrima;

namespace {

constexpr const char* kDisplayName = "doc.json";

// Random keys with random channel subsets and modes; tear values are whole counts and the
// other values span magnitudes from 1e-3 to 1e7 so the float text round trip is exercised.
KeyframeSequence randomKeys(std::mt19937& random) {
  std::uniform_int_distribution<int> keyCount(0, 25);
  std::uniform_real_distribution<double> time(0.0, 120.0);
  std::bernoulli_distribution coin(0.5);
  std::bernoulli_distribution sparse(0.15);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-3, 7);
  std::uniform_int_distribution<int> tears(0, kMaxTearParticles);
  std::uniform_int_distribution<int> mode(0, 3);     // the four interpolations
  std::uniform_int_distribution<int> handles(0, 2);  // the three handle types
  KeyframeSequence keys;
  const int count = keyCount(random);
  for (int k = 0; k < count; ++k) {
    Keyframe key;
    key.time = time(random);
    key.interpolation = static_cast<Interpolation>(mode(random));
    for (int fap = 1; fap <= kChannelCount; ++fap) {
      if (!sparse(random)) continue;
      const float value =
          isTearChannel(fap)
              ? static_cast<float>(tears(random))
              : static_cast<float>(mantissa(random) * std::pow(10.0, exponent(random)));
      key.set(fap, value);
      if (sparse(random)) {
        // A shape of the channel's own, with handles of any size the file allows.
        const auto handle = [&](double direction) {
          return Handle{direction * std::abs(mantissa(random)) * std::pow(10.0, exponent(random)),
                        mantissa(random) * std::pow(10.0, exponent(random))};
        };
        key.setShape(
            fap, KeyShape{static_cast<Interpolation>(mode(random)),
                          static_cast<HandleType>(handles(random)), handle(-1e-4), handle(1e-4)});
      }
    }
    keys.insert(key);
  }
  return keys;
}

TearParameterValues randomSimulation(std::mt19937& random) {
  std::bernoulli_distribution coin(0.4);
  TearParameterValues values;
  for (const TearParameterInfo& info : tearParameterTable()) {
    if (!coin(random)) continue;
    std::uniform_real_distribution<double> value(info.minValue, info.maxValue);
    values[std::string(info.name)] = value(random);
  }
  return values;
}

ProjectDocument randomDocument(unsigned seed) {
  std::mt19937 random(seed);
  std::bernoulli_distribution coin(0.5);
  std::uniform_real_distribution<double> fps(0.5, 1000.0);
  std::uniform_real_distribution<double> coordinate(-0.2, 0.2);
  const char* names[] = {"sad crying", "pleurer \xc3\xa0 chaudes larmes", "quote \" back\\slash",
                         "tab\tnew\nline", ""};
  ProjectDocument document;
  document.name = names[seed % std::size(names)];
  document.fps = coin(random) ? 22.0 : fps(random);
  document.defaultInterpolation =
      std::array{Interpolation::Linear, Interpolation::Smooth, Interpolation::Constant,
                 Interpolation::Bezier}[random() % 4];
  document.keys = randomKeys(random);
  if (coin(random)) {
    document.tearSources.left =
        Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
  }
  if (coin(random)) {
    document.tearSources.right =
        Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
  }
  SceneSettings& scene = document.scene;
  scene.particles = coin(random);
  scene.surface = coin(random);
  scene.trails = coin(random);
  scene.textureBlending = coin(random);
  scene.blush = coin(random);
  scene.redness = coin(random) ? SceneSettings::Redness::Tears : SceneSettings::Redness::Animation;
  scene.simulation = randomSimulation(random);
  scene.quality.level = static_cast<TearQuality>(random() % 3);
  const std::array<const char*, 3> solvers{"wcsph", "dfsph", "pbf"};
  if (coin(random)) scene.quality.solver = solvers[random() % solvers.size()];
  if (coin(random)) scene.quality.tension = coin(random) ? "akinci" : "mueller";
  if (coin(random)) scene.quality.neighbours = coin(random) ? "octree" : "grid";
  // Absolute paths outside any temporary folder: they survive a save anywhere unchanged.
  if (coin(random)) document.head = HeadFiles{"/opt/faces/head.obj", "/opt/faces/head.fdp.json"};
  if (coin(random)) {  // keyed face colours (FaceColours.h)
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<IntensityKey> redness;
    for (int k = 0; k < 3; ++k)
      redness.push_back({unit(random) * 100, unit(random), Interpolation::Linear});
    document.colours.redness = IntensityCurve(redness);
    if (coin(random))
      document.colours.blush = IntensityCurve({{0.0, unit(random), Interpolation::Smooth}});
  }
  if (coin(random)) {  // keyed moods (MoodCurves.h)
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (Mood mood : kMoods)
      if (coin(random))
        document.moods[mood] =
            IntensityCurve({{unit(random) * 10, unit(random), Interpolation::Smooth},
                            {10 + unit(random) * 10, unit(random), Interpolation::Linear}});
  }
  return document;
}

// Writes `text` to `path`, creating its folder.
void writeFile(const QString& path, const QByteArray& text) {
  QDir().mkpath(QFileInfo(path).absolutePath());
  QFile file(path);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write(text);
}

QString readFile(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// A valid document with `fields` spliced into the top level.
std::string withTopLevel(const std::string& fields) {
  return R"({"format": "lacrima-project", "version": 1, "keys": [])" +
         (fields.empty() ? std::string() : ", " + fields) + "}";
}

// A valid version 2 document whose scene holds `fields`.
std::string withScene2(const std::string& fields) {
  return R"({"format": "lacrima-project", "version": 2, "keys": [], "scene": {)" + fields + "}}";
}

// A valid document whose only key holds `values`.
std::string withValues(const std::string& values) {
  return R"({"format": "lacrima-project", "version": 1,
            "keys": [{"time": 0, "values": )" +
         values + "}]}";
}

// A one-line document of schema `version` whose only key is `key`.
std::string withKey(int version, const std::string& key) {
  return R"({"format": "lacrima-project", "version": )" + std::to_string(version) +
         R"(, "keys": [)" + key + "]}";
}

FileError parseError(const std::string& json) {
  try {
    ProjectDocument::fromJson(json, kDisplayName);
  } catch (const FileError& error) {
    return error;
  }
  throw std::logic_error("document was accepted: " + json);
}

std::size_t countOccurrences(const QString& text, const QString& what) {
  return static_cast<std::size_t>(text.count(what));
}

}  // namespace

class ProjectDocumentTest : public QObject {
  Q_OBJECT

 private slots:
  void roundTripIsExact() {
    for (unsigned seed = 1; seed <= 300; ++seed) {
      const ProjectDocument document = randomDocument(seed);
      const std::string json = document.toJson();
      const ProjectDocument back = ProjectDocument::fromJson(json, kDisplayName);
      QVERIFY2(back == document, qPrintable(QString("seed %1").arg(seed)));
      // Writing is deterministic, so a second save diffs as empty.
      QCOMPARE(back.toJson(), json);
    }
  }

  void floatValuesSurviveTheirDecimalText() {
    // Every float in a wide band, sampled: float -> double -> text -> double -> float.
    std::mt19937 random(42);
    std::uniform_int_distribution<std::uint32_t> bits(0, 0x4b189680);  // 0 .. 1e7
    ProjectDocument document;
    for (int i = 0; i < 4000; ++i) {
      std::uint32_t pattern = bits(random);
      float value = 0.0f;
      std::memcpy(&value, &pattern, sizeof value);
      Keyframe key;
      key.time = i * 0.01;
      key.set(3, (i % 2) ? value : -value);
      key.set(4, static_cast<float>(i) * 0.1f);  // values whose text is short: "0.1"
      document.keys.insert(key);
    }
    const std::string json = document.toJson();
    QVERIFY(ProjectDocument::fromJson(json, kDisplayName) == document);
    QVERIFY(json.find("\"lower_t_midlip\": 0.1\n") != std::string::npos);
  }

  void writtenJsonUsesTheDocumentedLayout() {
    ProjectDocument document;
    document.name = "sad crying";
    Keyframe late;
    late.time = 1.5;
    late.set(kTearLeftFap, 12.0f);
    late.set(3, 120.0f);
    Keyframe early;
    early.time = 0.5;
    early.interpolation = Interpolation::Smooth;
    early.set(5, -7.25f);
    document.keys.insert(late);
    document.keys.insert(early);
    document.tearSources.left = Eigen::Vector3d(0.5, -1.25, 2.0);
    document.scene.simulation["adhesion"] = 40.0;
    const QString json = QString::fromStdString(document.toJson());

    for (const char* field : {"\"format\": \"lacrima-project\"",
                              "\"version\": 2",
                              "\"name\": \"sad crying\"",
                              "\"fps\": 22",
                              "\"interpolation\": \"linear\"",
                              "\"keys\": [",
                              "\"time\": 0.5",
                              "\"interpolation\": \"smooth\"",
                              "\"values\": {",
                              "\"open_jaw\": 120",
                              "\"tears_l_eye\": 12",
                              "\"raise_b_midlip\": -7.25",
                              "\"tearSources\": {",
                              "\"left\": [0.5, -1.25, 2]",
                              "\"right\": null",
                              "\"scene\": {",
                              "\"particles\": false",
                              "\"surface\": true",
                              "\"trails\": true",
                              "\"textureBlending\": true",
                              "\"redness\": \"animation\"",
                              "\"blush\": false",
                              "\"simulation\": {",
                              "\"adhesion\": 40"}) {
      QVERIFY2(json.contains(QLatin1String(field)), field);
    }
    // Documented field order, keys sorted by time, values in channel order, indented.
    QVERIFY(json.indexOf("\"format\"") < json.indexOf("\"version\""));
    QVERIFY(json.indexOf("\"keys\"") < json.indexOf("\"tearSources\""));
    QVERIFY(json.indexOf("\"tearSources\"") < json.indexOf("\"scene\""));
    QVERIFY(json.indexOf("\"time\": 0.5") < json.indexOf("\"time\": 1.5"));
    QVERIFY(json.indexOf("\"open_jaw\"") < json.indexOf("\"tears_l_eye\""));
    QVERIFY(json.startsWith("{\n  \"format\""));
    QVERIFY(json.contains("\n      \"time\": 0.5,\n"));
    QVERIFY(json.endsWith("}\n"));
    QCOMPARE(countOccurrences(json, "\"time\""), std::size_t{2});
  }

  // The quality is written only where it differs from the defaults (Balanced, the level's own
  // choices), so a project that never chose keeps its text; chosen, it reads back as written.
  void qualityFields() {
    ProjectDocument document;
    QVERIFY(!QString::fromStdString(document.toJson()).contains("quality"));
    document.scene.quality.level = TearQuality::Reference;
    document.scene.quality.solver = "dfsph";
    document.scene.quality.tension = "akinci";
    document.scene.quality.neighbours = "octree";
    const std::string json = document.toJson();
    for (const char* field : {"\"quality\": \"reference\"", "\"solver\": \"dfsph\"",
                              "\"tension\": \"akinci\"", "\"neighbours\": \"octree\""})
      QVERIFY2(QString::fromStdString(json).contains(QLatin1String(field)), field);
    QVERIFY(ProjectDocument::fromJson(json, kDisplayName) == document);

    const ProjectDocument read = ProjectDocument::fromJson(
        withScene2(R"("quality": "preview", "neighbours": "grid")"), kDisplayName);
    QVERIFY(read.scene.quality.level == TearQuality::Preview);
    QVERIFY(!read.scene.quality.solver && !read.scene.quality.tension);
    QVERIFY(read.scene.quality.neighbours == "grid");
    // An explicit choice equal to the level's own stays explicit: it is what the user chose.
    QVERIFY(QString::fromStdString(read.toJson()).contains("\"neighbours\": \"grid\""));
    QVERIFY(ProjectDocument::fromJson(withTopLevel(""), kDisplayName).scene.quality ==
            TearQualitySettings{});

    // Position-based fluids: written as "pbf", read back as written.
    document.scene.quality.solver = "pbf";
    const std::string pbf = document.toJson();
    QVERIFY(QString::fromStdString(pbf).contains("\"solver\": \"pbf\""));
    QVERIFY(ProjectDocument::fromJson(pbf, kDisplayName) == document);
    QVERIFY(ProjectDocument::fromJson(withScene2(R"("solver": "pbf")"), kDisplayName)
                .scene.quality.solver == "pbf");
  }

  // The keys are the simulation's registries' (TearMethodKeys): an app that simulates passes
  // them and a key outside them is an error naming the known ones, at its line; a reader given
  // none (lacrima-fap) keeps any well-formed key as written.
  void methodKeysAreCheckedAgainstTheRegistries() {
    const TearMethodKeys keys{{"wcsph", "dfsph", "pbf"}, {"mueller", "akinci"}, {"grid", "octree"}};
    const auto error = [&keys](const std::string& scene, const TearMethodKeys* known) {
      try {
        ProjectDocument::fromJson(withScene2(scene), kDisplayName, ProjectDocument::Use::Edit,
                                  known);
      } catch (const FileError& e) {
        return QString::fromUtf8(e.what());
      }
      return QString("no error");
    };
    QCOMPARE(error(R"("solver": "pcisph")", &keys),
             QString(R"(doc.json:1:67: scene.solver: expected "wcsph", "dfsph" or "pbf", )"
                     R"(got "pcisph")"));
    QCOMPARE(error(R"("quality": "preview", "tension": "becker")", &keys),
             QString(R"(doc.json:1:89: scene.tension: expected "mueller" or "akinci", )"
                     R"(got "becker")"));
    QCOMPARE(error(R"("neighbours": "kd-tree")", &keys),
             QString(R"(doc.json:1:67: scene.neighbours: expected "grid" or "octree", )"
                     R"(got "kd-tree")"));
    QCOMPARE(error(R"("solver": "dfsph", "neighbours": "octree")", &keys), QString("no error"));
    // Without the registries' keys a well-formed one is kept, to be written back unchanged.
    const ProjectDocument kept = ProjectDocument::fromJson(
        withScene2(R"("solver": "pcisph", "tension": "becker_2007")"), kDisplayName);
    QCOMPARE(*kept.scene.quality.solver, std::string("pcisph"));
    QCOMPARE(*kept.scene.quality.tension, std::string("becker_2007"));
    QVERIFY(ProjectDocument::fromJson(kept.toJson(), kDisplayName) == kept);
  }

  void minimalDocumentGetsDefaults() {
    const ProjectDocument document = ProjectDocument::fromJson(withTopLevel(""), kDisplayName);
    QVERIFY(document == ProjectDocument{});
    QCOMPARE(document.name, std::string("untitled"));
    QCOMPARE(document.fps, 22.0);
    QVERIFY(document.keys.empty());
    QVERIFY(!document.tearSources.left && !document.tearSources.right);
    QVERIFY(document.scene.surface && !document.scene.particles);
  }

  void keysMayBeListedInAnyOrder() {
    const ProjectDocument document = ProjectDocument::fromJson(
        R"({"format": "lacrima-project", "version": 1, "interpolation": "smooth",
            "keys": [{"time": 2, "values": {"open_jaw": 20}},
                     {"time": 1, "interpolation": "linear", "values": {"viseme": 4}}]})",
        kDisplayName);
    QCOMPARE(document.keys.keys().size(), std::size_t{2});
    QCOMPARE(document.keys.keys()[0].time, 1.0);
    QCOMPARE(document.keys.keys()[0].value(1), 4.0f);
    // A key without its own mode takes the document's default.
    QVERIFY(document.keys.keys()[0].interpolation == Interpolation::Linear);
    QVERIFY(document.keys.keys()[1].interpolation == Interpolation::Smooth);
  }

  void rejectsInvalidDocuments_data() {
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("location");  // SourceLocation::toString()
    QTest::addColumn<QString>("message");   // expected at the start of FileError::message()

    QTest::newRow("bad syntax")
        << QString("{\n  \"format\": \"lacrima-project\",\n  \"version\": 1,\n  \"keys\": [],\n}")
        << "doc.json:5:1"
        << "invalid JSON: ";
    QTest::newRow("bad syntax after UTF-8")
        << QString::fromUtf8("{\"name\": \"\xc3\xa9t\xc3\xa9\", \"fps\": 22,}") << "doc.json:1:27"
        << "invalid JSON: ";
    QTest::newRow("not an object") << "[1, 2]"
                                   << "doc.json:1:1"
                                   << "expected a JSON object";
    QTest::newRow("missing format") << R"({"version": 1, "keys": []})"
                                    << "doc.json:1:1"
                                    << "format: missing; this is not a Lacrima project";
    QTest::newRow("wrong format") << R"({"format": "lacrima-projekt", "version": 1, "keys": []})"
                                  << "doc.json:1:2"
                                  << "format: expected \"lacrima-project\", got the string";
    QTest::newRow("newer version")
        << R"({"format": "lacrima-project", "version": 3, "keys": [], "newField": 1})"
        << "doc.json:1:31"
        << "version: written by a newer Lacrima (schema 3); this build reads up to 2";
    QTest::newRow("fractional version")
        << R"({"format": "lacrima-project", "version": 1.5, "keys": []})"
        << "doc.json:1:31"
        << "version: expected a whole number >= 1";
    QTest::newRow("missing keys") << R"({"format": "lacrima-project", "version": 1})"
                                  << "doc.json:1:1"
                                  << "keys: missing";
    QTest::newRow("unknown top-level field")
        << QString::fromStdString(withTopLevel(R"("colour": "red")")) << "doc.json:1:57"
        << "colour: unknown field; expected one of format, version, name, fps";
    QTest::newRow("unknown FAP name")
        << QString::fromStdString(withValues(R"({"opn_jaw": 1})")) << "doc.json:2:45"
        << "keys[0].values.opn_jaw: unknown FAP name; did you mean open_jaw?";
    QTest::newRow("fractional tear count")
        << QString::fromStdString(withValues(R"({"tears_l_eye": 2.5})")) << "doc.json:2:45"
        << "keys[0].values.tears_l_eye: expected a whole number of particles in [0, 100000], got "
           "2.5";
    QTest::newRow("too many tears")
        << QString::fromStdString(withValues(R"({"tears_r_eye": 100001})")) << "doc.json:2:45"
        << "keys[0].values.tears_r_eye: expected a whole number of particles";
    QTest::newRow("value too large")
        << QString::fromStdString(withValues(R"({"open_jaw": 2e7})")) << "doc.json:2:45"
        << "keys[0].values.open_jaw: expected a number in [-1e7, 1e7], got 20000000";
    QTest::newRow("value not a number")
        << QString::fromStdString(withValues(R"({"open_jaw": "12"})")) << "doc.json:2:45"
        << "keys[0].values.open_jaw: expected a number";
    QTest::newRow("negative fps") << QString::fromStdString(withTopLevel(R"("fps": -22)"))
                                  << "doc.json:1:57"
                                  << "fps: expected a number in (0, 1000], got -22";
    QTest::newRow("fps as text") << QString::fromStdString(withTopLevel(R"("fps": "22")"))
                                 << "doc.json:1:57"
                                 << "fps: expected a number in (0, 1000]";
    // Times that once overflowed the bake's message (6e66) or threw std::length_error (1e9).
    QTest::newRow("time far beyond a day")
        << QString::fromStdString(withKey(1, R"({"time": 6e66, "values": {"open_jaw": 1}})"))
        << "doc.json:1:55"
        << "keys[0].time: expected a time in seconds from 0 to 86400, got 6e+66";
    QTest::newRow("time of a billion seconds")
        << QString::fromStdString(withKey(1, R"({"time": 1e9, "values": {"open_jaw": 1}})"))
        << "doc.json:1:55"
        << "keys[0].time: expected a time in seconds from 0 to 86400, got 1000000000";
    QTest::newRow("bezier in a version 1 file")
        << QString::fromStdString(
               withKey(1, R"({"time": 0, "interpolation": "bezier", "values": {"open_jaw": 1}})"))
        << "doc.json:1:66"
        << "keys[0].interpolation: expected \"linear\" or \"smooth\"";
    QTest::newRow("shapes in a version 1 file")
        << QString::fromStdString(
               withKey(1, R"({"time": 0, "values": {"open_jaw": 1}, "shapes": {"open_jaw": {}}})"))
        << "doc.json:1:93"
        << "keys[0].shapes: unknown field; expected one of time, interpolation, values";
    QTest::newRow("shape of a channel the key does not set")
        << QString::fromStdString(withKey(
               2, R"({"time": 0, "values": {"open_jaw": 1}, "shapes": {"raise_b_midlip": {}}})"))
        << "doc.json:1:104"
        << "keys[0].shapes.raise_b_midlip: a shape for a channel the key's \"values\" do not set";
    QTest::newRow("in handle pointing forward")
        << QString::fromStdString(withKey(2, R"({"time": 0, "values": {"open_jaw": 1}, "shapes":
               {"open_jaw": {"handles": "free", "in": [0.5, 1], "out": [0.5, 1]}}})"))
        << "doc.json:2:49"
        << "keys[0].shapes.open_jaw.in: expected a handle pointing back in time";
    QTest::newRow("handle too long")
        << QString::fromStdString(withKey(2, R"({"time": 0, "values": {"open_jaw": 1}, "shapes":
               {"open_jaw": {"handles": "aligned", "in": [-1, 1], "out": [1e9, 1]}}})"))
        << "doc.json:2:67"
        << "keys[0].shapes.open_jaw.out: expected a handle pointing forward in time: [0..86400 s";
    QTest::newRow("unknown handle type")
        << QString::fromStdString(withKey(2, R"({"time": 0, "values": {"open_jaw": 1}, "shapes":
               {"open_jaw": {"handles": "broken"}}})"))
        << "doc.json:2:30"
        << "keys[0].shapes.open_jaw.handles: expected \"auto\", \"aligned\" or \"free\"";
    QTest::newRow("bad default interpolation")
        << QString::fromStdString(withTopLevel(R"("interpolation": "cubic")")) << "doc.json:1:57"
        << "interpolation: expected \"linear\" or \"smooth\"";
    QTest::newRow("tearSources with 2 numbers")
        << QString::fromStdString(withTopLevel(R"("tearSources": {"left": [1, 2], "right": null})"))
        << "doc.json:1:73"
        << "tearSources.left: expected null or an array of 3 finite numbers";
    QTest::newRow("tearSources with text")
        << QString::fromStdString(withTopLevel(R"("tearSources": {"right": [1, "2", 3]})"))
        << "doc.json:1:86"
        << "tearSources.right[1]: expected a finite number";
    QTest::newRow("unknown tear source")
        << QString::fromStdString(withTopLevel(R"("tearSources": {"centre": null})"))
        << "doc.json:1:73"
        << "tearSources.centre: unknown field; expected one of left, right";
    QTest::newRow("unknown scene field")
        << QString::fromStdString(withTopLevel(R"("scene": {"colour": 1})")) << "doc.json:1:67"
        << "scene.colour: unknown field; expected one of particles, surface, trails";
    QTest::newRow("scene flag not a bool")
        << QString::fromStdString(withTopLevel(R"("scene": {"trails": 1})")) << "doc.json:1:67"
        << "scene.trails: expected true or false";
    QTest::newRow("bad redness") << QString::fromStdString(
                                        withTopLevel(R"("scene": {"redness": "always"})"))
                                 << "doc.json:1:67"
                                 << "scene.redness: expected \"animation\" or \"tears\"";
    QTest::newRow("unknown simulation parameter")
        << QString::fromStdString(withTopLevel(R"("scene": {"simulation": {"stickiness": 1}})"))
        << "doc.json:1:82"
        << "scene.simulation.stickiness: unknown parameter 'stickiness'; expected one of: pressure";
    QTest::newRow("adhesion out of range")
        << QString::fromStdString(withTopLevel(R"("scene": {"simulation": {"adhesion": 20000}})"))
        << "doc.json:1:82"
        << "scene.simulation.adhesion: 20000 is outside [0, 10000]";
    QTest::newRow("unknown quality level")
        << QString::fromStdString(withScene2(R"("quality": "ultra")")) << "doc.json:1:67"
        << "scene.quality: expected \"preview\", \"balanced\" or \"reference\", got \"ultra\"";
    QTest::newRow("quality level not a string")
        << QString::fromStdString(withScene2(R"("quality": 2)")) << "doc.json:1:67"
        << "scene.quality: expected \"preview\", \"balanced\" or \"reference\", got 2";
    QTest::newRow("solver not a key")
        << QString::fromStdString(withScene2(R"("solver": "PCISPH")")) << "doc.json:1:67"
        << "scene.solver: expected a method's key (lower-case letters, digits, - and _), got "
           "\"PCISPH\"";
    QTest::newRow("tension model not a key")
        << QString::fromStdString(withScene2(R"("quality": "preview", "tension": 2)"))
        << "doc.json:1:89"
        << "scene.tension: expected a method's key (lower-case letters, digits, - and _), got 2";
    QTest::newRow("neighbour structure not a key")
        << QString::fromStdString(withScene2(R"("neighbours": "")")) << "doc.json:1:67"
        << "scene.neighbours: expected a method's key (lower-case letters, digits, - and _), got "
           "\"\"";
    QTest::newRow("quality in a version 1 file")
        << QString::fromStdString(withTopLevel(R"("scene": {"quality": "reference"})"))
        << "doc.json:1:67"
        << "scene.quality: quality needs a project of version 2 or later";
    QTest::newRow("solver in a version 1 file")
        << QString::fromStdString(withTopLevel(R"("scene": {"solver": "dfsph"})"))
        << "doc.json:1:67"
        << "scene.solver: solver needs a project of version 2 or later";
    QTest::newRow("colours in a version 1 file")
        << QString::fromStdString(withTopLevel(R"("colours": {"redness": []})")) << "doc.json:1:57"
        << "colours: colours need a project of version 2 or later";
    QTest::newRow("colour beyond 1")
        << R"({"format": "lacrima-project", "version": 2, "keys": [], "colours": {"blush": [{"time": 0, "value": 1.5}]}})"
        << "doc.json:1:91"
        << "colours.blush[0].value: expected a number in [0, 1], got 1.5";
    QTest::newRow("unknown colour")
        << R"({"format": "lacrima-project", "version": 2, "keys": [], "colours": {"tint": []}})"
        << "doc.json:1:69"
        << "colours.tint: unknown field; expected one of redness, blush";
    QTest::newRow("moods in a version 1 file")
        << QString::fromStdString(withTopLevel(R"("moods": {"sadness": []})")) << "doc.json:1:57"
        << "moods: moods need a project of version 2 or later";
    QTest::newRow("mood beyond 1")
        << R"({"format": "lacrima-project", "version": 2, "keys": [], "moods": {"anger": [{"time": 0, "value": 1.5}]}})"
        << "doc.json:1:89"
        << "moods.anger[0].value: expected a number in [0, 1], got 1.5";
    QTest::newRow("unknown mood")
        << R"({"format": "lacrima-project", "version": 2, "keys": [], "moods": {"grief": []}})"
        << "doc.json:1:67"
        << "moods.grief: unknown field; expected one of sadness, anger, joy, shame";
    QTest::newRow("duplicate key time") << R"({"format": "lacrima-project", "version": 1, "keys": [
               {"time": 0.5, "values": {}}, {"time": 1, "values": {}},
               {"time": 0.5, "values": {"open_jaw": 1}}]})"
                                        << "doc.json:3:17"
                                        << "keys[2].time: 0.5 repeats the time of keys[0]";
    QTest::newRow("negative key time")
        << R"({"format": "lacrima-project", "version": 1, "keys": [{"time": -1, "values": {}}]})"
        << "doc.json:1:55"
        << "keys[0].time: expected a time in seconds from 0 to 86400, got -1";
    QTest::newRow("unknown key field")
        << R"({"format": "lacrima-project", "version": 1, "keys": [{"time": 0, "values": {}, "ease": 1}]})"
        << "doc.json:1:80"
        << "keys[0].ease: unknown field; expected one of time, interpolation, values";
    QTest::newRow("key without values")
        << R"({"format": "lacrima-project", "version": 1, "keys": [{"time": 0}]})"
        << "doc.json:1:54"
        << "keys[0].values: missing";
  }

  void rejectsInvalidHeads_data() {
    QTest::addColumn<QString>("head");
    QTest::addColumn<QString>("message");  // expected at the start of FileError::message()
    QTest::newRow("not an object") << R"("heads/ict.obj")"
                                   << R"(head: expected an object {"mesh": path, "fdp": path})";
    QTest::newRow("no mesh") << R"({"fdp": "a.fdp.json"})"
                             << R"(head: missing field "mesh")";
    QTest::newRow("no fdp") << R"({"mesh": "a.obj"})"
                            << R"(head: missing field "fdp")";
    QTest::newRow("empty mesh") << R"({"mesh": "", "fdp": "a.fdp.json"})"
                                << "head.mesh: expected a file path";
    QTest::newRow("number fdp") << R"({"mesh": "a.obj", "fdp": 3})"
                                << "head.fdp: expected a file path";
    QTest::newRow("unknown member") << R"({"mesh": "a.obj", "fdp": "a.fdp.json", "rig": "x"})"
                                    << "head.rig: unknown field";
  }

  void rejectsInvalidHeads() {
    QFETCH(QString, head);
    QFETCH(QString, message);
    const FileError error = parseError(withTopLevel("\"head\": " + head.toStdString()));
    QVERIFY2(QString::fromStdString(error.message()).startsWith(message), error.what());
    QCOMPARE(error.where().line, 1);  // the line of the bad value, as for every other field
    QVERIFY(error.where().column > 1);
  }

  void headIsOptionalAndKeptAsWritten() {
    QVERIFY(!ProjectDocument::fromJson(withTopLevel(""), kDisplayName).head);
    QVERIFY(ProjectDocument{}.toJson().find("\"head\"") == std::string::npos);
    const ProjectDocument document = ProjectDocument::fromJson(
        withTopLevel(R"("head": {"mesh": "heads/ict.obj", "fdp": "/abs/ict.fdp.json"})"),
        kDisplayName);
    QVERIFY(document.head);
    QCOMPARE(document.head->mesh, std::string("heads/ict.obj"));
    QCOMPARE(document.head->fdp, std::string("/abs/ict.fdp.json"));
    const QString json = QString::fromStdString(document.toJson());
    QVERIFY2(json.contains("\"head\": {\n    \"mesh\": \"heads/ict.obj\",\n    \"fdp\": "
                           "\"/abs/ict.fdp.json\"\n  }"),
             qPrintable(json));
    QVERIFY(json.indexOf("\"scene\"") < json.indexOf("\"head\""));
    QVERIFY(ProjectDocument::fromJson(document.toJson(), kDisplayName) == document);
  }

  // A project names its head relative to its own folder; loading makes the paths absolute and
  // saving elsewhere (Save As) rewrites them so they name the same files.
  void headPathsFollowTheProjectFile() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString original = folder.filePath("shots/crying.lacrima");
    writeFile(original,
              QByteArray::fromStdString(withTopLevel(
                  R"("head": {"mesh": "heads/ict.obj", "fdp": "./heads/../heads/ict.fdp.json"})")));
    const ProjectDocument loaded = ProjectDocument::load(original.toStdString());
    QVERIFY(loaded.head);
    const std::string mesh = QDir::cleanPath(folder.filePath("shots/heads/ict.obj")).toStdString();
    const std::string fdp =
        QDir::cleanPath(folder.filePath("shots/heads/ict.fdp.json")).toStdString();
    QCOMPARE(loaded.head->mesh, mesh);
    QCOMPARE(loaded.head->fdp, fdp);

    // Saved in its own folder: relative again, as written (normalised).
    loaded.save(original.toStdString());
    QVERIFY(readFile(original).contains(R"("mesh": "heads/ict.obj")"));
    QVERIFY(readFile(original).contains(R"("fdp": "heads/ict.fdp.json")"));

    // Save As into a sibling folder: the same files, through "..".
    const QString moved = folder.filePath("final/v2/crying.lacrima");
    QDir().mkpath(folder.filePath("final/v2"));
    loaded.save(moved.toStdString());
    QVERIFY2(readFile(moved).contains(R"("mesh": "../../shots/heads/ict.obj")"),
             qPrintable(readFile(moved)));
    const ProjectDocument reloaded = ProjectDocument::load(moved.toStdString());
    QCOMPARE(reloaded.head->mesh, mesh);
    QCOMPARE(reloaded.head->fdp, fdp);
    QVERIFY(reloaded == loaded);

    // A head sharing only the filesystem root with the project stays absolute.
    ProjectDocument elsewhere = loaded;
    elsewhere.head = HeadFiles{"/opt/faces/head.obj", "/opt/faces/head.fdp.json"};
    elsewhere.save(moved.toStdString());
    QVERIFY(readFile(moved).contains(R"("mesh": "/opt/faces/head.obj")"));
    QVERIFY(ProjectDocument::load(moved.toStdString()) == elsewhere);
  }

  void missingHeadFilesAreNamed() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    ProjectDocument document;
    QVERIFY(!document.missingHeadFile("p.lacrima"));  // the default head: nothing to check
    document.head = HeadFiles{folder.filePath("ict.obj").toStdString(),
                              folder.filePath("ict.fdp.json").toStdString()};
    auto problem = document.missingHeadFile("p.lacrima");
    QVERIFY(problem);
    QCOMPARE(problem->where.file, std::string("p.lacrima"));
    QVERIFY2(problem->message.starts_with("head.mesh: no file at " + document.head->mesh),
             problem->message.c_str());
    QVERIFY(problem->message.find("Choose head") != std::string::npos);
    writeFile(folder.filePath("ict.obj"), "v 0 0 0\n");
    problem = document.missingHeadFile("p.lacrima");
    QVERIFY(problem);
    QVERIFY(problem->message.starts_with("head.fdp: no file at " + document.head->fdp));
    QDir().mkpath(folder.filePath("ict.fdp.json"));  // a folder where the file should be
    QVERIFY(document.missingHeadFile("p.lacrima")->message.starts_with("head.fdp: not a file"));
    QDir(folder.filePath("ict.fdp.json")).removeRecursively();
    writeFile(folder.filePath("ict.fdp.json"), "{}");
    QVERIFY(!document.missingHeadFile("p.lacrima"));
  }

  void rejectsInvalidDocuments() {
    QFETCH(QString, json);
    QFETCH(QString, location);
    QFETCH(QString, message);
    const FileError error = parseError(json.toStdString());
    QCOMPARE(QString::fromStdString(error.where().toString()), location);
    QVERIFY2(QString::fromStdString(error.message()).startsWith(message),
             qPrintable(QString::fromStdString(error.message())));
    QVERIFY(QString::fromStdString(error.what()).startsWith(location + ": "));
  }

  // read() is what a file embedding a project (a recovery file) uses; it names the line and
  // column of a bad value as fromJson and load do.
  void readNamesLineColumnAndPath() {
    const std::string json =
        "{\"format\": \"lacrima-project\", \"version\": 1,\n \"keys\": [\n"
        "  {\"time\": 0, \"values\": {}},\n"
        "  {\"time\": 1, \"values\": {\"open_jaw\": \"wide\"}}]}";
    try {
      ProjectDocument::read(JsonInput::parse(json, kDisplayName).root());
      QFAIL("a value of the wrong type was read");
    } catch (const FileError& error) {
      QCOMPARE(std::string(error.what()),
               std::string("doc.json:4:26: keys[1].values.open_jaw: expected a number in "
                           "[-1e7, 1e7], got \"wide\""));
    }
  }

  void loadNamesAMissingFile() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const std::string path = folder.filePath("absent.lacrima").toStdString();
    try {
      ProjectDocument::load(path);
      QFAIL("loading a missing file succeeded");
    } catch (const FileError& error) {
      QCOMPARE(error.where().file, path);
      QVERIFY(std::string(error.what()).starts_with(path + ": cannot open"));
    }
    try {
      ProjectDocument::load(folder.path().toStdString());
      QFAIL("loading a folder succeeded");
    } catch (const FileError& error) {
      QCOMPARE(error.message(), std::string("is a folder, not a project file"));
    }
  }

  // A ~140-byte project asking a bake for 16 million frames (4.5 GB): opened to edit (the
  // editor can shorten it), refused to bake at the key that sets its length.
  void bakeLongerThanTheLimitIsRefusedToBake() {
    const std::string json =
        R"({"format":"lacrima-project","version":1,"fps":1000,"keys":[{"time":0,"values":{"open_jaw":1}},{"time":16000,"values":{"open_jaw":2}}]})";
    const ProjectDocument edited = ProjectDocument::fromJson(json, kDisplayName);
    QCOMPARE(edited.keys.keys().size(), std::size_t{2});
    QVERIFY_THROWS_EXCEPTION(std::length_error, edited.bake());
    try {
      ProjectDocument::fromJson(json, kDisplayName, ProjectDocument::Use::Bake);
      QFAIL("a project of 16 million frames was accepted to bake");
    } catch (const FileError& error) {
      QCOMPARE(QString::fromStdString(error.where().toString()), QString("doc.json:1:96"));
      QCOMPARE(QString::fromStdString(error.message()),
               QString("keys[1].time: the animation runs from 0 s to 16000 s, 16000001 frames at "
                       "1000 fps; at most 1048576 frames can be played or exported (shorten it "
                       "or lower the frame rate)"));
    }
    // One frame under the limit bakes.
    const std::string fits =
        R"({"format":"lacrima-project","version":1,"fps":1000,"keys":[{"time":0,"values":{"open_jaw":1}},{"time":1048.575,"values":{"open_jaw":2}}]})";
    QCOMPARE(ProjectDocument::fromJson(fits, kDisplayName, ProjectDocument::Use::Bake)
                 .bake()
                 .frames.size(),
             std::size_t{1048576});
  }

  void loadRefusesHugeFiles() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString path = folder.filePath("huge.lacrima");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QVERIFY(file.resize((qint64{64} << 20) + 1));  // sparse: costs no disk
    file.close();
    try {
      ProjectDocument::load(path.toStdString());
      QFAIL("a 64 MiB + 1 byte file was read");
    } catch (const FileError& error) {
      QVERIFY2(error.message().find("limited to 64 MiB") != std::string::npos, error.what());
    }
  }

  void saveThenLoadGivesTheSameDocument() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const std::string path = folder.filePath("crying.lacrima").toStdString();
    const ProjectDocument document = randomDocument(99);
    document.save(path);
    QVERIFY(ProjectDocument::load(path) == document);
  }

  void loadReportsErrorsWithThePath() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString path = folder.filePath("broken.lacrima");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\n  \"format\": \"lacrima-project\",\n  \"version\": 1\n  \"keys\": []\n}\n");
    file.close();
    try {
      ProjectDocument::load(path.toStdString());
      QFAIL("a broken file loaded");
    } catch (const FileError& error) {
      QCOMPARE(error.where().file, path.toStdString());
      QCOMPARE(error.where().line, 4);
    }
  }

  // Mood curves: saved and read back exactly, a bad key in a file named by file and line, and
  // never part of the animation that plays or exports (a strict .fap stays standard).
  void moodCurvesAreProjectCurvesOnly() {
    ProjectDocument document;
    document.keys = KeyframeSequence({[] {
      Keyframe key;
      key.set(3, 100);
      return key;
    }()});
    const FapAnimation without = document.bake();
    document.moods[Mood::Sadness] =
        IntensityCurve({{0, 0, Interpolation::Smooth}, {4, 0.8, Interpolation::Linear}});
    document.moods[Mood::Shame] = IntensityCurve({{2, 0.25, Interpolation::Smooth}});
    QCOMPARE(document.bake().frames, without.frames);
    QCOMPARE(document.bake().animated, without.animated);
    QVERIFY(document.moods.at(2)[Mood::Sadness] > 0.1 && document.moods.at(2)[Mood::Sadness] < 0.7);
    QCOMPARE(float(document.moods.at(6)[Mood::Sadness]), 0.8f);  // held after the last key
    QCOMPARE(document.moods.at(9)[Mood::Shame], 0.25);
    QCOMPARE(document.moods.endTime(), 4.0);

    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString path = folder.filePath("moods.lacrima");
    document.save(path.toStdString());
    QVERIFY(ProjectDocument::load(path.toStdString()) == document);
    QVERIFY(readFile(path).contains(QStringLiteral("\"moods\"")));

    writeFile(path,
              "{\"format\": \"lacrima-project\", \"version\": 2, \"keys\": [],\n"
              " \"moods\": {\n"
              "  \"sadness\": [{\"time\": 0, \"value\": 0},\n"
              "              {\"time\": 2, \"value\": -0.5}]}}\n");
    try {
      ProjectDocument::load(path.toStdString());
      QFAIL("a mood below 0 loaded");
    } catch (const FileError& error) {
      const QString what = QString::fromUtf8(error.what());
      QVERIFY2(what.startsWith(path + ":4:"), qPrintable(what));
      QVERIFY2(what.contains("moods.sadness[1].value: expected a number in [0, 1], got -0.5"),
               qPrintable(what));
    }
  }

  void saveIsAtomic() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const std::string path = folder.filePath("project.lacrima").toStdString();
    ProjectDocument first;
    first.name = "first";
    first.save(path);
    ProjectDocument second = randomDocument(7);
    second.name = "second";
    second.save(path);
    QVERIFY(ProjectDocument::load(path) == second);
    // Only the target remains: the temporary file was renamed over it.
    QCOMPARE(QDir(folder.path()).entryList(QDir::Files | QDir::Hidden | QDir::System),
             QStringList{"project.lacrima"});

    // A folder that does not exist: the save fails with a message and touches nothing.
    const std::string nowhere = folder.filePath("missing/project.lacrima").toStdString();
    try {
      second.save(nowhere);
      QFAIL("saving into a missing folder succeeded");
    } catch (const FileError& error) {
      QCOMPARE(error.where().file, nowhere);
      QVERIFY(!error.message().empty());
    }
    QVERIFY(!QFile::exists(QString::fromStdString(nowhere)));
    QVERIFY(ProjectDocument::load(path) == second);
  }

  void fromAnimationKeysEveryFrame() {
    FapAnimation animation;
    animation.name = "take3";
    animation.fps = 25.0;
    animation.frames.resize(50);
    animation.animated.set(channelIndex(3));
    animation.animated.set(channelIndex(kTearRightFap));
    for (int f = 0; f < animation.frameCount(); ++f) {
      animation.frames[f][channelIndex(3)] = static_cast<float>(f * 7 % 13) - 6.0f;
      animation.frames[f][channelIndex(kTearRightFap)] = static_cast<float>(f / 5);
    }
    const ProjectDocument document = ProjectDocument::fromAnimation(animation);
    QCOMPARE(document.name, std::string("take3"));
    QCOMPARE(document.fps, 25.0);
    QCOMPARE(document.keys.keys().size(), std::size_t{50});
    QVERIFY(document.keys.keys()[10].interpolation == Interpolation::Linear);
    const FapAnimation baked = document.bake();
    QVERIFY(baked.frames == animation.frames);
    QVERIFY(ProjectDocument::fromJson(document.toJson(), kDisplayName) == document);
  }

  void tearParameterDefaultsAreThe2009Values() {
    const std::pair<const char*, double> expected[] = {
        {"pressure", 0.004}, {"viscosity", 0.9}, {"tension", 0.2}, {"adhesion", 20.0},
        {"friction", 3.8},   {"gravity", 9.81},  {"kernel", 0.5},  {"node_size", 0.5},
        {"cube_size", 0.25}, {"iso", 0.5}};
    QCOMPARE(tearParameterTable().size(), std::size(expected));
    for (std::size_t i = 0; i < std::size(expected); ++i) {
      const TearParameterInfo& info = tearParameterTable()[i];
      QCOMPARE(info.name, std::string_view(expected[i].first));
      QCOMPARE(info.defaultValue, expected[i].second);
      QCOMPARE(findTearParameter(info.name), &info);
      QVERIFY(!info.description.empty());
    }
    QVERIFY(findTearParameter("stickiness") == nullptr);
  }

  void tearParameterDefaultsLieInTheirRanges() {
    for (const TearParameterInfo& info : tearParameterTable()) {
      QVERIFY(std::isfinite(info.minValue) && std::isfinite(info.maxValue));
      QVERIFY2(info.minValue <= info.defaultValue && info.defaultValue <= info.maxValue,
               info.name.data());
      validateTearParameter(info.name, info.defaultValue);  // must not throw
      validateTearParameter(info.name, info.minValue);
      validateTearParameter(info.name, info.maxValue);
    }
    // The stress cases a later simulation must survive are expressible.
    for (const auto& [name, value] :
         std::initializer_list<std::pair<const char*, double>>{{"adhesion", 10000.0},
                                                               {"pressure", 0.4},
                                                               {"viscosity", 0.0},
                                                               {"viscosity", 9.0},
                                                               {"tension", 0.0},
                                                               {"tension", 2.0},
                                                               {"kernel", 0.05},
                                                               {"kernel", 5.0}}) {
      validateTearParameter(name, value);
    }
  }

  void validateRejectsBadValuesAndNames() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, validateTearParameter("adhesion", NAN));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, validateTearParameter("adhesion", INFINITY));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, validateTearParameter("gravity", -INFINITY));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, validateTearParameter("iso", 0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, validateTearParameter("kernel", 0.001));
    try {
      validateTearParameter("adhesion", 10001.0);
      QFAIL("out-of-range adhesion accepted");
    } catch (const std::invalid_argument& error) {
      QCOMPARE(std::string(error.what()), std::string("adhesion: 10001 is outside [0, 10000]"));
    }
    try {
      validateTearParameter("Adhesion", 1.0);
      QFAIL("unknown name accepted");
    } catch (const std::invalid_argument& error) {
      QVERIFY(
          std::string(error.what())
              .starts_with(
                  "unknown parameter 'Adhesion'; expected one of: pressure, viscosity, tension"));
    }
  }
};

QTEST_GUILESS_MAIN(ProjectDocumentTest)
#include "ProjectDocumentTest.moc"
