#include <lacrima/batch/BatchManifest.h>

#include <lacrima/common/ImageSize.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/TearQuality.h>
#include <lacrima/common/mood/Moods.h>

#include <QDir>
#include <QFileInfo>

#include <array>
#include <limits>
#include <stdexcept>

namespace lacrima::batch {

namespace {

constexpr std::size_t kMaxAxisValues = 10000;
constexpr double kMoodRate = 22;  // lacrima-fap generate's frame rate
constexpr std::array<std::string_view, 12> kJobFields{"animation", "mood", "seed",   "seconds",
                                                      "mesh",      "fdp",  "tears",  "quality",
                                                      "view",      "size", "frames", "outputs"};

bool isJobField(std::string_view name) {
  return std::find(kJobFields.begin(), kJobFields.end(), name) != kJobFields.end();
}

class JobReader {
 public:
  explicit JobReader(const std::string& manifest)
      : base_(QFileInfo(QString::fromStdString(manifest)).absoluteDir()) {}

  void applyFields(BatchJob& job, const JsonValue& object) const {
    object.object();
    for (const JsonValue& member : object.members()) {
      if (!isJobField(member.name()))
        member.fail(
            "unknown job field; expected one of animation, mood, seed, seconds, mesh, "
            "fdp, tears, quality, view, size, frames, outputs");
      applyField(job, member.name(), member);
    }
  }

  void applyField(BatchJob& job, std::string_view name, const JsonValue& v) const {
    if (name == "animation") {
      job.animation = inputFile(v);
      job.mood.clear();
    } else if (name == "mood") {
      try {
        job.mood = toString(parseMoodLevels(v.string()));
      } catch (const std::invalid_argument& e) {
        v.fail(e.what());
      }
      job.animation.reset();
    } else if (name == "seed") {
      // Whole numbers a double holds exactly; lacrima-fap takes any 64-bit seed, manifests these.
      const double seed = v.number(0, 9007199254740991.0);
      if (seed != static_cast<double>(static_cast<std::uint64_t>(seed)))
        v.fail("expected a whole number, got " + v.describe());
      job.seed = static_cast<std::uint64_t>(seed);
    } else if (name == "seconds") {
      job.seconds = v.number(0.1, 3600);
    } else if (name == "mesh") {
      job.mesh = inputFile(v);
    } else if (name == "fdp") {
      job.fdp = inputFile(v);
    } else if (name == "tears") {
      job.tears = v.boolean();
    } else if (name == "quality") {
      const std::string level = v.string();
      if (!parseTearQuality(level)) v.fail("expected \"preview\", \"balanced\" or \"reference\"");
      job.quality = level;
    } else if (name == "view") {
      const std::string view = v.string();
      const bool word = !view.empty() && std::all_of(view.begin(), view.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || c == '-';
      });
      if (!word) v.fail("expected a view name such as \"front\" or \"close-left\"");
      job.view = view;
    } else if (name == "size") {
      const ParsedImageSize size = parseImageSize(v.string());
      if (!size.error.empty()) v.fail(size.error);
      if (size.size.width() % 2 || size.size.height() % 2)
        v.fail("expected an even width and height (H.264 needs them)");
      job.width = size.size.width();
      job.height = size.size.height();
    } else if (name == "frames") {
      readFrames(job, v);
    } else if (name == "outputs") {
      std::array<bool, kOutputCount> wanted{};
      for (const JsonValue& o : v.array(kOutputCount * 4)) {
        const std::optional<Output> output = outputByName(o.string());
        if (!output)
          o.fail(
              "expected \"frames\", \"masks\", \"alpha\", \"video\", \"gltf\" or "
              "\"tear-meshes\"");
        wanted[static_cast<std::size_t>(*output)] = true;
      }
      job.outputs.clear();
      for (int k = 0; k < kOutputCount; ++k)
        if (wanted[static_cast<std::size_t>(k)]) job.outputs.push_back(static_cast<Output>(k));
      if (job.outputs.empty()) v.fail("expected at least one output");
    }
  }

  // A job is complete once every layer is applied; `where` takes the blame otherwise.
  void check(const BatchJob& job, const JsonValue& where) const {
    if (!job.animation && job.mood.empty())
      where.fail("the job has neither \"animation\" nor \"mood\": expected one of them");
    if (job.mesh.has_value() != job.fdp.has_value())
      where.fail("\"mesh\" and \"fdp\" go together (a head and its feature points)");
    if (job.outputs.empty()) where.fail("the job has no \"outputs\"");
    if (!job.mood.empty() && job.lastFrame >= 0 && job.lastFrame > job.seconds * kMoodRate)
      where.fail("frames end at " + std::to_string(job.lastFrame) + ", past the end of a " +
                 formatJsonNumber(job.seconds) + " s take at 22 fps");
  }

 private:
  InputFile inputFile(const JsonValue& v) const {
    const std::string written = v.string();
    if (written.empty()) v.fail("expected a file name, got an empty string");
    const QString resolved =
        QDir::cleanPath(base_.absoluteFilePath(QString::fromStdString(written)));
    const QFileInfo info(resolved);
    if (!info.isFile()) v.fail("no such file: " + resolved.toStdString());
    return {written, resolved.toStdString()};
  }

  static void readFrames(BatchJob& job, const JsonValue& v) {
    const std::string text = v.string();
    if (text == "all") {
      job.firstFrame = 0;
      job.lastFrame = -1;
      return;
    }
    const auto dash = text.find('-');
    const auto number = [&](std::string_view part) {
      if (part.empty() || part.size() > 7 ||
          !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }))
        v.fail("expected \"all\" or FIRST-LAST with whole numbers, got \"" + text + "\"");
      return std::stoi(std::string(part));
    };
    if (dash == std::string::npos) v.fail("expected \"all\" or FIRST-LAST, got \"" + text + "\"");
    const int first = number(std::string_view(text).substr(0, dash));
    const int last = number(std::string_view(text).substr(dash + 1));
    if (last < first) v.fail("expected FIRST <= LAST, got \"" + text + "\"");
    job.firstFrame = first;
    job.lastFrame = last;
  }

  QDir base_;
};

// Every combination of the axes' values (the last axis fastest), each applied over `start`.
void expandGrid(const JobReader& reader, const BatchJob& start, const JsonValue& grid,
                std::vector<BatchJob>& jobs) {
  grid.object();
  const std::vector<JsonValue> axes = grid.members();
  std::vector<std::vector<JsonValue>> values;
  std::size_t product = 1;
  for (const JsonValue& axis : axes) {
    values.push_back(axis.array(kMaxAxisValues));
    if (values.back().empty()) axis.fail("expected at least one value on a grid axis");
    if (product > BatchManifest::kMaxJobs / values.back().size())
      axis.fail("the grid has more than " + std::to_string(BatchManifest::kMaxJobs) + " jobs");
    product *= values.back().size();
  }
  if (jobs.size() + product > BatchManifest::kMaxJobs)
    grid.fail("the manifest has more than " + std::to_string(BatchManifest::kMaxJobs) + " jobs");
  std::vector<std::size_t> at(axes.size(), 0);
  for (std::size_t n = 0; n < product; ++n) {
    BatchJob job = start;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const JsonValue& value = values[a][at[a]];
      if (isJobField(axes[a].name()))
        reader.applyField(job, axes[a].name(), value);
      else
        reader.applyFields(job, value);
    }
    reader.check(job, grid);
    jobs.push_back(std::move(job));
    for (std::size_t a = axes.size(); a-- > 0;) {
      if (++at[a] < values[a].size()) break;
      at[a] = 0;
    }
  }
}

}  // namespace

BatchManifest readManifest(const std::string& path) {
  const JsonValue root =
      JsonInput::load(path, {"batch manifest", BatchManifest::kMaxFileBytes}).root();
  root.rejectUnknownMembers({"format", "version", "defaults", "jobs", "grid", "paired"});
  if (root.has("format") && root["format"].string() != "lacrima-batch")
    root["format"].fail("expected \"lacrima-batch\"");
  if (root.has("version")) root["version"].integer(1, 1);
  const JobReader reader(path);
  BatchJob start;
  start.outputs = {Output::Frames};
  if (root.has("defaults")) reader.applyFields(start, root["defaults"]);
  if (!root.has("jobs") && !root.has("grid"))
    root.fail("the manifest has neither \"jobs\" nor \"grid\": expected at least one");

  BatchManifest manifest;
  manifest.path = path;
  if (root.has("jobs")) {
    for (const JsonValue& entry : root["jobs"].array(BatchManifest::kMaxJobs)) {
      BatchJob job = start;
      reader.applyFields(job, entry);
      reader.check(job, entry);
      manifest.jobs.push_back(std::move(job));
    }
  }
  if (root.has("grid")) expandGrid(reader, start, root["grid"], manifest.jobs);
  if (root.has("paired") && root["paired"].boolean()) {
    if (manifest.jobs.size() > BatchManifest::kMaxJobs / 2)
      root["paired"].fail("pairs would make more than " + std::to_string(BatchManifest::kMaxJobs) +
                          " jobs");
    std::vector<BatchJob> pairs;
    pairs.reserve(manifest.jobs.size() * 2);
    for (BatchJob& job : manifest.jobs) {
      job.tears = true;
      pairs.push_back(job);
      job.tears = false;
      pairs.push_back(std::move(job));
    }
    manifest.jobs = std::move(pairs);
  }
  return manifest;
}

}  // namespace lacrima::batch
