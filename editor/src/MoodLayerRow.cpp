#include <lacrima/editor/MoodLayerRow.h>

#include <lacrima/editing/EditorModel.h>

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>

namespace lacrima::editor {

MoodLayerRow::MoodLayerRow(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  enabled_ = new QCheckBox(tr("Crying layer"), this);
  enabled_->setObjectName(QStringLiteral("moodLayerOn"));
  enabled_->setToolTip(tr("Untick to mute the crying layer"));
  range_ = new QLabel(this);
  range_->setObjectName(QStringLiteral("moodLayerRange"));
  grid->addWidget(enabled_, 0, 0);
  grid->addWidget(range_, 0, 1, 1, 3);
  grid->addWidget(new QLabel(tr("Seed"), this), 1, 0);
  seed_ = new QLineEdit(this);
  seed_->setObjectName(QStringLiteral("moodLayerSeed"));
  seed_->setValidator(
      new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[0-9]{1,16}")), this));
  seed_->setToolTip(tr("Another seed, another take of the same moods (Enter)"));
  grid->addWidget(seed_, 1, 1);
  newSeed_ = new QPushButton(tr("New seed"), this);
  grid->addWidget(newSeed_, 1, 2);
  bake_ = new QPushButton(tr("Bake to keys"), this);
  bake_->setToolTip(tr("Write what the layer adds into keys and remove the layer"));
  remove_ = new QPushButton(tr("Delete"), this);
  grid->addWidget(bake_, 2, 1);
  grid->addWidget(remove_, 2, 2);

  connect(enabled_, &QCheckBox::toggled, this, [this](bool on) { model_.setMoodLayerMuted(!on); });
  connect(seed_, &QLineEdit::returnPressed, this, &MoodLayerRow::applyTypedSeed);
  connect(newSeed_, &QPushButton::clicked, this, [this] {
    const auto& layer = model_.document().moodLayer;
    if (layer) model_.setMoodLayerSeed(layer->seed < MoodLayer::kMaxSeed ? layer->seed + 1 : 0);
  });
  connect(bake_, &QPushButton::clicked, this, [this] { model_.bakeMoodLayer(); });
  connect(remove_, &QPushButton::clicked, this, [this] { model_.removeMoodLayer(); });
  connect(&model_, &editing::EditorModel::moodLayerChanged, this, &MoodLayerRow::refresh);
  connect(&model_, &editing::EditorModel::documentReset, this, &MoodLayerRow::refresh);
  refresh();
}

void MoodLayerRow::applyTypedSeed() {
  bool ok = false;
  const qulonglong seed = seed_->text().toULongLong(&ok);
  if (ok) model_.setMoodLayerSeed(seed);
  refresh();  // a refused seed shows the layer's again
}

void MoodLayerRow::refresh() {
  const auto& layer = model_.document().moodLayer;
  setVisible(layer.has_value());
  if (!layer) return;
  const QSignalBlocker quiet(enabled_);
  enabled_->setChecked(!layer->muted);
  range_->setText(tr("%1 s to %2 s, following the mood curves").arg(layer->start).arg(layer->end));
  seed_->setText(QString::number(layer->seed));
  bake_->setEnabled(!layer->muted);
}

}  // namespace lacrima::editor
