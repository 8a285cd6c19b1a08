#include <lacrima/viewport/DarkTheme.h>

#include <QApplication>
#include <QPalette>
#include <QStyleFactory>

namespace lacrima::viewport {

void applyDarkTheme(QApplication& app) {
  app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
  QPalette p;
  const QColor window(0x2b, 0x2d, 0x31);
  const QColor base(0x1f, 0x21, 0x24);
  const QColor text(0xdc, 0xde, 0xe2);
  const QColor disabled(0x7a, 0x7e, 0x86);
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, QColor(0x26, 0x28, 0x2c));
  p.setColor(QPalette::ToolTipBase, QColor(0x35, 0x38, 0x3d));
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, QColor(0x36, 0x39, 0x3e));
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, QColor(0xff, 0x6b, 0x6b));
  p.setColor(QPalette::Highlight, QColor(0x3d, 0x7e, 0xc9));
  p.setColor(QPalette::HighlightedText, Qt::white);
  p.setColor(QPalette::Link, QColor(0x6a, 0xa8, 0xf0));
  p.setColor(QPalette::PlaceholderText, disabled);
  p.setColor(QPalette::Mid, QColor(0x44, 0x47, 0x4d));
  p.setColor(QPalette::Dark, QColor(0x18, 0x19, 0x1c));
  p.setColor(QPalette::Light, QColor(0x4a, 0x4d, 0x54));
  for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
    p.setColor(QPalette::Disabled, role, disabled);
  app.setPalette(p);
  app.setStyleSheet(
      QStringLiteral("QToolTip { border: 1px solid #50545b; padding: 4px; }"
                     "QDockWidget::title { padding: 4px 6px; background: #25272b; }"
                     "QToolBar { border: none; spacing: 2px; }"
                     "QStatusBar { color: #aeb2b9; }"));
}

}  // namespace lacrima::viewport
