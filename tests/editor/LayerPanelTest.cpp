// Presets as layers through the widgets: the preset panel's "As a layer", the Layers panel's
// list, mute box, typed intensity keys (refused text changes nothing) and delete, all undoable.
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/PresetLibrary.h>
#include <lacrima/editor/LayerPanel.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/PresetPanel.h>

#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QTreeWidget>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::editor;

namespace {

constexpr int kLiftLeftCheek = 41;  // 160 in Joy

void typeInto(NumberField* field, const QString& text) {
  field->setFocus();
  field->selectAll();
  QTest::keyClicks(field, text);
  QTest::keyClick(field, Qt::Key_Return);
}

}  // namespace

class LayerPanelTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    model_ = std::make_unique<editing::EditorModel>();
    window_ = std::make_unique<QWidget>();
    presets_ = new PresetPanel(*model_, editing::PresetLibrary::builtIn(), window_.get());
    layers_ = new LayerPanel(*model_, window_.get());
    auto* layout = new QHBoxLayout(window_.get());
    layout->addWidget(presets_);
    layout->addWidget(layers_);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    model_->setCurrentTime(2.0);
    presets_->setAsLayer(true);
    QVERIFY(presets_->apply(QStringLiteral("joy")));
  }

  void cleanup() {
    window_.reset();
    model_.reset();
  }

  void aPresetAppliedAsALayerIsListed() {
    QCOMPARE(layers_->list()->topLevelItemCount(), 1);
    QCOMPARE(layers_->list()->topLevelItem(0)->text(0), QStringLiteral("Joy"));
    QCOMPARE(layers_->list()->topLevelItem(0)->checkState(0), Qt::Checked);
    QVERIFY(model_->document().keys.empty());
    QCOMPARE(model_->currentValue(kLiftLeftCheek), 160.0f);
  }

  void untickingMutesTheLayer() {
    layers_->list()->topLevelItem(0)->setCheckState(0, Qt::Unchecked);
    QVERIFY(model_->document().layers.front().muted);
    QCOMPARE(model_->currentValue(kLiftLeftCheek), 0.0f);
    model_->undoStack()->undo();
    QVERIFY(!model_->document().layers.front().muted);
    QCOMPARE(layers_->list()->topLevelItem(0)->checkState(0), Qt::Checked);
  }

  void typedIntensityKeysTheLayerAndRefusalsChangeNothing() {
    auto* field = layers_->findChild<NumberField*>(QStringLiteral("layerIntensity"));
    QVERIFY(field);
    model_->setCurrentTime(3.0);
    const ProjectDocument before = model_->document();
    const int steps = model_->undoStack()->count();
    typeInto(field, QStringLiteral("abc0.5"));
    QVERIFY(model_->document() == before);
    QCOMPARE(model_->undoStack()->count(), steps);
    QVERIFY(!field->refusal().isEmpty());
    typeInto(field, QStringLiteral("250"));  // beyond 100
    QVERIFY(model_->document() == before);
    typeInto(field, QStringLiteral("0.5"));
    QCOMPARE(model_->undoStack()->count(), steps + 1);
    QCOMPARE(model_->document().layers.front().intensityKeys().back().time, 3.0);
    QCOMPARE(model_->document().layers.front().intensityKeys().back().value, 0.5);
    QCOMPARE(model_->currentValue(kLiftLeftCheek), 80.0f);
    QCOMPARE(layers_->list()->topLevelItem(0)->text(2), QStringLiteral("3"));
  }

  void deleteLayerAndUndo() {
    const auto buttons = layers_->findChildren<QPushButton*>();
    QPushButton* remove = nullptr;
    for (QPushButton* button : buttons) {
      if (button->text() == QStringLiteral("Delete layer")) remove = button;
    }
    QVERIFY(remove);
    QTest::mouseClick(remove, Qt::LeftButton);
    QCOMPARE(layers_->list()->topLevelItemCount(), 0);
    QVERIFY(!remove->isEnabled());
    model_->undoStack()->undo();
    QCOMPARE(layers_->list()->topLevelItemCount(), 1);
  }

  void asKeysAgainWritesKeys() {
    presets_->setAsLayer(false);
    QVERIFY(presets_->apply(QStringLiteral("sadness")));
    QCOMPARE(model_->document().layers.size(), std::size_t{1});
    QVERIFY(!model_->document().keys.empty());
  }

 private:
  std::unique_ptr<editing::EditorModel> model_;
  std::unique_ptr<QWidget> window_;
  PresetPanel* presets_ = nullptr;
  LayerPanel* layers_ = nullptr;
};

QTEST_MAIN(LayerPanelTest)
#include "LayerPanelTest.moc"
