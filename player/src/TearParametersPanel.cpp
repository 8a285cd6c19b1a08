#include <lacrima/player/TearParametersPanel.h>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lacrima::player {

namespace {

// "node_size" -> "Node size"
QString label(std::string_view name) {
  QString text =
      QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())).replace('_', ' ');
  text[0] = text[0].toUpper();
  return text;
}

// Enough decimals to show the default with three significant digits (pressure 0.004 needs 6).
int decimalsFor(double value) {
  if (!(value > 0)) return 2;
  return std::clamp(2 - static_cast<int>(std::floor(std::log10(value))), 2, 7);
}

}  // namespace

TearParametersPanel::TearParametersPanel(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout;
  for (const TearParameterInfo& info : tearParameterTable()) {
    auto* box = new QDoubleSpinBox(this);
    const int decimals = decimalsFor(info.defaultValue);
    box->setDecimals(decimals);
    // The smallest step the box can show must stay in range (iso and the lengths are > 0).
    box->setRange(std::max(info.minValue, info.minValue > 0 ? std::pow(10.0, -decimals) : 0.0),
                  info.maxValue);
    box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    box->setValue(info.defaultValue);
    box->setKeyboardTracking(false);
    box->setAccelerated(true);
    box->setToolTip(QStringLiteral("%1\n2009 value: %2; range %3 to %4")
                        .arg(QString::fromUtf8(info.description.data(),
                                               static_cast<qsizetype>(info.description.size())))
                        .arg(info.defaultValue)
                        .arg(info.minValue)
                        .arg(info.maxValue));
    box->setObjectName(
        QString::fromUtf8(info.name.data(), static_cast<qsizetype>(info.name.size())));
    form->addRow(label(info.name), box);
    boxes_.push_back(box);
  }
  thesis_ = new QPushButton(tr("2009 thesis"), this);
  thesis_->setToolTip(tr("The parameters of the 2009 system (the defaults)"));
  file_ = new QPushButton(tr("From the file"), this);
  file_->setToolTip(tr("The parameters the open project sets"));
  auto* presets = new QHBoxLayout;
  presets->addWidget(thesis_);
  presets->addWidget(file_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(presets);

  settle_ = new QTimer(this);
  settle_->setSingleShot(true);
  settle_->setInterval(250);
  connect(settle_, &QTimer::timeout, this, &TearParametersPanel::edited);
  for (QDoubleSpinBox* box : boxes_)
    connect(box, &QDoubleSpinBox::valueChanged, settle_, qOverload<>(&QTimer::start));
  connect(thesis_, &QPushButton::clicked, this, [this] {
    setShown({});
    emit edited();
  });
  connect(file_, &QPushButton::clicked, this, [this] {
    setShown(fileValues_);
    emit edited();
  });
}

void TearParametersPanel::setShown(const TearParameterValues& values) {
  const auto table = tearParameterTable();
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const QSignalBlocker block(boxes_[i]);
    const auto it = values.find(table[i].name);
    boxes_[i]->setValue(it != values.end() ? it->second : table[i].defaultValue);
  }
  settle_->stop();
}

void TearParametersPanel::display(const TearParameterValues& values,
                                  const TearParameterValues& fileValues) {
  fileValues_ = fileValues;
  file_->setEnabled(!fileValues.empty());
  setShown(values);
}

TearParameterValues TearParametersPanel::values() const {
  TearParameterValues values;
  const auto table = tearParameterTable();
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const double shown = boxes_[i]->value();
    // The box rounds to its decimals; a value that rounds to the default is the default.
    const double defaultShown =
        QString::number(table[i].defaultValue, 'f', boxes_[i]->decimals()).toDouble();
    if (shown != defaultShown) values[std::string(table[i].name)] = shown;
  }
  return values;
}

QDoubleSpinBox* TearParametersPanel::spinBox(std::string_view name) const {
  const auto table = tearParameterTable();
  for (std::size_t i = 0; i < boxes_.size(); ++i)
    if (table[i].name == name) return boxes_[i];
  return nullptr;
}

}  // namespace lacrima::player
