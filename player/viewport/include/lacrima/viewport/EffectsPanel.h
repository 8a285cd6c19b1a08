#pragma once
// The effect toggles: particle spheres, tear surface, wet trails, texture blending, blush, and
// what the eye redness follows; and the tears' quality (Preview / Balanced / Reference, with an
// Advanced section for the solver, surface tension and neighbour structure) with its cost of the
// last frames beside it. Shows and edits SceneSettings but for the tear parameters; a toggle
// never restarts the tears, a quality change does (FrameProducer). The player shows it beside
// the face, the editor in its project settings, so both name and explain them the same way.
#include <lacrima/common/ProjectDocument.h>

#include <QWidget>

#include <deque>

class QCheckBox;
class QComboBox;
class QLabel;
class QToolButton;

namespace lacrima::viewport {

class EffectsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit EffectsPanel(QWidget* parent = nullptr);

  void display(const SceneSettings& scene);  // without emitting edited()
  // The toggles' and the quality's state; the tear parameters (scene.simulation) untouched.
  void applyTo(SceneSettings& scene) const;

  // One frame's tear cost (ProducerTimes: simulation + surface + trails ms, sub-steps); the
  // label shows the mean of the last kCostFrames frames that simulated tears. Frames without
  // tears (0 sub-steps) leave it as it is. clearCost() forgets them (the quality changed).
  static constexpr int kCostFrames = 22;
  void addFrameCost(double milliseconds, long long substeps);
  void clearCost();

  QCheckBox* particles() const { return particles_; }
  QCheckBox* surface() const { return surface_; }
  QCheckBox* trails() const { return trails_; }
  QCheckBox* textureBlending() const { return textureBlending_; }
  QCheckBox* blush() const { return blush_; }
  QComboBox* redness() const { return redness_; }
  QComboBox* quality() const { return quality_; }  // in TearQuality order
  // Advanced: item 0 keeps the level's choice, then the enum's values in order.
  QComboBox* solver() const { return solver_; }
  QComboBox* tension() const { return tension_; }
  QComboBox* neighbours() const { return neighbours_; }
  QToolButton* advanced() const { return advanced_; }  // shows or hides those three
  QLabel* cost() const { return cost_; }

 signals:
  void edited();

 private:
  void buildQuality();
  void showCost();

  QCheckBox *particles_, *surface_, *trails_, *textureBlending_, *blush_;
  QComboBox* redness_;
  QComboBox *quality_, *solver_, *tension_, *neighbours_;
  QToolButton* advanced_;
  QWidget* advancedBox_;
  QLabel* cost_;
  struct FrameCost {
    double milliseconds;
    long long substeps;
  };
  std::deque<FrameCost> costs_;  // the last kCostFrames frames with tears
};

}  // namespace lacrima::viewport
