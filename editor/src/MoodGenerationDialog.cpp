#include <lacrima/editor/MoodGenerationDialog.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include <algorithm>
#include <stdexcept>

namespace lacrima::editor {

namespace {

QString displayName(std::string_view name) {
  QString text = QString::fromUtf8(name.data(), static_cast<int>(name.size()));
  text[0] = text[0].toUpper();
  return text;
}

QDoubleSpinBox* secondsBox(double value, QWidget* parent) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(0, MoodScript::kMaxTime);
  box->setDecimals(2);
  box->setSingleStep(0.5);
  box->setSuffix(QStringLiteral(" s"));
  box->setValue(value);
  return box;
}

}  // namespace

MoodGenerationDialog::MoodGenerationDialog(double start, double end, double fps,
                                           const MoodCurves* curves, QWidget* parent)
    : QDialog(parent), curves_(curves), fps_(fps) {
  setWindowTitle(tr("Generate crying"));
  auto* column = new QVBoxLayout(this);
  auto* intro = new QLabel(
      tr("The crying generator writes a take over the range as keys on the channels it moves "
         "(face, tears and all), or adds it as a layer that follows the mood curves and stays "
         "editable. One undo step."),
      this);
  intro->setWordWrap(true);
  column->addWidget(intro);
  auto* form = new QFormLayout;
  source_ = new QComboBox(this);
  source_->setObjectName(QStringLiteral("moodSource"));
  source_->addItem(tr("Constant moods"));
  source_->addItem(tr("The project's mood curves"));
  const bool keyed = curves_ && !curves_->empty();
  if (!keyed) {
    // Offered only when there is something to follow; the tooltip says how to get there.
    qobject_cast<QStandardItemModel*>(source_->model())->item(1)->setEnabled(false);
  }
  source_->setToolTip(keyed ? tr("Follow the mood curves keyed in the graph editor (Moods)")
                            : tr("Key moods in the graph editor (Moods) to generate from them"));
  form->addRow(tr("Moods"), source_);
  output_ = new QComboBox(this);
  output_->setObjectName(QStringLiteral("moodOutput"));
  output_->addItem(tr("Keys"));
  output_->addItem(tr("A procedural layer"));
  output_->setToolTip(
      tr("A layer is generated as it plays, from the mood curves: edit them in the graph "
         "editor (Moods) and the face follows; mute, re-seed or bake it in the Layers panel. "
         "Constant moods are keyed as mood curves over the range."));
  form->addRow(tr("Output"), output_);
  presets_ = new QComboBox(this);
  presets_->addItem(tr("Moods of your own"));
  for (const MoodPreset& preset : moodPresets()) presets_->addItem(displayName(preset.name));
  form->addRow(tr("Crying preset"), presets_);
  for (Mood mood : kMoods) {
    auto* box = new QDoubleSpinBox(this);
    box->setObjectName(QStringLiteral("mood.") + displayName(moodName(mood)).toLower());
    box->setRange(0, 1);
    box->setDecimals(2);
    box->setSingleStep(0.05);
    levels_[static_cast<std::size_t>(mood)] = box;
    form->addRow(displayName(moodName(mood)), box);
  }
  levels_[static_cast<std::size_t>(Mood::Sadness)]->setValue(0.8);
  connect(presets_, &QComboBox::activated, this, [this](int index) {
    if (index < 1) return;
    const MoodLevels& levels = moodPresets()[static_cast<std::size_t>(index - 1)].levels;
    for (Mood mood : kMoods) levels_[static_cast<std::size_t>(mood)]->setValue(levels[mood]);
  });
  seed_ = new QLineEdit(QStringLiteral("1"), this);
  seed_->setValidator(
      new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[0-9]{1,20}")), this));
  seed_->setToolTip(tr("The same moods and seed give the same take; another seed another one"));
  form->addRow(tr("Seed"), seed_);
  start_ = secondsBox(start, this);
  end_ = secondsBox(end, this);
  form->addRow(tr("From"), start_);
  form->addRow(tr("To"), end_);
  ease_ = secondsBox(1, this);
  ease_->setRange(0, 60);
  ease_->setToolTip(tr("The moods rise from neutral over this long at the start of the range"));
  form->addRow(tr("Ease in"), ease_);
  column->addLayout(form);
  const auto showSource = [this] {
    // The constant moods' fields mean nothing while the curves drive the take.
    const bool constant = source_->currentIndex() == 0;
    presets_->setEnabled(constant);
    ease_->setEnabled(constant);
    for (QDoubleSpinBox* box : levels_) box->setEnabled(constant);
  };
  connect(source_, &QComboBox::currentIndexChanged, this, showSource);
  problem_ = new QLabel(this);
  problem_->setObjectName("problem");
  problem_->setWordWrap(true);
  problem_->setStyleSheet(QStringLiteral("color: #e04040"));
  column->addWidget(problem_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Generate"));
  connect(output_, &QComboBox::currentIndexChanged, this, [this, buttons](int index) {
    buttons->button(QDialogButtonBox::Ok)->setText(index == 1 ? tr("Add layer") : tr("Generate"));
  });
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    try {
      request();
      accept();
    } catch (const std::invalid_argument& e) {
      problem_->setText(QString::fromUtf8(e.what()));
    }
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  column->addWidget(buttons);
}

bool MoodGenerationDialog::asLayer() const { return output_->currentIndex() == 1; }

editing::MoodGenerationRequest MoodGenerationDialog::request() const {
  editing::MoodGenerationRequest request;
  request.start = start_->value();
  request.end = end_->value();
  if (!(request.end > request.start))
    throw std::invalid_argument("To: expected a time after From (" + std::to_string(request.start) +
                                " s)");
  bool ok = false;
  request.seed = seed_->text().toULongLong(&ok);
  if (!ok)
    throw std::invalid_argument("Seed: expected a whole number from 0 to 18446744073709551615");
  MoodLevels levels;
  for (Mood mood : kMoods) levels[mood] = levels_[static_cast<std::size_t>(mood)]->value();
  const double ease = std::min(ease_->value(), request.end - request.start);
  request.script =
      ease > 0 ? MoodScript({MoodKey{0, {}}, MoodKey{ease, levels}}) : MoodScript::constant(levels);
  request.fps = fps_;
  if (source_->currentIndex() == 1) {
    if (!curves_ || curves_->empty())
      throw std::invalid_argument("Moods: the project keys no moods (graph editor, Moods)");
    request.curves = curves_;
  }
  return request;
}

}  // namespace lacrima::editor
