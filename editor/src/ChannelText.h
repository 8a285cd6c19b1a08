#pragma once
// Channel and group names as the editor's widgets show them. Private to lacrima_editor.
#include <lacrima/common/FapTable.h>

#include <QString>

#include <string_view>

namespace lacrima::editor {

// A name from the FAP table (UTF-8 string_view) as a QString.
inline QString fromView(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// "Jaw, chin and inner lips": the group's name with a capital.
inline QString groupTitle(FapGroup group) {
  QString title = fromView(toString(group));
  if (!title.isEmpty()) title[0] = title[0].toUpper();
  return title;
}

}  // namespace lacrima::editor
