#include <lacrima/playback/TearQualityOptions.h>
#include <lacrima/tears/TearMethods.h>
#include <lacrima/viewport/EffectsPanel.h>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include <optional>
#include <string>

namespace lacrima::viewport {

namespace {

QCheckBox* toggle(const QString& text, const QString& tip, QWidget* parent) {
  auto* box = new QCheckBox(text, parent);
  box->setToolTip(tip);
  // Clicking must not steal the keyboard focus: Space stays Play/Pause.
  box->setFocusPolicy(Qt::TabFocus);
  return box;
}

QComboBox* combo(const QStringList& items, const QString& tip, QWidget* parent) {
  auto* box = new QComboBox(parent);
  box->addItems(items);
  box->setToolTip(tip);
  box->setFocusPolicy(Qt::TabFocus);
  return box;
}

QString fromUtf8(const std::string& text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// An advanced choice: item 0 is the level's own, then the family's registered methods, each
// with its key as the item's data and its summary as the item's tooltip.
QComboBox* methodCombo(tears::MethodFamily family, const QString& tip, QWidget* parent) {
  QComboBox* box = combo({EffectsPanel::tr("as the level")}, tip, parent);
  for (const tears::MethodInfo& method : tears::registeredMethods(family)) {
    box->addItem(fromUtf8(method.label), fromUtf8(method.key));
    box->setItemData(box->count() - 1, fromUtf8(method.summary), Qt::ToolTipRole);
  }
  return box;
}

void showChoice(QComboBox* box, const std::optional<std::string>& key) {
  if (!key) {
    box->setCurrentIndex(0);
    return;
  }
  int index = box->findData(fromUtf8(*key));
  if (index < 0) {  // not registered in this build: shown and kept as written
    box->addItem(fromUtf8(*key), fromUtf8(*key));
    index = box->count() - 1;
  }
  box->setCurrentIndex(index);
}

std::optional<std::string> choiceOf(const QComboBox* box) {
  if (box->currentIndex() <= 0) return std::nullopt;
  return box->currentData().toString().toStdString();
}

}  // namespace

EffectsPanel::EffectsPanel(QWidget* parent) : QWidget(parent) {
  particles_ =
      toggle(tr("Particles"), tr("Draw every tear particle as a small sphere (inspection)"), this);
  surface_ = toggle(tr("Tear surface"),
                    tr("The tears' liquid surface (marching cubes over the particles)"), this);
  trails_ = toggle(tr("Wet trails"),
                   tr("The thin wet film tears leave on the skin; dries over seconds"), this);
  textureBlending_ = toggle(tr("Texture blending"),
                            tr("Red, darker skin around the eyes, watery eyes, blush"), this);
  blush_ = toggle(tr("Blush"), tr("Cheeks redden with the eyes"), this);
  redness_ = new QComboBox(this);
  redness_->addItem(tr("rises over the animation (2009)"));
  redness_->addItem(tr("follows the tears shed"));
  redness_->setToolTip(tr("What the redness around the eyes follows"));
  redness_->setFocusPolicy(Qt::TabFocus);

  buildQuality();

  auto* layout = new QVBoxLayout(this);
  for (QCheckBox* box : {particles_, surface_, trails_, textureBlending_, blush_}) {
    layout->addWidget(box);
    connect(box, &QCheckBox::toggled, this, &EffectsPanel::edited);
  }
  auto* form = new QFormLayout;
  form->addRow(tr("Eye redness"), redness_);
  auto* qualityRow = new QHBoxLayout;
  qualityRow->addWidget(quality_);
  qualityRow->addWidget(advanced_);
  form->addRow(tr("Tear quality"), qualityRow);
  form->addRow(tr("Cost"), cost_);
  layout->addLayout(form);
  layout->addWidget(advancedBox_);
  connect(redness_, &QComboBox::currentIndexChanged, this, &EffectsPanel::edited);
  for (QComboBox* box : {quality_, solver_, tension_, neighbours_}) {
    connect(box, &QComboBox::currentIndexChanged, this, [this] {
      clearCost();  // the frames measured were of the old choice
      emit edited();
    });
  }
  showCost();
  connect(textureBlending_, &QCheckBox::toggled, this, [this](bool on) {
    blush_->setEnabled(on);
    redness_->setEnabled(on);
  });
}

// The quality combo (each level's summary as its item tooltip), the cost label and the
// Advanced section, hidden until asked for.
void EffectsPanel::buildQuality() {
  quality_ = new QComboBox(this);
  for (TearQuality level : {TearQuality::Preview, TearQuality::Balanced, TearQuality::Reference}) {
    const playback::TearQualityLevel& info = playback::tearQualityLevel(level);
    quality_->addItem(QString::fromUtf8(info.label.data(), static_cast<int>(info.label.size())));
    quality_->setItemData(
        quality_->count() - 1,
        QString::fromUtf8(info.summary.data(), static_cast<int>(info.summary.size())),
        Qt::ToolTipRole);
  }
  quality_->setToolTip(tr("How accurately the tears are simulated; changing it restarts them"));
  quality_->setFocusPolicy(Qt::TabFocus);
  cost_ = new QLabel(this);
  cost_->setToolTip(
      tr("Tear simulation, surface and trails per frame, and the simulation's "
         "sub-steps per frame: the mean of the last frames with tears"));
  advanced_ = new QToolButton(this);
  advanced_->setText(tr("Advanced"));
  advanced_->setCheckable(true);
  advanced_->setToolTip(tr("Choose the solver, surface tension and neighbour search yourself"));
  advanced_->setFocusPolicy(Qt::TabFocus);
  solver_ = methodCombo(tears::MethodFamily::PressureSolver,
                        tr("What keeps the tears from compressing; each method's tooltip says "
                           "what it trades"),
                        this);
  tension_ = methodCombo(tears::MethodFamily::SurfaceTension,
                         tr("What keeps drops round and trails thin"), this);
  neighbours_ = methodCombo(tears::MethodFamily::NeighbourStructure,
                            tr("Where the pairs of neighbouring particles come from"), this);
  advancedBox_ = new QWidget(this);
  auto* advancedForm = new QFormLayout(advancedBox_);
  advancedForm->setContentsMargins(0, 0, 0, 0);
  advancedForm->addRow(tr("Solver"), solver_);
  advancedForm->addRow(tr("Surface tension"), tension_);
  advancedForm->addRow(tr("Neighbours"), neighbours_);
  advancedBox_->setVisible(false);
  connect(advanced_, &QToolButton::toggled, advancedBox_, &QWidget::setVisible);
}

void EffectsPanel::display(const SceneSettings& scene) {
  const QSignalBlocker blocks[] = {QSignalBlocker(particles_), QSignalBlocker(surface_),
                                   QSignalBlocker(trails_),    QSignalBlocker(textureBlending_),
                                   QSignalBlocker(blush_),     QSignalBlocker(redness_),
                                   QSignalBlocker(quality_),   QSignalBlocker(solver_),
                                   QSignalBlocker(tension_),   QSignalBlocker(neighbours_)};
  particles_->setChecked(scene.particles);
  surface_->setChecked(scene.surface);
  trails_->setChecked(scene.trails);
  textureBlending_->setChecked(scene.textureBlending);
  blush_->setChecked(scene.blush);
  redness_->setCurrentIndex(scene.redness == SceneSettings::Redness::Animation ? 0 : 1);
  blush_->setEnabled(scene.textureBlending);
  redness_->setEnabled(scene.textureBlending);
  SceneSettings shown;
  applyTo(shown);
  if (shown.quality != scene.quality) clearCost();  // the frames measured were of another choice
  quality_->setCurrentIndex(static_cast<int>(scene.quality.level));
  showChoice(solver_, scene.quality.solver);
  showChoice(tension_, scene.quality.tension);
  showChoice(neighbours_, scene.quality.neighbours);
  // A project with explicit choices shows them.
  if (scene.quality.solver || scene.quality.tension || scene.quality.neighbours)
    advanced_->setChecked(true);
}

void EffectsPanel::applyTo(SceneSettings& scene) const {
  scene.particles = particles_->isChecked();
  scene.surface = surface_->isChecked();
  scene.trails = trails_->isChecked();
  scene.textureBlending = textureBlending_->isChecked();
  scene.blush = blush_->isChecked();
  scene.redness = redness_->currentIndex() == 0 ? SceneSettings::Redness::Animation
                                                : SceneSettings::Redness::Tears;
  scene.quality.level = static_cast<TearQuality>(quality_->currentIndex());
  scene.quality.solver = choiceOf(solver_);
  scene.quality.tension = choiceOf(tension_);
  scene.quality.neighbours = choiceOf(neighbours_);
}

void EffectsPanel::addFrameCost(double milliseconds, long long substeps) {
  if (substeps <= 0) return;
  costs_.push_back({milliseconds, substeps});
  while (costs_.size() > static_cast<std::size_t>(kCostFrames)) costs_.pop_front();
  showCost();
}

void EffectsPanel::clearCost() {
  costs_.clear();
  showCost();
}

void EffectsPanel::showCost() {
  if (costs_.empty()) {
    // Frames are measured as they play, not as a seek replays them: tears on screen after a
    // seek or a quality change have no cost to show yet.
    cost_->setText(tr("measured while tears play"));
    return;
  }
  double milliseconds = 0, substeps = 0;
  for (const FrameCost& c : costs_) {
    milliseconds += c.milliseconds;
    substeps += static_cast<double>(c.substeps);
  }
  const double n = static_cast<double>(costs_.size());
  cost_->setText(tr("%1 ms per frame, %2 sub-steps")
                     .arg(milliseconds / n, 0, 'f', 1)
                     .arg(substeps / n, 0, 'f', 0));
}

}  // namespace lacrima::viewport
