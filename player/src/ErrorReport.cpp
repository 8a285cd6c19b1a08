#include <lacrima/player/ErrorReport.h>

#include <lacrima/common/Diagnostics.h>

#include <QFileInfo>

namespace lacrima::player {

QString ErrorReport::html() const {
  QString where = QStringLiteral("<b>%1</b>").arg(file.toHtmlEscaped());
  if (line > 0) where += QStringLiteral(", line %1").arg(line);
  if (column > 0) where += QStringLiteral(", column %1").arg(column);
  return QStringLiteral("<p>%1</p><p>%2</p>").arg(where, message.toHtmlEscaped());
}

ErrorReport describeError(const std::exception& error, const QString& path) {
  ErrorReport r;
  if (const auto* fileError = dynamic_cast<const FileError*>(&error)) {
    r.file = QString::fromStdString(fileError->where().file);
    r.line = fileError->where().line;
    r.column = fileError->where().column;
    r.message = QString::fromStdString(fileError->message());
    r.oneLine = QString::fromUtf8(fileError->what());
  } else {
    r.file = path;
    r.message = QString::fromUtf8(error.what());
    r.oneLine = path + ": " + r.message;
  }
  if (r.file.isEmpty()) r.file = path;
  return r;
}

}  // namespace lacrima::player
