// lacrima-rig: rig a head for MPEG-4 facial animation. Reads a head (the default MakeHuman head
// or any file assimp reads) and its feature-point file, bakes one pose per FAP and writes the
// player's assets. Exit codes as lacrima-fap: 0 success, 1 bad input or a failed write, 2 wrong
// usage; results on stdout (--report), diagnostics and progress on stderr.
#include "Previews.h"
#include "Progress.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/exporters/GlbExport.h>
#include <lacrima/exporters/OgreMeshExport.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/rigging/ImportProcess.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/rigging/RigChecks.h>
#include <lacrima/rigging/RigDescription.h>
#include <lacrima/rigging/SkinTopology.h>
#include <lacrima/rigging/SphereFit.h>

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QGuiApplication>

#include <charconv>
#include <cstdio>
#include <optional>
#include <string>

using namespace lacrima;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "3=400", "open_jaw=-200" -> channel values.
FapValues parseFapValues(const QStringList& items) {
  FapValues values{};
  for (const QString& item : items) {
    const qsizetype eq = item.indexOf('=');
    const std::string name = item.left(eq).trimmed().toStdString();
    const std::string number = eq < 0 ? std::string() : item.mid(eq + 1).trimmed().toStdString();
    int fap = 0;
    const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), fap);
    if (ec != std::errc() || end != name.data() + name.size()) fap = fapByName(name).value_or(0);
    double value = 0;
    const auto [vend, vec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (eq < 0 || !isValidFap(fap) || vec != std::errc() || vend != number.data() + number.size())
      throw UsageError("--fap " + item.toStdString() + ": expected FAP=VALUE with a FAP number 1-" +
                       std::to_string(kChannelCount) + " or name (e.g. 3=400 or open_jaw=400)");
    values[static_cast<std::size_t>(channelIndex(fap))] = static_cast<float>(value);
  }
  return values;
}

void printWarnings(const Warnings& warnings) {
  for (const Diagnostic& d : warnings) std::fprintf(stderr, "warning: %s\n", d.toString().c_str());
}

PreviewPoints pointsForPreview(const HeadMesh& mesh, const rigging::FeaturePointFile& fdp,
                               const rigging::BuiltRig* rig) {
  PreviewPoints points;
  for (const auto& [id, spec] : fdp.points) points[id] = rigging::surfacePosition(spec.at, mesh);
  if (rig) {
    if (rig->eyeCentreLeft) points["eyeL"] = *rig->eyeCentreLeft;
    if (rig->eyeCentreRight) points["eyeR"] = *rig->eyeCentreRight;
    points["7.1"] = rig->neckPivot;
    points["tearL"] = rig->tearLeft.position;
    points["tearR"] = rig->tearRight.position;
  }
  return points;
}

// --complete: the partial file's points plus the default head's others, carried onto `mesh`
// (FeaturePointProposal.h).
rigging::FeaturePointFile completeFeaturePoints(const rigging::FeaturePointFile& file,
                                                const HeadMesh& mesh, std::string_view meshName,
                                                Warnings* warnings) {
  const rigging::FeaturePointFile partial = rigging::validateFeaturePoints(
      file, mesh, warnings, rigging::FeaturePointSet::Partial, meshName);
  if (!rigging::defaultHeadAvailable())
    throw FileError({rigging::defaultHeadPackageDir(), 0, 0},
                    "--complete carries the default head's feature points, but the default head "
                    "is not in the cache; run " +
                        rigging::defaultHeadFetchCommand() + " first");
  const HeadMesh reference = rigging::loadDefaultHead();
  const rigging::FeaturePointFile referenceFdp =
      rigging::readFeaturePointFile(findMediaFile("default-head.fdp.json"));
  rigging::validateFeaturePoints(referenceFdp, reference, nullptr);
  rigging::FeaturePointFile complete =
      rigging::proposeFeaturePoints(partial, mesh, referenceFdp, reference, warnings);
  rigging::recordPositions(complete, mesh);  // so that a re-exported mesh can be re-snapped
  return complete;
}

void savePng(const QImage& image, const std::string& path) {
  if (!image.save(QString::fromStdString(path), "PNG"))
    throw FileError({path, 0, 0}, "cannot write the PNG image (folder missing or not writable?)");
  std::fprintf(stderr, "lacrima-rig: wrote %s\n", path.c_str());
}

int run(QCommandLineParser& parser) {
  const bool useDefault = parser.isSet("default");
  if (useDefault == parser.isSet("mesh"))
    throw UsageError("choose the head: --default, or --mesh FILE with --fdp FILE");
  if (parser.isSet("mesh") && !parser.isSet("fdp"))
    throw UsageError("--mesh needs --fdp FILE (its feature points)");
  const bool wantRig = parser.isSet("output") || parser.isSet("report") ||
                       parser.isSet("pose-image") || parser.isSet("check");
  const bool complete = parser.isSet("complete");
  if (complete && !parser.isSet("mesh"))
    throw UsageError("--complete needs --mesh FILE and --fdp PARTIAL (feature points on it)");
  if (!wantRig && !complete && !parser.isSet("fdp-image"))
    throw UsageError(
        "nothing to do: give -o DIR, --report, --check, --fdp-image, --pose-image or --complete "
        "FILE");
  if (parser.isSet("fap") && !parser.isSet("pose-image"))
    throw UsageError("--fap only applies to --pose-image");
  std::optional<rigging::GeodesicMethod> method;
  if (parser.isSet("geodesics")) {
    const QString m = parser.value("geodesics");
    if (m == "dijkstra")
      method = rigging::GeodesicMethod::Dijkstra;
    else if (m == "heat")
      method = rigging::GeodesicMethod::Heat;
    else
      throw UsageError("--geodesics: expected dijkstra or heat, got " + m.toStdString());
  }
  bool sizeOk = false;
  const int panelSize = parser.value("image-size").toInt(&sizeOk);
  if (!sizeOk || panelSize < 100 || panelSize > 4000)
    throw UsageError("--image-size: expected 100 to 4000 pixels");
  const FapValues values = parseFapValues(parser.values("fap"));
  rigging::ImportOptions importOptions;
  if (parser.isSet("import-time-limit")) {
    bool ok = false;
    const double seconds = parser.value("import-time-limit").toDouble(&ok);
    if (!ok || !(seconds >= 0.1 && seconds <= 86400))
      throw UsageError("--import-time-limit: expected 0.1 to 86400 seconds");
    importOptions.seconds = seconds;
  }

  QElapsedTimer timer;
  timer.start();
  HeadMesh mesh;
  std::string fdpPath = parser.value("fdp").toStdString();
  const std::string meshName = useDefault ? "the default head" : parser.value("mesh").toStdString();
  if (useDefault) {
    if (!rigging::defaultHeadAvailable())
      throw FileError({rigging::defaultHeadPackageDir(), 0, 0},
                      "the default head is not in the cache; run " +
                          rigging::defaultHeadFetchCommand() + " first");
    mesh = rigging::loadDefaultHead();
    if (fdpPath.empty()) fdpPath = findMediaFile("default-head.fdp.json");
  } else {
    // A user's file is read by the importer process: a file that crashes or hangs assimp costs
    // that process, and comes back here as a FileError naming the file.
    mesh = rigging::importHeadMeshIsolated(parser.value("mesh").toStdString(), importOptions);
  }
  Warnings warnings;
  rigging::FeaturePointFile fdp = rigging::readFeaturePointFile(fdpPath, &warnings);
  if (complete) {
    fdp = completeFeaturePoints(fdp, mesh, meshName, &warnings);
    const std::string out = parser.value("complete").toStdString();
    saveAtomically(out, rigging::featurePointFileJson(fdp));
    std::fprintf(stderr, "lacrima-rig: wrote %s (%zu feature points)\n", out.c_str(),
                 fdp.points.size());
    fdp = rigging::readFeaturePointFile(out);  // so that messages name the complete file's lines
  }
  fdp = rigging::validateFeaturePoints(fdp, mesh, &warnings, rigging::FeaturePointSet::Complete,
                                       meshName);
  for (const std::string& w : rigging::checkSkinTopology(mesh, fdp.skin)) {
    Diagnostic d;
    d.where.file = fdpPath;
    d.message = w;
    warnings.push_back(std::move(d));
  }
  // From here on head and points are in the face frame (+y up, face towards +z), whatever axes
  // the head was exported with: the rig, rig.json and the images.
  const rigging::FaceFrame frame = rigging::bringToFaceFrame(mesh, fdp, &warnings);
  rigging::dropIgnoredParts(mesh, fdp);
  printWarnings(warnings);

  std::optional<rigging::BuiltRig> rig;
  if (wantRig) {
    Progress progress;
    rigging::RigOptions options;
    options.geodesics = method;
    options.progress = [&](double f, std::string_view stage) { progress.update(f, stage); };
    rig = rigging::buildRig(mesh, fdp, options);
  }
  const double rigSeconds = static_cast<double>(timer.elapsed()) / 1000.0;
  if (rig) {
    for (const std::string& w : rig->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    std::fprintf(stderr, "lacrima-rig: loaded and rigged %d vertices in %.2f s\n",
                 mesh.vertexCount(), rigSeconds);
  }

  if (parser.isSet("output")) {
    const QString dir = parser.value("output");
    if (!QDir().mkpath(dir))
      throw FileError({dir.toStdString(), 0, 0}, "cannot create the output folder");
    const std::string base = QDir(dir).absolutePath().toStdString() + "/";
    exporters::exportOgreMesh(mesh, rig->poses, base + "head.mesh");
    exporters::exportGlb(mesh, rig->poses, base + "head.glb");
    saveAtomically(base + "rig.json", rigging::rigDescriptionJson(mesh, *rig, {}, frame));
    std::fprintf(
        stderr,
        "lacrima-rig: wrote %shead.mesh, head.material, head.glb, rig.json (%.2f s in all)\n",
        base.c_str(), static_cast<double>(timer.elapsed()) / 1000.0);
  }
  if (parser.isSet("report")) {
    const std::string report = rigging::rigReportJson(mesh, *rig);
    std::fwrite(report.data(), 1, report.size(), stdout);
  }
  if (parser.isSet("fdp-image")) {
    // Eye centres from the file or fitted, so the image also checks them without a full rig.
    rigging::BuiltRig preview;
    if (rig) {
      preview = *rig;
    } else {
      for (auto [spec, out] : {std::pair{&fdp.eyeLeft, &preview.eyeCentreLeft},
                               std::pair{&fdp.eyeRight, &preview.eyeCentreRight}}) {
        if (spec->centre)
          *out = *spec->centre;
        else if (!spec->submeshes.empty())
          if (const auto sphere = rigging::fitSphere(mesh, spec->submeshes)) *out = sphere->centre;
      }
      preview.neckPivot = fdp.neckPivot.value_or(Eigen::Vector3d::Zero());
      preview.tearLeft.position = preview.tearRight.position = preview.neckPivot;
    }
    const PreviewPoints points = pointsForPreview(mesh, fdp, &preview);
    savePng(
        exporters::renderHeadPreview(mesh, mesh.positions, previewPanels(mesh, points),
                                     previewMarkers(points), previewStyle(mesh, fdp, panelSize)),
        parser.value("fdp-image").toStdString());
  }
  if (parser.isSet("pose-image")) {
    const PoseBlender blender(mesh, rig->poses);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    // Markers follow their points through the pose, so misplaced motion is visible.
    PreviewPoints points;
    for (const auto& [id, binding] : rig->bindings) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (const auto& [v, w] : binding) p += w * positions.col(v).cast<double>();
      points[id] = p;
    }
    PreviewPoints neutral = pointsForPreview(mesh, fdp, nullptr);
    std::vector<exporters::PreviewPanel> panels = previewPanels(mesh, neutral);
    QString title;
    for (int fap = 1; fap <= kChannelCount; ++fap)
      if (const float v = values[static_cast<std::size_t>(channelIndex(fap))]; v != 0.0f)
        title += QString(" %1=%2")
                     .arg(QString::fromUtf8(fapInfo(fap).name.data(),
                                            static_cast<qsizetype>(fapInfo(fap).name.size())))
                     .arg(v);
    for (exporters::PreviewPanel& p : panels) p.title += title;
    savePng(exporters::renderHeadPreview(mesh, positions, panels, previewMarkers(points),
                                         previewStyle(mesh, fdp, panelSize)),
            parser.value("pose-image").toStdString());
  }
  if (parser.isSet("check")) {  // RigChecks.h: one line per check, exit 1 on an Error
    const std::vector<rigging::RigCheck> checks = rigging::checkRig(mesh, fdp, *rig);
    int errors = 0;
    for (const rigging::RigCheck& c : checks) {
      std::printf("%s\n", rigging::toString(c).c_str());
      errors += c.severity == rigging::RigCheck::Severity::Error;
    }
    std::printf("%zu checks: %d errors, %zu warnings\n", checks.size(), errors,
                checks.size() - static_cast<std::size_t>(errors));
    if (errors > 0) return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // Images need fonts, not a screen: default to the offscreen platform.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  QCoreApplication::setApplicationName("lacrima-rig");
  QCoreApplication::setApplicationVersion(LACRIMA_VERSION);
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Rigs a head for MPEG-4 facial animation: places its feature points (from a feature-point\n"
      "file), computes geodesic influence weights, bakes one pose per FAP and writes\n"
      "DIR/head.mesh + head.material + textures (OGRE), DIR/head.glb and DIR/rig.json.\n\n"
      "Examples:\n"
      "  lacrima-rig --default -o rig/\n"
      "  lacrima-rig --mesh head.obj --fdp head.fdp.json -o rig/ --report > report.json\n"
      "  lacrima-rig --default --fdp-image points.png\n"
      "  lacrima-rig --mesh head.obj --fdp partial.fdp.json --complete head.fdp.json\n"
      "  lacrima-rig --default --pose-image jaw.png --fap open_jaw=400 --fap 19=1024\n\n"
      "Exit codes: 0 success, 1 bad input or failed write, 2 wrong usage.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addOptions({
      {"default",
       "Rig the default MakeHuman head (fetched by lacrima-fetch-head; in a checkout, by "
       "packaging/fetch-default-head.sh)."},
      {"mesh", "Rig this head file (any format assimp reads).", "FILE"},
      {"fdp", "Feature-point file (*.fdp.json); default head: the bundled one.", "FILE"},
      {{"o", "output"},
       "Write head.mesh, head.material, textures, head.glb and rig.json here.",
       "DIR"},
      {"complete",
       "Propose the feature points --fdp lacks (it needs at least 2.10, 3.7, 3.8, 3.11, 3.12, "
       "8.3, 8.4, 9.3) by carrying the default head's onto --mesh; write the complete file "
       "here (then rig with it if -o, --report or an image is asked for too).",
       "FILE"},
      {"geodesics", "Distance for influence falloff: dijkstra (default) or heat.", "METHOD"},
      {"report", "Print FAPU values and per-FAP checks as JSON on stdout."},
      {"check",
       "Print the rig checks (points on the wrong part, asymmetry, zero FAPU, joined "
       "lips, poses that move nothing), one a line; exit 1 when one is an error."},
      {"fdp-image", "Render the neutral head with its feature points to a PNG.", "PNG"},
      {"pose-image", "Render the posed head (see --fap) with its feature points to a PNG.", "PNG"},
      {"fap", "A FAP value for --pose-image, e.g. 3=400 or open_jaw=400 (repeatable).",
       "FAP=VALUE"},
      {"image-size", "Pixels per image panel (default 600).", "N", "600"},
      {"import-time-limit",
       "Longest the importer process may take to read --mesh (default 10 s plus 3 s per MiB "
       "of the file); past it the import stops with an error.",
       "SECONDS"},
  });
  if (!parser.parse(QCoreApplication::arguments())) {
    std::fprintf(stderr, "lacrima-rig: %s\n(see lacrima-rig --help)\n",
                 qPrintable(parser.errorText()));
    return kExitUsage;
  }
  if (parser.isSet("help")) {
    std::fputs(qPrintable(parser.helpText()), stdout);
    return kExitOk;
  }
  if (parser.isSet("version")) {
    std::printf("lacrima-rig %s\n", LACRIMA_VERSION);
    return kExitOk;
  }
  if (!parser.positionalArguments().isEmpty()) {
    std::fprintf(stderr, "lacrima-rig: unexpected argument %s\n(see lacrima-rig --help)\n",
                 qPrintable(parser.positionalArguments().first()));
    return kExitUsage;
  }
  try {
    return run(parser);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "lacrima-rig: %s\n(see lacrima-rig --help)\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-rig: error: %s\n", e.what());
    return kExitBadInput;
  }
}
