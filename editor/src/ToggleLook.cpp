#include <lacrima/editor/ToggleLook.h>

#include <QToolButton>

namespace lacrima::editor {

void showCheckedState(QToolButton* button) {
  const QColor accent = button->palette().color(QPalette::Highlight);
  QColor fill = accent;
  fill.setAlphaF(0.45);
  button->setStyleSheet(
      QStringLiteral("QToolButton { border: 1px solid transparent; border-radius: 3px; "
                     "padding: 2px 4px; }"
                     "QToolButton:hover { border-color: %3; }"
                     "QToolButton:checked { background-color: %1; border-color: %2; }")
          .arg(fill.name(QColor::HexArgb), accent.name(),
               button->palette().color(QPalette::Mid).name()));
}

}  // namespace lacrima::editor
