#include <lacrima/player/MoodPanel.h>

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRandomGenerator>
#include <QRegularExpressionValidator>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <cmath>

namespace lacrima::player {

namespace {

QString moodLabel(Mood mood) {
  QString name =
      QString::fromLatin1(moodName(mood).data(), static_cast<int>(moodName(mood).size()));
  name[0] = name[0].toUpper();
  return name;
}

}  // namespace

MoodPanel::MoodPanel(QWidget* parent) : QWidget(parent) {
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(0, 0, 0, 0);
  presets_ = new QComboBox(this);
  presets_->setObjectName("moodPresets");
  presets_->addItem(tr("Crying preset..."));
  for (const MoodPreset& preset : moodPresets())
    presets_->addItem(QString::fromUtf8(preset.name.data(), static_cast<int>(preset.name.size())));
  presets_->setToolTip(tr("The crying presets as moods: the generator cries that way"));
  connect(presets_, &QComboBox::activated, this, [this](int index) {
    if (index < 1) return;
    const MoodLevels levels = moodPresets()[static_cast<std::size_t>(index - 1)].levels;
    showLevels(levels);
    {
      const QSignalBlocker block(presets_);
      presets_->setCurrentIndex(0);
    }
    emit moodsEdited(levels);
  });
  column->addWidget(presets_);
  auto* form = new QFormLayout;
  for (Mood mood : kMoods) {
    const auto m = static_cast<std::size_t>(mood);
    auto* slider = new QSlider(Qt::Horizontal, this);
    slider->setObjectName(QStringLiteral("mood.") + moodLabel(mood).toLower());
    slider->setRange(0, kSliderSteps);
    slider->setPageStep(10);
    slider->setToolTip(tr("%1, from 0 to 1: the face eases toward it").arg(moodLabel(mood)));
    auto* value = new QLabel(QStringLiteral("0.00"), this);
    value->setMinimumWidth(value->fontMetrics().horizontalAdvance(QStringLiteral("0.00")) + 4);
    auto* row = new QHBoxLayout;
    row->addWidget(slider, 1);
    row->addWidget(value);
    form->addRow(moodLabel(mood), row);
    sliders_[m] = slider;
    values_[m] = value;
    connect(slider, &QSlider::valueChanged, this, [this, m](int v) {
      values_[m]->setText(QString::number(v / double(kSliderSteps), 'f', 2));
      emit moodsEdited(levels());
    });
  }
  seedField_ = new QLineEdit(QStringLiteral("1"), this);
  seedField_->setObjectName("moodSeed");
  seedField_->setValidator(
      new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[0-9]{1,20}")), this));
  seedField_->setToolTip(tr("The take's seed: the same moods and seed give the same take"));
  connect(seedField_, &QLineEdit::editingFinished, this, &MoodPanel::seedTyped);
  randomise_ = new QPushButton(tr("Randomise"), this);
  randomise_->setToolTip(tr("Another take: a new seed (the tears well again)"));
  connect(randomise_, &QPushButton::clicked, this, [this] {
    seed_ = QRandomGenerator::global()->generate64();
    seedField_->setText(QString::number(seed_));
    emit seedEdited(seed_);
  });
  auto* seedRow = new QHBoxLayout;
  seedRow->addWidget(seedField_, 1);
  seedRow->addWidget(randomise_);
  form->addRow(tr("Seed"), seedRow);
  column->addLayout(form);
}

void MoodPanel::seedTyped() {
  bool ok = false;
  const std::uint64_t seed = seedField_->text().toULongLong(&ok);
  if (!ok) {  // more than 2^64 - 1: show the seed in use again
    seedField_->setText(QString::number(seed_));
    return;
  }
  if (seed == seed_) return;
  seed_ = seed;
  emit seedEdited(seed_);
}

void MoodPanel::showLevels(const MoodLevels& levels) {
  for (Mood mood : kMoods) {
    const auto m = static_cast<std::size_t>(mood);
    const QSignalBlocker block(sliders_[m]);
    sliders_[m]->setValue(static_cast<int>(std::lround(levels[mood] * kSliderSteps)));
    values_[m]->setText(QString::number(levels[mood], 'f', 2));
  }
}

void MoodPanel::display(const MoodLevels& levels, std::uint64_t seed) {
  showLevels(levels);
  seed_ = seed;
  seedField_->setText(QString::number(seed));
}

MoodLevels MoodPanel::levels() const {
  MoodLevels levels;
  for (Mood mood : kMoods)
    levels[mood] = sliders_[static_cast<std::size_t>(mood)]->value() / double(kSliderSteps);
  return levels;
}

}  // namespace lacrima::player
