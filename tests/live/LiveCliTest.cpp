// The live programs as scripts use them: `lacrima-player --no-window --listen ... --record`
// fed by a client written here from the published layouts, and by `lacrima-send`, as the
// README shows. Real processes; the recorded file is read back and checked.
#include "LiveTestSupport.h"

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTable.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QNetworkDatagram>
#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QUdpSocket>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::live::test;

namespace {

const QString kBin = QStringLiteral(LACRIMA_BIN_DIR);

float channel(const FapValues& values, const char* name) {
  return values[static_cast<std::size_t>(channelIndex(*fapByName(name)))];
}

// QProcess::waitForFinished is false for a process that has already finished, and the event
// loop that waitFor spins may have seen it finish: a fast program would then fail the test.
bool exited(QProcess& process, int timeoutMs) {
  return process.state() == QProcess::NotRunning || process.waitForFinished(timeoutMs);
}

// Starts a headless player on `url` (port 0) recording to `out`; returns the port it got.
quint16 startPlayer(QProcess& player, const QString& url, const QString& out,
                    const QStringList& more = {}) {
  player.setProgram(kBin + "/lacrima-player");
  player.setArguments(
      QStringList{"--no-window", "--listen", url, "--record", out, "--exit-when-idle", "1.5"} +
      more);
  player.start();
  if (!player.waitForStarted(5000)) return 0;
  // "listening on fap+tcp://127.0.0.1:40123"
  if (!waitFor([&] { return player.canReadLine(); }, 30000)) return 0;
  const QByteArray line = player.readLine().trimmed();
  return static_cast<quint16>(line.mid(line.lastIndexOf(':') + 1).toUInt());
}

}  // namespace

class LiveCliTest : public QObject {
  Q_OBJECT

 private slots:
  // A Greta-style agent over TCP; the player records it and exits when the agent is done.
  void headlessPlayerRecordsAnAgent() {
    QTemporaryDir dir;
    const QString out = dir.filePath("agent.fap");
    QProcess player;
    const quint16 port = startPlayer(player, "fap+tcp://127.0.0.1:0", out);
    QVERIFY2(port != 0, player.readAllStandardError().constData());
    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(agent.waitForConnected(3000));
    QElapsedTimer sending;
    sending.start();
    agent.write("2.1 greta 20 10\n");
    for (int f = 0; f < 10; ++f) {
      agent.write(gretaFrame(f, {{3, 30 * f}, {48, -1000 * f}, {69, 5 * f}, {70, 0}}, 70));
      agent.flush();
      waitFor([] { return false; }, 50);
    }
    const double sendingSeconds = sending.elapsed() / 1000.0;
    agent.disconnectFromHost();
    QVERIFY(exited(player, 60000));
    const QByteArray err = player.readAllStandardError();
    QCOMPARE(player.exitCode(), 0);
    QVERIFY2(err.contains("recorded"), err.constData());
    const FapReadResult take = FapReader::readFile(out.toStdString());
    QCOMPARE(take.animation.fps, 20.0);
    // About one frame per frame sent at 20 fps (more when a loaded machine stretched the sending).
    QVERIFY(take.animation.frameCount() >= 2);
    QVERIFY(take.animation.frameCount() <= sendingSeconds * 20 + 3);
    float previousJaw = 0;
    for (const FapValues& v : take.animation.frames) {
      QVERIFY(channel(v, "open_jaw") >= previousJaw);  // in the order sent
      previousJaw = channel(v, "open_jaw");
    }
    const FapValues& last = take.animation.frames.back();
    QCOMPARE(channel(last, "open_jaw"), 270.0F);
    QCOMPARE(channel(last, "head_pitch"), -9000.0F);  // the head moved
    QCOMPARE(channel(last, "tears_l_eye"), 45.0F);    // the stream's own tears
  }

  // The README's example: lacrima-send plays the demo into a listening player, over UDP here.
  void lacrimaSendStreamsTheDemo() {
    QTemporaryDir dir;
    const QString out = dir.filePath("demo.fap");
    QProcess player;
    const quint16 port = startPlayer(player, "fap+udp://:0", out);
    QVERIFY2(port != 0, player.readAllStandardError().constData());
    const QString demo = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.fap");
    QProcess send;
    // 88 fps: four times the demo's rate, so the test takes 3.5 s; recorded at 88 fps too.
    send.start(kBin + "/lacrima-send",
               {demo, "--to", QStringLiteral("fap+udp://127.0.0.1:%1").arg(port), "--rate", "88"});
    QVERIFY(exited(send, 60000));
    QCOMPARE(send.exitCode(), 0);
    QVERIFY(exited(player, 60000));
    QCOMPARE(player.exitCode(), 0);
    const FapAnimation sent = FapReader::readFile(demo.toStdString()).animation;
    const FapAnimation got = FapReader::readFile(out.toStdString()).animation;
    QCOMPARE(got.fps, 88.0);
    qInfo("sent %d frames, recorded %d", sent.frameCount(), got.frameCount());
    // Unloaded, every frame (309 of 309); a loaded machine bunches some.
    QVERIFY(got.frameCount() >= sent.frameCount() / 2 &&
            got.frameCount() <= sent.frameCount() + 10);
    // Every recorded frame is one of the demo's, in order: none invented, none out of place.
    int at = 0;
    for (const FapValues& v : got.frames) {
      while (at < sent.frameCount() && sent.frames[static_cast<std::size_t>(at)] != v) ++at;
      QVERIFY2(at < sent.frameCount(), "a recorded frame the demo does not have, or out of order");
    }
    QVERIFY(got.frames.back() == sent.frames.back());
  }

  // A mood line drives the crying generator without a window too, and --record keeps its frames
  // (sadness raises the inner brows, the face never stands still); a frame from the stream then
  // takes the face back. (The window's recording of the generator: test_player_window.)
  void headlessPlayerRecordsTheMoodGenerator() {
    QTemporaryDir dir;
    const QString out = dir.filePath("moods.fap");
    QProcess player;
    // Idle after 1.5 s.
    const quint16 port = startPlayer(player, "fap+tcp://127.0.0.1:0", out, {"--record-rate", "20"});
    QVERIFY2(port != 0, player.readAllStandardError().constData());
    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(agent.waitForConnected(3000));
    agent.write("mood sadness=0.9\n");
    agent.flush();
    waitFor([] { return false; }, 800);  // within the idle time: a mood line is activity
    agent.write("2.1 greta 20 1\n" + gretaFrame(0, {{3, 77}}));
    agent.flush();
    waitFor([] { return false; }, 200);
    agent.disconnectFromHost();
    QVERIFY(exited(player, 60000));
    const QByteArray err = player.readAllStandardError();
    QCOMPARE(player.exitCode(), 0);
    QVERIFY2(err.contains("recorded"), err.constData());
    const FapAnimation take = FapReader::readFile(out.toStdString()).animation;
    // Count the generated frames rather than expect one per recorded frame: a loaded machine
    // may run the generator's timer late.
    std::vector<FapValues> generated;
    for (const FapValues& v : take.frames) {
      if (channel(v, "raise_l_i_eyebrow") > 0 && channel(v, "raise_r_i_eyebrow") > 0 &&
          (generated.empty() || v != generated.back()))
        generated.push_back(v);
    }
    QVERIFY2(
        generated.size() >= 10u,  // 20 a second for 0.8 s
        qPrintable(
            QString("%1 generated of %2 recorded").arg(generated.size()).arg(take.frameCount())));
    const FapValues& last = take.frames.back();  // the stream's frame: the rest neutral
    QCOMPARE(channel(last, "open_jaw"), 77.0F);
    QCOMPARE(channel(last, "raise_l_i_eyebrow"), 0.0F);
  }

  // --no-window --render: the take rendered when the stream ends, as --render renders a file.
  void headlessRenderOfATake() {
    QTemporaryDir dir;
    const QString out = dir.filePath("render");
    QProcess player;
    const quint16 port = startPlayer(player, "fap+tcp://127.0.0.1:0", dir.filePath("take.fap"),
                                     {"--render", out, "--size", "96x72"});
    QVERIFY2(port != 0, player.readAllStandardError().constData());
    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(agent.waitForConnected(3000));
    agent.write("2.1 greta 10 3\n");
    for (int f = 0; f < 3; ++f) {
      agent.write(gretaFrame(f, {{3, 200 * f}, {49, 8000 * f}}));
      agent.flush();
      waitFor([] { return false; }, 100);
    }
    agent.disconnectFromHost();
    QVERIFY(exited(player, 120000));
    const QByteArray err = player.readAllStandardError();
    QCOMPARE(player.exitCode(), 0);
    const int frames =
        FapReader::readFile(dir.filePath("take.fap").toStdString()).animation.frameCount();
    QVERIFY2(QFileInfo::exists(out + "/contact_sheet.png"), err.constData());
    for (int f = 0; f < frames; ++f)
      QVERIFY(QFileInfo::exists(out + QStringLiteral("/frame_%1.png").arg(f, 4, 10, QChar('0'))));
    QVERIFY(
        !QFileInfo::exists(out + QStringLiteral("/frame_%1.png").arg(frames, 4, 10, QChar('0'))));
  }

  // `lacrima-send --mood` sends the mood line of docs/live.md, every mood named, over TCP and
  // as one datagram; a listening player reads it with the stream parser (test_live_inputs).
  void lacrimaSendSendsAMoodLine() {
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    QProcess send;
    send.start(kBin + "/lacrima-send",
               {"--mood", "sadness=0.8,shame=0.25", "--to",
                QStringLiteral("fap+tcp://127.0.0.1:%1").arg(server.serverPort())});
    QVERIFY(waitFor([&] { return server.hasPendingConnections(); }, 30000));
    QTcpSocket* peer = server.nextPendingConnection();
    QByteArray got;
    QVERIFY(waitFor(
        [&] {
          got += peer->readAll();
          return got.endsWith('\n');
        },
        30000));
    QCOMPARE(got, QByteArray("mood sadness=0.8 anger=0 joy=0 shame=0.25\n"));
    QVERIFY(exited(send, 10000));
    QCOMPARE(send.exitCode(), 0);

    QUdpSocket udp;
    QVERIFY(udp.bind(QHostAddress::LocalHost, 0));
    send.start(
        kBin + "/lacrima-send",
        {"--mood", "joy=1", "--to", QStringLiteral("fap+udp://127.0.0.1:%1").arg(udp.localPort())});
    QVERIFY(exited(send, 10000));
    QCOMPARE(send.exitCode(), 0);
    QVERIFY(waitFor([&] { return udp.hasPendingDatagrams(); }, 10000));
    QCOMPARE(udp.receiveDatagram().data(), QByteArray("mood sadness=0 anger=0 joy=1 shame=0\n"));
  }

  void usageErrors() {
    QProcess player;
    player.start(kBin + "/lacrima-player", {"--no-window", "--listen", "tcp://x:1"});
    QVERIFY(exited(player, 10000));
    QCOMPARE(player.exitCode(), 2);
    QVERIFY(player.readAllStandardError().contains("--listen: expected fap+tcp://"));
    QProcess send;
    send.start(kBin + "/lacrima-send", {"x.fap", "--to", "livelink+udp://:11111"});
    QVERIFY(exited(send, 10000));
    QCOMPARE(send.exitCode(), 2);

    // Moods: a bad intensity or mood, --seed alone, --mood with a FILE or a render.
    const std::pair<QStringList, const char*> bad[] = {
        {{"--mood", "sadness=1.2"}, "--mood: sadness: expected an intensity from 0 to 1"},
        {{"--mood", "grief=1"}, "--mood: unknown mood 'grief'"},
        {{"--seed", "4"}, "--seed goes with --mood"},
        {{"--mood", "joy=1", "--seed", "x3"}, "--seed: expected a whole number"},
        {{"--mood", "joy=1", "take.fap"}, "--mood plays the crying generator with no FILE"},
        {{"--mood", "joy=1", "--render", "out"}, "for --render write a take first"},
    };
    for (const auto& [arguments, expected] : bad) {
      player.start(kBin + "/lacrima-player", arguments);
      QVERIFY(exited(player, 10000));
      QCOMPARE(player.exitCode(), 2);
      const QByteArray error = player.readAllStandardError();
      QVERIFY2(error.contains(expected), error.constData());
    }
    send.start(kBin + "/lacrima-send", {"--mood", "sadness=x", "--to", "fap+tcp://127.0.0.1:9"});
    QVERIFY(exited(send, 10000));
    QCOMPARE(send.exitCode(), 2);
    QVERIFY(send.readAllStandardError().contains("--mood: sadness: expected an intensity"));
  }
};

QTEST_GUILESS_MAIN(LiveCliTest)
#include "LiveCliTest.moc"
