#pragma once
// Copying and pasting keys, through the system clipboard so keys move between editor windows.
//
// Copied keys are stored with times relative to the first of them, as a project document
// (the project JSON, so the text is readable and validated on the way back in) under the
// MIME type application/x-lacrima-keys, plus the same text as plain text.
#include <lacrima/common/Keyframes.h>

#include <optional>
#include <span>
#include <vector>

class QMimeData;

namespace lacrima::editing {

inline constexpr const char* kKeysMimeType = "application/x-lacrima-keys";

// The keys at `times`, shifted so the earliest is at 0.
std::vector<Keyframe> copyKeys(const KeyframeSequence& keys, std::span<const double> times);

// Owned by the caller (QClipboard::setMimeData takes it).
QMimeData* keysToMimeData(const std::vector<Keyframe>& keys);
// nullopt when the clipboard holds no keys (or text that is not a valid key list).
std::optional<std::vector<Keyframe>> keysFromMimeData(const QMimeData* data);

}  // namespace lacrima::editing
