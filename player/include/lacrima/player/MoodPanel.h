#pragma once
// The Mood box of the player's side panel (docs/mood.md, docs/player.md): a slider per mood, the
// seed and Randomise, and the crying presets as mood settings. Its edits go to the crying
// generator, which drives the face live; a new level is a target the generator's moods ease
// toward, so the face never jumps.
#include <lacrima/common/mood/Moods.h>

#include <QWidget>

#include <array>
#include <cstdint>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;

namespace lacrima::player {

class MoodPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kSliderSteps = 100;  // a slider's step: 0.01

  explicit MoodPanel(QWidget* parent = nullptr);

  // Shows these without emitting anything (a mood line from a stream, --mood, --seed).
  void display(const MoodLevels& levels, std::uint64_t seed);
  MoodLevels levels() const;
  std::uint64_t seed() const { return seed_; }

  QSlider* slider(Mood mood) const { return sliders_[static_cast<int>(mood)]; }
  QLineEdit* seedField() const { return seedField_; }
  QPushButton* randomise() const { return randomise_; }
  QComboBox* presets() const { return presets_; }

 signals:
  void moodsEdited(const lacrima::MoodLevels& levels);
  void seedEdited(std::uint64_t seed);

 private:
  void showLevels(const MoodLevels& levels);
  void seedTyped();

  std::array<QSlider*, kMoodCount> sliders_{};
  std::array<QLabel*, kMoodCount> values_{};
  QLineEdit* seedField_;
  QPushButton* randomise_;
  QComboBox* presets_;
  std::uint64_t seed_ = 1;
};

}  // namespace lacrima::player
