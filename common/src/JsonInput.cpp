#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonSyntaxError.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <algorithm>

namespace lacrima::inline common {

JsonInput JsonInput::parse(std::string_view text, std::string name) {
  auto source = std::make_shared<const JsonSource>(JsonSource{std::string(text), std::move(name)});
  QJsonParseError error{};
  const QJsonDocument document = QJsonDocument::fromJson(
      QByteArray::fromRawData(source->text.data(), static_cast<qsizetype>(source->text.size())),
      &error);
  if (error.error != QJsonParseError::NoError) {
    throw FileError(jsonSyntaxErrorLocation(source->text, error, source->name),
                    "invalid JSON: " + error.errorString().toStdString());
  }
  QJsonValue root =
      document.isObject() ? QJsonValue(document.object()) : QJsonValue(document.array());
  return JsonInput(std::move(source), std::move(root));
}

JsonInput JsonInput::load(const std::string& path, const FileLimits& limits) {
  const auto fail = [&](const std::string& message) { throw FileError({path, 0, 0}, message); };
  const std::string kind(limits.kind);
  QFile file(QString::fromStdString(path));
  // QFile refuses folders with "Unknown error"; say what is actually wrong.
  if (QFileInfo(file).isDir()) fail("is a folder, not a " + kind);
  if (!file.open(QIODevice::ReadOnly)) fail("cannot open: " + file.errorString().toStdString());
  // Whole MiB from 1 MiB up, else bytes: "0 MiB" would say nothing under a small limit.
  const auto size = [](qint64 bytes) {
    return bytes >= (qint64{1} << 20) ? std::to_string(bytes >> 20) + " MiB"
                                      : std::to_string(bytes) + " bytes";
  };
  const auto tooLarge = [&](qint64 bytes) {
    fail("is " + size(bytes) + " or more; " + kind + "s are limited to " + size(limits.maxBytes));
  };
  if (file.size() > limits.maxBytes) tooLarge(file.size());
  // Read in pieces up to one byte past the limit: pipes and special files report size 0, and
  // QFile::read(limit) would allocate the whole limit up front (256 MiB for a 200-byte model;
  // found by fuzz_three_model, which ran at 2 inputs a second).
  constexpr qint64 kPiece = qint64{1} << 16;
  QByteArray bytes;
  for (;;) {
    const QByteArray piece = file.read(std::min(kPiece, limits.maxBytes + 1 - bytes.size()));
    if (piece.isEmpty()) break;
    bytes.append(piece);
    if (bytes.size() > limits.maxBytes) tooLarge(bytes.size());
  }
  if (file.error() != QFileDevice::NoError)
    fail("cannot read: " + file.errorString().toStdString());
  return parse(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), path);
}

JsonValue JsonInput::root() const {
  const JsonValue root(root_, JsonPath(), source_);
  if (!root.isObject())
    root.fail("expected a JSON object at the top level, got " + root.describe());
  return root;
}

}  // namespace lacrima::inline common
