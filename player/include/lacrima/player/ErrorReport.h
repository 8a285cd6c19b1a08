#pragma once
// What the player tells a user about a file it cannot use: the file, the line (and column), and
// the message, both as one line for stderr and the status bar and as rich text for a dialog.
#include <QString>

#include <exception>

namespace lacrima::player {

struct ErrorReport {
  QString file;  // as named by the user
  int line = 0;  // 0 when the problem concerns the whole file
  int column = 0;
  QString message;  // what was expected
  QString oneLine;  // "file:line:column: message"

  QString html() const;  // for QMessageBox
};

// From a FileError (file, line, column, message) or any other exception (its what()), for
// `path` when the exception does not name a file itself.
ErrorReport describeError(const std::exception& error, const QString& path);

}  // namespace lacrima::player
