#include <lacrima/batch/BatchJob.h>

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/JsonWriter.h>

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <array>

namespace lacrima::batch {

namespace {

constexpr std::array<std::string_view, kOutputCount> kOutputNames{"frames", "masks", "alpha",
                                                                  "video",  "gltf",  "tear-meshes"};

}  // namespace

std::string_view outputName(Output output) { return kOutputNames[static_cast<int>(output)]; }

std::optional<Output> outputByName(std::string_view name) {
  for (int k = 0; k < kOutputCount; ++k)
    if (kOutputNames[static_cast<std::size_t>(k)] == name) return static_cast<Output>(k);
  return std::nullopt;
}

bool needsDisplay(Output output) {
  return output == Output::Frames || output == Output::Masks || output == Output::Alpha ||
         output == Output::Video;
}

bool BatchJob::wants(Output output) const {
  return std::find(outputs.begin(), outputs.end(), output) != outputs.end();
}

bool BatchJob::needsDisplay() const {
  return std::any_of(outputs.begin(), outputs.end(),
                     [](Output o) { return batch::needsDisplay(o); });
}

std::string BatchJob::framesText() const {
  if (firstFrame == 0 && lastFrame < 0) return "all";
  return std::to_string(firstFrame) + "-" + (lastFrame < 0 ? "end" : std::to_string(lastFrame));
}

std::string BatchJob::label() const {
  std::string text =
      !mood.empty()
          ? mood + " seed " + std::to_string(seed)
          : QFileInfo(QString::fromStdString(animation->written)).fileName().toStdString();
  if (mesh)
    text += " on " + QFileInfo(QString::fromStdString(mesh->written)).fileName().toStdString();
  text += tears ? ", tears" : ", no tears";
  text += ", " + view + " " + std::to_string(width) + "x" + std::to_string(height);
  return text;
}

std::string fileSha256(const std::string& path) {
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly))
    throw FileError({path, 0, 0}, "cannot read: " + file.errorString().toStdString());
  QCryptographicHash hash(QCryptographicHash::Sha256);
  if (!hash.addData(&file))
    throw FileError({path, 0, 0}, "cannot read: " + file.errorString().toStdString());
  return hash.result().toHex().toStdString();
}

std::string canonicalJson(const BatchJob& job,
                          const std::function<std::string(const std::string&)>& fingerprint) {
  JsonWriter json(JsonWriter::Layout::Compact);
  const auto file = [&](std::string_view name, const InputFile& input) {
    json.key(name);
    json.beginObject();
    json.field("file", std::string_view(input.written));
    json.field("sha256", std::string_view(fingerprint(input.resolved)));
    json.endObject();
  };
  json.beginObject();
  if (job.animation) file("animation", *job.animation);
  if (!job.mood.empty()) {
    json.field("mood", std::string_view(job.mood));
    // As text: JSON numbers are doubles, and seeds use all 64 bits.
    json.field("seed", std::string_view(std::to_string(job.seed)));
    json.field("seconds", job.seconds);
  }
  if (job.mesh) file("mesh", *job.mesh);
  if (job.fdp) file("fdp", *job.fdp);
  json.field("tears", job.tears);
  json.field("quality", std::string_view(job.quality.empty() ? "file" : job.quality));
  json.field("view", std::string_view(job.view));
  json.field("size",
             std::string_view(std::to_string(job.width) + "x" + std::to_string(job.height)));
  json.field("frames", std::string_view(job.framesText()));
  json.key("outputs");
  json.beginArray();
  for (Output o : job.outputs) json.string(outputName(o));
  json.endArray();
  json.endObject();
  std::string text = std::move(json).finish();
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

std::string jobId(const std::string& canonical) {
  const QByteArray digest = QCryptographicHash::hash(
      QByteArray::fromRawData(canonical.data(), static_cast<qsizetype>(canonical.size())),
      QCryptographicHash::Sha256);
  return digest.toHex().left(16).toStdString();
}

}  // namespace lacrima::batch
