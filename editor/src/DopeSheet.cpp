#include <lacrima/editor/DopeSheet.h>

#include <lacrima/editor/DopeSheetView.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QToolButton>
#include <QVBoxLayout>

namespace lacrima::editor {

DopeSheet::DopeSheet(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent),
      view_(new DopeSheetView(model, this)),
      filter_(new QLineEdit(this)),
      onlyAnimated_(new QToolButton(this)) {
  setObjectName(QStringLiteral("dopeSheet"));
  filter_->setObjectName(QStringLiteral("dopeSheetFilter"));
  filter_->setPlaceholderText(
      tr("Filter channels: name, number or group  (jaw, 31, 19-22, tears)"));
  filter_->setClearButtonEnabled(true);
  onlyAnimated_->setObjectName(QStringLiteral("dopeSheetOnlyAnimated"));
  onlyAnimated_->setText(tr("Only animated"));
  onlyAnimated_->setCheckable(true);
  onlyAnimated_->setChecked(view_->onlyAnimated());
  onlyAnimated_->setToolTip(tr("Show only channels that some key sets (off: every channel)"));
  // The mouse and keys, on hover (a tooltip over the whole sheet would follow every move).
  auto* help = new QLabel(tr("Keys…"), this);
  help->setEnabled(false);
  help->setToolTip(
      tr("Click a mark to select (Ctrl/Shift adds), drag to move, drag on empty space to box "
         "select, click a name to select its row.\nA all · Alt+A none · Delete/X delete · Ctrl+C "
         "copy · Ctrl+V paste at the playhead · Shift+D duplicate to the playhead · F frame all"));

  auto* bar = new QHBoxLayout;
  bar->setContentsMargins(4, 2, 8, 2);
  // The filter's long placeholder must not claim the bar: the buttons after it keep their room.
  filter_->setMinimumWidth(120);
  filter_->setMaximumWidth(520);
  bar->addWidget(filter_, 1);
  bar->addWidget(onlyAnimated_);
  bar->addStretch(0);
  help->setMinimumWidth(help->sizeHint().width());
  bar->addWidget(help);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addLayout(bar);
  layout->addWidget(view_, 1);
  setFocusProxy(view_);  // focusing the sheet (after a time is entered) focuses its marks

  connect(filter_, &QLineEdit::textChanged, view_, &DopeSheetView::setFilterText);
  connect(onlyAnimated_, &QToolButton::toggled, view_, &DopeSheetView::setOnlyAnimated);
}

}  // namespace lacrima::editor
