#include <lacrima/viewport/WarningsButton.h>

#include <QDialog>
#include <QDialogButtonBox>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace lacrima::viewport {

WarningsButton::WarningsButton(QWidget* parent) : QToolButton(parent) {
  setObjectName(QStringLiteral("warningsButton"));
  setAutoRaise(true);
  setStyleSheet(QStringLiteral("QToolButton { color: #e6b43c; padding: 1px 6px; }"));
  hide();
  connect(this, &QToolButton::clicked, this, [this] { showList(); });
}

void WarningsButton::setWarnings(const QStringList& warnings, const QString& source) {
  warnings_ = warnings;
  source_ = source;
  const auto count = static_cast<int>(warnings.size());
  setText(tr("⚠ %n warning(s)", nullptr, count));
  setToolTip(count == 0 ? QString() : tr("Click to read every warning of %1").arg(source));
  setVisible(count > 0);
  if (list_) fillList();
}

QDialog* WarningsButton::showList() {
  if (!list_) {
    list_ = new QDialog(this);
    list_->setObjectName(QStringLiteral("warningsList"));
    list_->resize(720, 360);
    auto* layout = new QVBoxLayout(list_);
    text_ = new QPlainTextEdit(list_);
    text_->setReadOnly(true);
    text_->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, list_);
    connect(buttons, &QDialogButtonBox::rejected, list_, &QDialog::close);
    layout->addWidget(text_, 1);
    layout->addWidget(buttons);
  }
  fillList();
  list_->show();
  list_->raise();
  return list_;
}

void WarningsButton::fillList() {
  list_->setWindowTitle(
      tr("%n warning(s) of %1", nullptr, static_cast<int>(warnings_.size())).arg(source_));
  text_->setPlainText(warnings_.join(QStringLiteral("\n\n")));
}

}  // namespace lacrima::viewport
