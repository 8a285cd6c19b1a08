#pragma once
// The effect toggles: particle spheres, tear surface, wet trails, texture blending, blush, and
// what the eye redness follows. Shows and edits the non-simulation part of a SceneSettings;
// none of these restarts the tears. The player shows it beside the face, the editor in its
// project settings, so both name and explain the effects the same way.
#include <lacrima/common/ProjectDocument.h>

#include <QWidget>

class QCheckBox;
class QComboBox;

namespace lacrima::viewport {

class EffectsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit EffectsPanel(QWidget* parent = nullptr);

  void display(const SceneSettings& scene);  // without emitting edited()
  void applyTo(SceneSettings& scene) const;  // the toggles' state, simulation untouched

  QCheckBox* particles() const { return particles_; }
  QCheckBox* surface() const { return surface_; }
  QCheckBox* trails() const { return trails_; }
  QCheckBox* textureBlending() const { return textureBlending_; }
  QCheckBox* blush() const { return blush_; }
  QComboBox* redness() const { return redness_; }

 signals:
  void edited();

 private:
  QCheckBox *particles_, *surface_, *trails_, *textureBlending_, *blush_;
  QComboBox* redness_;
};

}  // namespace lacrima::viewport
