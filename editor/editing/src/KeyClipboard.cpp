#include <lacrima/editing/KeyClipboard.h>

#include <lacrima/common/ProjectDocument.h>
#include <lacrima/editing/KeyChange.h>

#include <QMimeData>

namespace lacrima::editing {

std::vector<Keyframe> copyKeys(const KeyframeSequence& keys, std::span<const double> times) {
  std::vector<Keyframe> out;
  for (double t : times) {
    const int index = findKey(keys, t);
    if (index >= 0) out.push_back(keys.keys()[static_cast<std::size_t>(index)]);
  }
  std::sort(out.begin(), out.end(),
            [](const Keyframe& a, const Keyframe& b) { return a.time < b.time; });
  if (!out.empty()) {
    const double first = out.front().time;
    for (Keyframe& key : out) key.time -= first;
  }
  return out;
}

QMimeData* keysToMimeData(const std::vector<Keyframe>& keys) {
  ProjectDocument clip;
  clip.name = "clipboard";
  clip.keys = KeyframeSequence(keys);
  const QByteArray text = QByteArray::fromStdString(clip.toJson());
  auto* data = new QMimeData;  // ownership passes to QClipboard
  data->setData(QString::fromLatin1(kKeysMimeType), text);
  data->setText(QString::fromUtf8(text));
  return data;
}

std::optional<std::vector<Keyframe>> keysFromMimeData(const QMimeData* data) {
  if (!data) return std::nullopt;
  QByteArray text = data->data(QString::fromLatin1(kKeysMimeType));
  if (text.isEmpty() && data->hasText()) text = data->text().toUtf8();
  if (text.isEmpty() || !text.contains("lacrima-project")) return std::nullopt;
  try {
    const ProjectDocument clip = ProjectDocument::fromJson(
        std::string_view(text.constData(), static_cast<std::size_t>(text.size())), "clipboard");
    if (clip.keys.empty()) return std::nullopt;
    return clip.keys.keys();
  } catch (const FileError&) {
    return std::nullopt;
  }
}

}  // namespace lacrima::editing
