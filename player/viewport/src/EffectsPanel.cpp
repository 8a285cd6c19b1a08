#include <lacrima/viewport/EffectsPanel.h>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace lacrima::viewport {

namespace {

QCheckBox* toggle(const QString& text, const QString& tip, QWidget* parent) {
  auto* box = new QCheckBox(text, parent);
  box->setToolTip(tip);
  // Clicking must not steal the keyboard focus: Space stays Play/Pause.
  box->setFocusPolicy(Qt::TabFocus);
  return box;
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

  auto* layout = new QVBoxLayout(this);
  for (QCheckBox* box : {particles_, surface_, trails_, textureBlending_, blush_}) {
    layout->addWidget(box);
    connect(box, &QCheckBox::toggled, this, &EffectsPanel::edited);
  }
  auto* form = new QFormLayout;
  form->addRow(tr("Eye redness"), redness_);
  layout->addLayout(form);
  connect(redness_, &QComboBox::currentIndexChanged, this, &EffectsPanel::edited);
  connect(textureBlending_, &QCheckBox::toggled, this, [this](bool on) {
    blush_->setEnabled(on);
    redness_->setEnabled(on);
  });
}

void EffectsPanel::display(const SceneSettings& scene) {
  const QSignalBlocker blocks[] = {QSignalBlocker(particles_), QSignalBlocker(surface_),
                                   QSignalBlocker(trails_),    QSignalBlocker(textureBlending_),
                                   QSignalBlocker(blush_),     QSignalBlocker(redness_)};
  particles_->setChecked(scene.particles);
  surface_->setChecked(scene.surface);
  trails_->setChecked(scene.trails);
  textureBlending_->setChecked(scene.textureBlending);
  blush_->setChecked(scene.blush);
  redness_->setCurrentIndex(scene.redness == SceneSettings::Redness::Animation ? 0 : 1);
  blush_->setEnabled(scene.textureBlending);
  redness_->setEnabled(scene.textureBlending);
}

void EffectsPanel::applyTo(SceneSettings& scene) const {
  scene.particles = particles_->isChecked();
  scene.surface = surface_->isChecked();
  scene.trails = trails_->isChecked();
  scene.textureBlending = textureBlending_->isChecked();
  scene.blush = blush_->isChecked();
  scene.redness = redness_->currentIndex() == 0 ? SceneSettings::Redness::Animation
                                                : SceneSettings::Redness::Tears;
}

}  // namespace lacrima::viewport
