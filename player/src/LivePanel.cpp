#include <lacrima/player/LivePanel.h>

#include <lacrima/common/FapChannels.h>

#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace lacrima::player {

LivePanel::LivePanel(QWidget* parent) : QWidget(parent) {
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(0, 0, 0, 0);
  status_ = new QLabel(this);
  status_->setObjectName("liveStatus");
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  column->addWidget(status_);
  auto* form = new QFormLayout;
  left_ = new QSpinBox(this);
  right_ = new QSpinBox(this);
  for (QSpinBox* box : {left_, right_}) {
    box->setRange(0, 500);  // the sliders' range; files may hold more
    box->setSuffix(tr(" particles"));
    box->setToolTip(
        tr("Tears for streams that carry no tear channel (FAP 69/70), such as a "
           "phone's blendshapes"));
    connect(box, &QSpinBox::valueChanged, this,
            [this] { emit tearsEdited(left_->value(), right_->value()); });
  }
  form->addRow(tr("Tears, left eye"), left_);
  form->addRow(tr("Tears, right eye"), right_);
  column->addLayout(form);
}

void LivePanel::showStatus(const QString& text) { status_->setText(text); }
QString LivePanel::statusText() const { return status_->text(); }
int LivePanel::tearsLeft() const { return left_->value(); }
int LivePanel::tearsRight() const { return right_->value(); }

void LivePanel::setTears(int left, int right) {
  {
    const QSignalBlocker a(left_), b(right_);
    left_->setValue(left);
    right_->setValue(right);
  }
  emit tearsEdited(left_->value(), right_->value());
}

}  // namespace lacrima::player
