#include <lacrima/editor/LayerPanel.h>

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/KeyChange.h>
#include <lacrima/editor/MoodLayerRow.h>
#include <lacrima/editor/NumberField.h>

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

namespace lacrima::editor {
namespace {

enum Column { kName, kIntensity, kKeys };

constexpr double kMaxIntensity = 100.0;  // as EditorModel::keyLayerIntensity accepts

}  // namespace

LayerPanel::LayerPanel(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  auto* layout = new QVBoxLayout(this);
  moodLayer_ = new MoodLayerRow(model_, this);
  layout->addWidget(moodLayer_);
  list_ = new QTreeWidget(this);
  list_->setObjectName(QStringLiteral("layerList"));
  list_->setRootIsDecorated(false);
  list_->setHeaderLabels({tr("Layer"), tr("Now"), tr("Keys")});
  list_->header()->setSectionResizeMode(kName, QHeaderView::Stretch);
  list_->setToolTip(
      tr("Presets added as layers mix on top of the keys, each scaled by its "
         "intensity curve. Untick a layer to mute it."));
  layout->addWidget(list_, 1);

  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Intensity at playhead"), this));
  intensity_ = new NumberField(this);
  intensity_->setObjectName(QStringLiteral("layerIntensity"));
  intensity_->setRange({-kMaxIntensity, kMaxIntensity, false, {}});
  intensity_->setDecimals(3);
  intensity_->setSingleStep(0.1);
  intensity_->setSubject(tr("a layer's intensity (1 = the preset's pose, 0 = nothing)"));
  row->addWidget(intensity_, 1);
  key_ = new QPushButton(tr("Key"), this);
  unkey_ = new QPushButton(tr("Remove key"), this);
  row->addWidget(key_);
  row->addWidget(unkey_);
  layout->addLayout(row);
  remove_ = new QPushButton(tr("Delete layer"), this);
  layout->addWidget(remove_);

  connect(&model_, &editing::EditorModel::layersChanged, this, &LayerPanel::rebuild);
  connect(&model_, &editing::EditorModel::documentReset, this, &LayerPanel::rebuild);
  connect(&model_, &editing::EditorModel::timeChanged, this, &LayerPanel::refreshValues);
  connect(list_, &QTreeWidget::currentItemChanged, this, &LayerPanel::refreshValues);
  connect(list_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
    if (rebuilding_ || column != kName) return;
    model_.setLayerMuted(list_->indexOfTopLevelItem(item), item->checkState(kName) != Qt::Checked);
  });
  // Enter, a step or "Key" keys the value; a refused text changes nothing (the field says why).
  connect(intensity_, &NumberField::valueEntered, this,
          [this](double value) { model_.keyLayerIntensity(selectedLayer(), value); });
  connect(key_, &QPushButton::clicked, this, &LayerPanel::keyTypedIntensity);
  connect(unkey_, &QPushButton::clicked, this,
          [this] { model_.unkeyLayerIntensity(selectedLayer()); });
  connect(remove_, &QPushButton::clicked, this, [this] { model_.removeLayer(selectedLayer()); });
  rebuild();
}

int LayerPanel::selectedLayer() const {
  QTreeWidgetItem* item = list_->currentItem();
  return item ? list_->indexOfTopLevelItem(item) : -1;
}

bool LayerPanel::keyTypedIntensity() {
  const int layer = selectedLayer();
  if (layer < 0 || !intensity_->commit()) return false;
  model_.keyLayerIntensity(layer, intensity_->value());
  return true;
}

void LayerPanel::rebuild() {
  const int selected = std::max(0, selectedLayer());
  rebuilding_ = true;
  list_->clear();
  for (const PoseLayer& layer : model_.document().layers) {
    auto* item = new QTreeWidgetItem(list_);
    item->setText(kName, QString::fromStdString(layer.name));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(kName, layer.muted ? Qt::Unchecked : Qt::Checked);
    item->setText(kKeys, QString::number(layer.intensityKeys().size()));
  }
  if (list_->topLevelItemCount() > 0) {
    list_->setCurrentItem(list_->topLevelItem(std::min(selected, list_->topLevelItemCount() - 1)));
  }
  rebuilding_ = false;
  refreshValues();
}

void LayerPanel::refreshValues() {
  const auto& layers = model_.document().layers;
  const double now = model_.currentTime();
  for (int i = 0; i < list_->topLevelItemCount() && i < static_cast<int>(layers.size()); ++i) {
    list_->topLevelItem(i)->setText(
        kIntensity, QString::number(layers[static_cast<std::size_t>(i)].intensityAt(now), 'g', 3));
  }
  const int layer = selectedLayer();
  if (layer >= 0) intensity_->setValue(layers[static_cast<std::size_t>(layer)].intensityAt(now));
  updateButtons();
}

void LayerPanel::updateButtons() {
  const int layer = selectedLayer();
  const bool has = layer >= 0;
  intensity_->setEnabled(has);
  key_->setEnabled(has);
  remove_->setEnabled(has);
  bool keyedNow = false;
  if (has) {
    for (const IntensityKey& key :
         model_.document().layers[static_cast<std::size_t>(layer)].intensityKeys()) {
      keyedNow |= std::abs(key.time - model_.currentTime()) < editing::kSameKeyTime;
    }
  }
  unkey_->setEnabled(keyedNow);
}

}  // namespace lacrima::editor
