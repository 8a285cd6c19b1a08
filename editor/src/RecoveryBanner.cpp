#include <lacrima/editor/RecoveryBanner.h>

#include <lacrima/editor/EditorTheme.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>

namespace lacrima::editor {

RecoveryBanner::RecoveryBanner(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("recoveryBanner"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(12, 6, 8, 6);
  text_ = new QLabel(this);
  text_->setWordWrap(true);
  restore_ = new QPushButton(tr("Restore"), this);
  restore_->setObjectName(QStringLiteral("restoreRecovery"));
  discard_ = new QPushButton(tr("Discard"), this);
  discard_->setObjectName(QStringLiteral("discardRecovery"));
  layout->addWidget(text_, 1);
  layout->addWidget(restore_);
  layout->addWidget(discard_);
  connect(restore_, &QPushButton::clicked, this, &RecoveryBanner::restoreRequested);
  connect(discard_, &QPushButton::clicked, this, &RecoveryBanner::discardRequested);
}

void RecoveryBanner::setText(const QString& text) { text_->setText(text); }

void RecoveryBanner::paintEvent(QPaintEvent*) {
  QPainter p(this);
  QColor c = theme::keyAccent();
  c.setAlphaF(0.18);
  p.fillRect(rect(), palette().color(QPalette::Window));
  p.fillRect(rect(), c);
  p.fillRect(QRect(0, 0, 4, height()), theme::keyAccent());
}

}  // namespace lacrima::editor
