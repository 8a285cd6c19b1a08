#include <lacrima/editor/PresetPanel.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/NumberField.h>

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace lacrima::editor {

PresetPanel::PresetPanel(editing::EditorModel& model, editing::PresetLibrary library,
                         QWidget* parent)
    : QWidget(parent), model_(model), library_(std::move(library)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  layout->setSpacing(6);

  list_ = new QTreeWidget(this);
  list_->setObjectName(QStringLiteral("presetList"));
  list_->setHeaderHidden(true);
  list_->setRootIsDecorated(false);
  list_->setIndentation(10);
  list_->setUniformRowHeights(true);
  layout->addWidget(list_, 1);

  details_ = new QLabel(this);
  details_->setWordWrap(true);
  details_->setMinimumHeight(34);
  details_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  QPalette dim = details_->palette();
  dim.setColor(QPalette::WindowText, dim.color(QPalette::WindowText).darker(125));
  details_->setPalette(dim);
  layout->addWidget(details_);

  auto* strength = new QHBoxLayout;
  strength->addWidget(new QLabel(tr("Intensity"), this));
  intensity_ = new QSlider(Qt::Horizontal, this);
  intensity_->setRange(0, 150);
  intensity_->setValue(100);
  intensity_->setToolTip(tr("Scales the preset's values (tear counts too)"));
  intensityField_ = new NumberField(this);
  intensityField_->setObjectName(QStringLiteral("intensity"));
  intensityField_->setRange({0, 150, true, QStringLiteral("%")});
  intensityField_->setSubject(tr("the intensity"));
  intensityField_->setValue(100);
  intensityField_->setSingleStep(5);
  intensityField_->setMinimumWidth(64);
  intensityField_->setToolTip(intensity_->toolTip());
  strength->addWidget(intensity_, 1);
  strength->addWidget(intensityField_);
  layout->addLayout(strength);

  replace_ = new QCheckBox(tr("Replace the current pose"), this);
  replace_->setChecked(true);
  replace_->setToolTip(
      tr("Channels the preset does not set go back to 0 at this time; off: the preset is added on "
         "top"));
  layout->addWidget(replace_);
  asLayer_ = new QCheckBox(tr("As a layer"), this);
  asLayer_->setObjectName(QStringLiteral("presetAsLayer"));
  asLayer_->setToolTip(
      tr("Add the pose as a layer with its own intensity over time, mixed on top of the keys "
         "(see the Layers panel); off: write it into the keys"));
  layout->addWidget(asLayer_);

  auto* buttons = new QHBoxLayout;
  apply_ = new QPushButton(tr("Apply at playhead"), this);
  apply_->setObjectName(QStringLiteral("applyPreset"));
  apply_->setDefault(true);
  auto* mirror = new QPushButton(tr("Mirror L ↔ R"), this);
  mirror->setToolTip(
      tr("Mirror the selected keys, or the pose at the playhead, left to right (Ctrl+M)"));
  auto* load = new QToolButton(this);
  load->setText(QStringLiteral("…"));
  load->setToolTip(tr("Load another presets file"));
  buttons->addWidget(apply_, 1);
  buttons->addWidget(mirror);
  buttons->addWidget(load);
  layout->addLayout(buttons);

  // The slider and the field show one value; either sets it.
  connect(intensity_, &QSlider::valueChanged, intensityField_, &NumberField::setValue);
  connect(intensityField_, &NumberField::valueEntered, intensity_,
          [this](double v) { intensity_->setValue(static_cast<int>(v)); });
  connect(list_, &QTreeWidget::currentItemChanged, this, &PresetPanel::showDetails);
  connect(list_, &QTreeWidget::itemDoubleClicked, this, [this] { apply(selectedId()); });
  connect(apply_, &QPushButton::clicked, this, [this] { apply(selectedId()); });
  connect(mirror, &QPushButton::clicked, &model_, &editing::EditorModel::mirror);
  connect(asLayer_, &QCheckBox::toggled, this, [this](bool layered) {
    replace_->setEnabled(!layered);  // a layer adds; it never replaces the keys' pose
    apply_->setText(layered ? tr("Add layer at playhead") : tr("Apply at playhead"));
  });
  connect(load, &QToolButton::clicked, this, &PresetPanel::loadRequested);
  rebuild();
}

void PresetPanel::setLibrary(editing::PresetLibrary library, const QString& source) {
  library_ = std::move(library);
  source_ = source;
  rebuild();
}

double PresetPanel::intensity() const { return intensity_->value() / 100.0; }
bool PresetPanel::replacesPose() const { return replace_->isChecked(); }
bool PresetPanel::asLayer() const { return asLayer_->isChecked(); }
void PresetPanel::setAsLayer(bool layered) { asLayer_->setChecked(layered); }

bool PresetPanel::apply(const QString& id) {
  const editing::Preset* preset = library_.find(id.toStdString());
  if (!preset) return false;
  if (asLayer()) {
    model_.applyPresetAsLayer(*preset, intensity());
  } else {
    model_.applyPreset(*preset, intensity(), replacesPose());
  }
  return true;
}

QString PresetPanel::selectedId() const {
  const QTreeWidgetItem* item = list_->currentItem();
  return item ? item->data(0, Qt::UserRole).toString() : QString();
}

void PresetPanel::rebuild() {
  list_->clear();
  QFont bold = list_->font();
  bold.setBold(true);
  for (const std::string& category : library_.categories()) {
    auto* heading = new QTreeWidgetItem(list_, {QString::fromStdString(category)});
    heading->setFlags(Qt::ItemIsEnabled);
    heading->setFont(0, bold);
    for (const editing::Preset& preset : library_.presets()) {
      if (preset.category != category) continue;
      QString label = QString::fromStdString(preset.name);
      if (preset.isSequence())
        label += tr("   (%1 keys, %2 s)").arg(preset.keys.size()).arg(preset.duration(), 0, 'f', 1);
      auto* item = new QTreeWidgetItem(heading, {label});
      item->setData(0, Qt::UserRole, QString::fromStdString(preset.id));
      item->setToolTip(0, QString::fromStdString(preset.description));
      if (preset.keys.front().has(kTearLeftFap) && preset.keys.front().value(kTearLeftFap) > 0)
        item->setForeground(0, theme::tearBlue());
    }
    heading->setExpanded(true);
  }
  // Start on the first preset, so Apply works at once.
  if (list_->topLevelItemCount() > 0 && list_->topLevelItem(0)->childCount() > 0)
    list_->setCurrentItem(list_->topLevelItem(0)->child(0));
  showDetails();
}

void PresetPanel::showDetails() {
  const editing::Preset* preset = library_.find(selectedId().toStdString());
  apply_->setEnabled(preset != nullptr);
  if (!preset) {
    details_->setText(
        tr("Pick a preset, then Apply (or double-click it). It lands at the playhead."));
    return;
  }
  int channels = 0;
  for (int fap = 1; fap <= kChannelCount; ++fap) channels += preset->keys.front().has(fap) ? 1 : 0;
  details_->setText(QString::fromStdString(preset->description) +
                    tr("  <i>(%n channels)</i>", nullptr, channels));
}

}  // namespace lacrima::editor
