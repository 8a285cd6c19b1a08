// The real main window of lacrima-player under xvfb-run, driven through QTest: the demo loaded
// through the Open action's path, Play until frames advance, Reset to a neutral face with no
// tears; a bad file gives an error dialog and keeps the animation; drops open files; toggles
// and parameters reach the playback; the Mood box drives the crying generator live.
#include "../live/LiveTestSupport.h"
#include "../support/MalformedFiles.h"
#include "../support/MissingData.h"

#include <lacrima/live/ListenUrl.h>
#include <lacrima/live/LiveSession.h>
#include <lacrima/player/LiveMappingDialog.h>
#include <lacrima/player/LivePanel.h>
#include <lacrima/player/MoodPanel.h>
#include <lacrima/player/PlayerWindow.h>
#include <lacrima/player/TearParametersPanel.h>
#include <lacrima/viewport/EffectsPanel.h>

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/viewport/FaceViewport.h>

#include <lacrima/playback/TearQualityOptions.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUdpSocket>
#include <QtTest>

#include <algorithm>
#include <fstream>

using namespace lacrima;
using namespace lacrima::player;

namespace {

const QString kDemo = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.fap");

}  // namespace

class PlayerWindowTest : public QObject {
  Q_OBJECT

  std::unique_ptr<PlayerWindow> window_;
  QTemporaryDir dir_;

  QToolButton* button(const char* name) { return window_->findChild<QToolButton*>(name); }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    window_ = std::make_unique<PlayerWindow>(playback::loadDefaultHeadRig());
    window_->resize(1100, 700);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }

  void loadPlayReset() {
    // A missing file with nothing loaded: no "previous animation" to keep.
    window_->setErrorDialogsEnabled(false);
    QVERIFY(!window_->openFile(dir_.filePath("missing.fap")));
    QVERIFY2(!window_->statusBar()->currentMessage().contains("still loaded"),
             qPrintable(window_->statusBar()->currentMessage()));
    window_->setErrorDialogsEnabled(true);
    QSignalSpy opened(window_.get(), &PlayerWindow::fileOpened);
    QVERIFY(window_->openFile(kDemo));
    QCOMPARE(opened.count(), 1);
    QCOMPARE(window_->playback().currentFrame(), 0);
    QVERIFY(window_->playback().frameCount() > 200);
    QVERIFY(window_->windowTitle().contains("crying.fap"));

    QToolButton* play = button("playButton");
    QVERIFY(play && play->isEnabled());
    QTest::mouseClick(play, Qt::LeftButton);
    QVERIFY(window_->playing());
    QTRY_VERIFY_WITH_TIMEOUT(window_->playback().currentFrame() >= 5, 20000);
    QVERIFY(window_->viewport().renderCount() > 0);
    qInfo("playing: frame %d after %lld renders, %.1f fps on screen",
          window_->playback().currentFrame(), window_->viewport().renderCount(),
          window_->renderedFramesPerSecond());
    QVERIFY(window_->timeline().value() > 0);

    QTest::mouseClick(button("resetButton"), Qt::LeftButton);
    QVERIFY(!window_->playing());
    QCOMPARE(window_->playback().currentFrame(), 0);
    QCOMPARE(window_->playback().currentTime(), 0.0);
    QCOMPARE(window_->timeline().value(), 0);
    QCOMPARE(window_->playback().producer().particleCount(), 0);
    const playback::FrameView& view = window_->playback().view();
    QVERIFY(*view.positions == window_->rig().head.positions);  // neutral
    QVERIFY(!view.surface && !view.trails && !view.particles);
  }

  // Space toggles Play/Pause; the tears run while playing into the crying part.
  void spacePlaysAndPauses() {
    QVERIFY(window_->openFile(kDemo));
    window_->seek(4.0);
    // Xvfb has no window manager to hand out the focus: make the window Qt's active one.
    window_->activateWindow();
    QApplication::setActiveWindow(window_.get());
    QCOMPARE(QApplication::activeWindow(), window_.get());
    QTest::keyClick(window_.get(), Qt::Key_Space);
    QVERIFY(window_->playing());
    const int from = window_->playback().currentFrame();
    QTRY_VERIFY_WITH_TIMEOUT(window_->playback().currentFrame() >= from + 3, 20000);
    QTest::keyClick(window_.get(), Qt::Key_Space);
    QVERIFY(!window_->playing());
    QVERIFY(window_->playback().producer().particleCount() > 0);
  }

  void badFileShowsDialogAndKeepsAnimation() {
    QVERIFY(window_->openFile(kDemo));
    window_->seek(5.0);
    const int frames = window_->playback().frameCount();
    const QString bad = dir_.filePath("broken.fap");
    std::ofstream(bad.toStdString()) << "2.1 broken 22 1\n1 1 1\n";
    QSignalSpy failed(window_.get(), &PlayerWindow::openFailed);
    QVERIFY(!window_->openFile(bad));
    QCOMPARE(failed.count(), 1);
    QVERIFY(failed.front().front().toString().startsWith(bad + ":2"));
    auto* dialog = window_->findChild<QMessageBox*>("openErrorDialog");
    QVERIFY(dialog);
    QTRY_VERIFY(dialog->isVisible());
    QVERIFY(dialog->text().contains("broken.fap") && dialog->text().contains("line 2"));
    dialog->accept();
    QVERIFY2(window_->statusBar()->currentMessage().contains("crying.fap is still loaded"),
             qPrintable(window_->statusBar()->currentMessage()));
    QCOMPARE(window_->playback().frameCount(), frames);
    QCOMPARE(QString::fromStdString(window_->playback().path()), kDemo);
    QVERIFY(window_->windowTitle().contains("crying.fap"));
    QVERIFY(qAbs(window_->playback().currentTime() - 5.0) < 1e-9);
  }

  // Every malformed fixture, through File ▸ Open (the dialogs answered as a user would) and by
  // drag and drop: refused with a message naming the file, the demo still loaded.
  void refusesEveryMalformedFile() {
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    QVERIFY(window_->openFile(kDemo));
    const int frames = window_->playback().frameCount();
    auto* open = window_->findChild<QAction*>(QStringLiteral("file.open"));
    QVERIFY(open);
    const QStringList files = test::malformedFiles();
    QVERIFY(files.size() >= 10);
    for (const QString& file : files) {
      for (const bool dropped : {false, true}) {
        QSignalSpy failed(window_.get(), &PlayerWindow::openFailed);
        QStringList messages;
        test::answeringDialogs(file, messages, [&] {
          if (dropped) {
            QMimeData mime;
            mime.setUrls({QUrl::fromLocalFile(file)});
            QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton,
                                  Qt::NoModifier);
            QApplication::sendEvent(window_.get(), &enter);
            QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(window_.get(), &drop);
          } else {
            open->trigger();
          }
          QTRY_COMPARE(failed.count(), 1);
          QTRY_COMPARE(messages.size(), 1);  // the error box, read and closed
        });
        if (QTest::currentTestFailed()) return;
        const QString name = QFileInfo(file).fileName();
        QVERIFY2(failed.front().front().toString().startsWith(file), qPrintable(file));
        QVERIFY2(messages.front().contains(name), qPrintable(messages.front()));
        QCOMPARE(QString::fromStdString(window_->playback().path()), kDemo);
        QCOMPARE(window_->playback().frameCount(), frames);
      }
    }
  }

  // Loop (L, --loop): at the end playing goes on from the start; without it, it stops there.
  // The named cameras of --view are in the View menu; the one shown is checked.
  void viewMenuHasTheCameras() {
    QVERIFY(window_->openFile(kDemo));
    QAction* framing = window_->cameraAction(scene::CameraPreset::Framing);
    QAction* front = window_->cameraAction(scene::CameraPreset::Front);
    QVERIFY(framing && front && framing->isChecked() && !front->isChecked());
    const QImage before = window_->viewport().grabFrame();
    front->trigger();
    QVERIFY(front->isChecked() && !framing->isChecked());
    QVERIFY(window_->viewport().grabFrame() != before);
    window_->cameraAction(scene::CameraPreset::CloseLeft)->trigger();
    QVERIFY(window_->cameraAction(scene::CameraPreset::CloseLeft)->isChecked());
    framing->trigger();
    QVERIFY(framing->isChecked());
  }

  void loopPlaysAgainFromTheStart() {
    QVERIFY(window_->openFile(kDemo));
    const double end = window_->playback().duration();
    window_->seek(end - 0.2);
    window_->loopAction()->setChecked(true);
    window_->play();
    QTRY_VERIFY_WITH_TIMEOUT(window_->playback().currentTime() < 1.0, 10000);
    QVERIFY(window_->playing());
    window_->pause();
    window_->loopAction()->setChecked(false);
    window_->seek(end - 0.2);
    window_->play();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->playing(), 10000);
    QVERIFY(window_->playback().currentTime() > end - 0.1);
  }

  void dropOpensFile() {
    const QString short_ = dir_.filePath("short.fap");
    std::string mask;
    for (int fap = 1; fap <= 68; ++fap)
      mask += std::string(fap > 1 ? " " : "") + (fap == 19 ? "1" : "0");
    std::ofstream(short_.toStdString()) << "2.1 short 22 3\n"
                                        << mask << "\n0 100\n"
                                        << mask << "\n1 200\n"
                                        << mask << "\n2 300\n";
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(short_)});
    QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &drop);
    QTRY_COMPARE(QString::fromStdString(window_->playback().path()), short_);
    QCOMPARE(window_->playback().frameCount(), 3);
    QVERIFY(!window_->playback().hasTears());
  }

  void togglesAndParametersReachPlayback() {
    QVERIFY(window_->openFile(kDemo));
    window_->seek(6.0);
    QVERIFY(!window_->playback().scene().particles);
    window_->effects().particles()->click();
    QVERIFY(window_->playback().scene().particles);
    QVERIFY(window_->playback().view().particles);
    window_->effects().surface()->click();
    QVERIFY(!window_->playback().view().surface);

    QSignalSpy edited(&window_->parameters(), &TearParametersPanel::edited);
    window_->parameters().spinBox("adhesion")->setValue(80);
    QTRY_COMPARE(edited.count(), 1);
    QCOMPARE(window_->playback().scene().simulation.at("adhesion"), 80.0);
    QCOMPARE(window_->playback().currentFrame(), 132);  // replayed back to where it was
    window_->parameters().thesisPreset()->click();
    QVERIFY(window_->playback().scene().simulation.empty());
  }

  // A project brings its own tear quality: opening it says so when it replaces the one shown.
  void openingAProjectSaysWhenItChangesTheQuality() {
    const QString project = dir_.filePath("reference.json");
    QFile file(project);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "lacrima-project", "version": 2, "scene": {"quality": "reference"},
      "keys": [{"time": 0, "values": {"open_jaw": 0}}, {"time": 1, "values": {"open_jaw": 90}}]})");
    file.close();
    QVERIFY(window_->openFile(kDemo));
    QVERIFY(window_->playback().scene().quality.level == TearQuality::Balanced);
    QVERIFY(!window_->statusBar()->currentMessage().contains("tear quality"));
    QVERIFY(window_->openFile(project));
    QVERIFY(window_->playback().scene().quality.level == TearQuality::Reference);
    QVERIFY2(window_->statusBar()->currentMessage().contains("tear quality reference"),
             qPrintable(window_->statusBar()->currentMessage()));
    QVERIFY(window_->openFile(kDemo));
    QVERIFY2(window_->statusBar()->currentMessage().contains("tear quality balanced"),
             qPrintable(window_->statusBar()->currentMessage()));
  }

  // --quality: applied at once, kept over the files opened later, shown in the Scene panel,
  // which can still change it.
  void tearQualityChoice() {
    window_->setTearQuality(TearQuality::Preview);
    QVERIFY(window_->playback().scene().quality.level == TearQuality::Preview);
    QCOMPARE(window_->effects().quality()->currentIndex(), static_cast<int>(TearQuality::Preview));
    QVERIFY(window_->openFile(kDemo));
    QVERIFY(window_->playback().scene().quality.level == TearQuality::Preview);
    QCOMPARE(window_->effects().quality()->currentIndex(), static_cast<int>(TearQuality::Preview));
    window_->effects().quality()->setCurrentIndex(static_cast<int>(TearQuality::Reference));
    QVERIFY(window_->playback().scene().quality.level == TearQuality::Reference);
    QCOMPARE(window_->playback().producer().simulationOptions().lambdaCfl,
             playback::simulationOptions({TearQuality::Reference, {}, {}, {}}).lambdaCfl);
    // Playing where the demo weeps shows the cost of the frames played beside the choice.
    window_->seek(6.0);
    QVERIFY(window_->playback().producer().particleCount() > 0);
    QVERIFY(!window_->effects().cost()->text().contains("sub-steps"));  // seeking is not playing
    // Tears on screen, none measured yet: the label must not say there are none.
    QVERIFY2(!window_->effects().cost()->text().contains("no tears"),
             qPrintable(window_->effects().cost()->text()));
    window_->play();
    QTRY_VERIFY_WITH_TIMEOUT(window_->effects().cost()->text().contains("sub-steps"), 20000);
    window_->pause();
    QVERIFY2(window_->effects().cost()->text().contains("ms per frame"),
             qPrintable(window_->effects().cost()->text()));
  }

  // Live > Listen: a Greta-style frame over TCP turns the head; the timeline gives way to the
  // live indicator, the Live box counts what came, the player's tear counts weep; opening a file
  // goes back to it.
  void liveStreamDrivesTheFace() {
    QVERIFY(window_->openFile(kDemo));
    live::ListenUrl url;  // fap+tcp on 127.0.0.1, a port the system chooses
    window_->listen(url);
    QVERIFY(window_->isLive());
    QVERIFY(!window_->source().seekable());
    const quint16 port = window_->liveSession().inputs().front()->url().port;
    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(agent.waitForConnected(3000));
    QByteArray mask;
    for (int fap = 1; fap <= 68; ++fap) mask += fap == 49 ? "1 " : "0 ";
    agent.write(mask + "\n0 20000\n");  // head_yaw: 0.2 rad
    QTRY_COMPARE_WITH_TIMEOUT(window_->liveSource()->framesReceived(), 1LL, 20000);
    QTRY_COMPARE_WITH_TIMEOUT(window_->liveSource()->shownValues()[channelIndex(49)], 20000.0F,
                              20000);
    QVERIFY(!window_->timeline().isEnabled());
    auto labels = window_->findChildren<QLabel*>();
    QVERIFY(std::any_of(labels.begin(), labels.end(),
                        [](QLabel* l) { return l->text().contains("LIVE"); }));
    window_->livePanel().setTears(30, 30);
    QTRY_VERIFY_WITH_TIMEOUT(window_->liveSource()->particleCount() > 0, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(window_->livePanel().statusText().contains("1 frame"), 20000);

    // Live > Live Link mapping: a gain edited and applied drives the next packet.
    live::ListenUrl phoneUrl;
    phoneUrl.kind = live::StreamKind::LiveLinkUdp;
    window_->listen(phoneUrl);
    LiveMappingDialog& mapping = window_->mappingDialog();
    QTableWidget& table = mapping.table();
    for (int r = 0; r < table.rowCount(); ++r)
      if (table.item(r, 0)->text() == "jawOpen") table.item(r, 2)->setData(Qt::EditRole, 1000.0);
    emit mapping.applied(mapping.mapping());
    std::array<float, 61> values{};
    values[live::test::kJawOpen] = 0.5F;
    QUdpSocket phone;
    phone.writeDatagram(live::test::liveLinkPacket(values), QHostAddress::LocalHost,
                        window_->liveSession().inputs().back()->url().port);
    QTRY_COMPARE_WITH_TIMEOUT(window_->liveSource()->shownValues()[channelIndex(3)], 500.0F, 20000);

    QVERIFY(window_->openFile(kDemo));
    QVERIFY(!window_->isLive());
    QVERIFY(window_->timeline().isEnabled());
    QVERIFY(!window_->liveSession().listening());
  }

  // The Mood box: a slider makes the face cry live with no file (the file's transport gives
  // way), the seed field picks the take, a preset sets the moods; a mood line from a stream
  // moves the sliders; opening a file ends it.
  void moodPanelDrivesTheGenerator() {
    QVERIFY(window_->openFile(kDemo));
    MoodPanel& panel = window_->moodPanel();
    QVERIFY(!window_->moodDriven());
    panel.slider(Mood::Sadness)->setValue(80);  // as a drag would
    QVERIFY(window_->moodDriven());
    QVERIFY(window_->playing());
    QCOMPARE(window_->liveSource()->moods()[Mood::Sadness], 0.8);
    QVERIFY(!window_->timeline().isEnabled());
    QVERIFY(window_->source().producer().scene().blush);
    const auto brow = static_cast<std::size_t>(channelIndex(31));
    QTRY_VERIFY_WITH_TIMEOUT(window_->liveSource()->shownValues()[brow] > 100, 20000);
    QCOMPARE(window_->liveSource()->tearStepsRequested(), 0LL);  // no tears yet

    panel.seedField()->setText("42");
    emit panel.seedField()->editingFinished();
    QCOMPARE(window_->liveSource()->moodSeed(), std::uint64_t(42));
    QTest::mouseClick(panel.randomise(), Qt::LeftButton);
    QCOMPARE(window_->liveSource()->moodSeed(), panel.seed());
    QCOMPARE(panel.seedField()->text(), QString::number(panel.seed()));
    panel.presets()->setCurrentIndex(3);  // Angry crying
    emit panel.presets()->activated(3);
    QCOMPARE(window_->liveSource()->moods()[Mood::Anger], moodPresets()[2].levels[Mood::Anger]);
    QCOMPARE(panel.slider(Mood::Anger)->value(),
             int(std::lround(moodPresets()[2].levels[Mood::Anger] * 100)));

    // A mood line on a stream: the generator follows it, the sliders show it, and a recording
    // keeps the generator's face (LiveSession::recordGenerated), not only frames received.
    live::ListenUrl url;
    QTemporaryDir dir;
    window_->liveSession().startRecording(dir.filePath("moods.fap").toStdString(), 20.0);
    window_->listen(url);
    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost,
                        window_->liveSession().inputs().front()->url().port);
    QVERIFY(agent.waitForConnected(3000));
    agent.write("mood joy=0.9\n");
    QTRY_COMPARE_WITH_TIMEOUT(panel.slider(Mood::Joy)->value(), 90, 20000);
    QCOMPARE(panel.slider(Mood::Anger)->value(), 0);
    QCOMPARE(window_->liveSource()->moods()[Mood::Joy], 0.9);
    QVERIFY(window_->moodDriven());
    const live::LiveRecorder* recorder = window_->liveSession().recorder();
    QVERIFY(recorder);
    QTRY_VERIFY_WITH_TIMEOUT(recorder->frameCount() >= 3, 20000);
    const FapAnimation& take = recorder->animation();
    // The generator's face, moving: recorded, where nothing was received but a mood line.
    QVERIFY(std::any_of(take.frames.back().begin(), take.frames.back().end(),
                        [](float v) { return v != 0; }));
    QVERIFY(take.frames.back() != take.frames.front());
    QVERIFY(window_->liveSession().stopRecording());

    QVERIFY(window_->openFile(kDemo));
    QVERIFY(!window_->isLive());
    QVERIFY(!window_->moodDriven());
    QVERIFY(window_->timeline().isEnabled());
  }
};

QTEST_MAIN(PlayerWindowTest)
#include "PlayerWindowTest.moc"
