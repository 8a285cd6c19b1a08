#include <lacrima/playback/TearQualityOptions.h>
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

// An advanced choice: item 0 is the level's own, then the enum's values in order.
template <typename Enum>
void showChoice(QComboBox* box, const std::optional<Enum>& choice) {
  box->setCurrentIndex(choice ? static_cast<int>(*choice) + 1 : 0);
}

template <typename Enum>
std::optional<Enum> choiceOf(const QComboBox* box) {
  if (box->currentIndex() <= 0) return std::nullopt;
  return static_cast<Enum>(box->currentIndex() - 1);
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
  const QString level = tr("as the level");
  solver_ = combo({level, tr("WCSPH"), tr("DFSPH"), tr("PBF")},
                  tr("Pressure: weakly compressible SPH (2009, the levels' own), "
                     "divergence-free SPH (drops cling harder; about twice the cost per "
                     "sub-step) or position-based fluids (density constraints, a fixed number "
                     "of iterations per sub-step)"),
                  this);
  tension_ = combo({level, tr("Müller"), tr("Akinci")},
                   tr("Surface tension: the colour-field curvature of Müller et al. 2003 (the "
                      "levels' own) or the cohesion and curvature of Akinci et al. 2013"),
                   this);
  neighbours_ = combo({level, tr("grid"), tr("octree")},
                      tr("Neighbour search: Verlet lists on a grid (the levels' own, faster) or "
                         "the 2009 octree (same pairs, slower; for comparison)"),
                      this);
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
  scene.quality.solver = choiceOf<TearSolver>(solver_);
  scene.quality.tension = choiceOf<TearTension>(tension_);
  scene.quality.neighbours = choiceOf<TearNeighbours>(neighbours_);
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
    cost_->setText(tr("no tears simulated yet"));
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
