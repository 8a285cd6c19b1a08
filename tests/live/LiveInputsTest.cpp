// Live inputs as real clients use them: Greta-style FAP frames over TCP and Live Link Face
// packets over UDP, built from the published layouts (LiveTestSupport.h), recorded and checked;
// and hostile peers (garbage, an endless line, a flood of datagrams, a peer gone mid-frame, too
// many connections) counted while the event loop stays responsive and memory bounded.
#include "LiveTestSupport.h"

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/live/LiveSession.h>

#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QUdpSocket>
#include <QtTest>

#include <sys/resource.h>

#include <random>

using namespace lacrima;
using namespace lacrima::live;
using namespace lacrima::live::test;

namespace {

ListenUrl anyPort(StreamKind kind) {
  ListenUrl url;
  url.kind = kind;
  return url;  // 127.0.0.1, port 0: the system picks one
}

float channel(const FapValues& values, const char* name) {
  return values[static_cast<std::size_t>(channelIndex(*fapByName(name)))];
}

long peakKilobytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

}  // namespace

class LiveInputsTest : public QObject {
  Q_OBJECT

 private slots:
  void urlsBindToLoopbackUnlessTold() {
    QString error;
    const auto plain = parseListenUrl("fap+tcp://:5555", error);
    QVERIFY(plain && plain->isLoopback() && plain->port == 5555);
    const auto all = parseListenUrl("livelink+udp://0.0.0.0:11111", error);
    QVERIFY(all && !all->isLoopback() && all->kind == StreamKind::LiveLinkUdp);
    QCOMPARE(all->toString(), QStringLiteral("livelink+udp://0.0.0.0:11111"));
    for (const char* bad :
         {"tcp://1.2.3.4:5", "fap+tcp://host.example:5", "fap+udp://:99999", "fap+tcp://127.0.0.1"})
      QVERIFY2(!parseListenUrl(bad, error) && !error.isEmpty(), bad);
  }

  // An agent sends Greta-style frames at 25 fps, cut across writes; the recording holds them.
  void gretaFramesOverTcpAreRecorded() {
    QTemporaryDir dir;
    const std::string out = dir.filePath("take.fap").toStdString();
    LiveSession session;
    std::vector<LiveFrame> frames;
    session.setFrameHandler([&](const LiveFrame& f) { frames.push_back(f); });
    session.startRecording(out, std::nullopt);
    const quint16 port = session.listen(anyPort(StreamKind::FapTcp)).url().port;

    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(agent.waitForConnected(3000));
    constexpr int kFrames = 12;
    QElapsedTimer sending;
    sending.start();
    QByteArray pending = "2.1 greta 25 " + QByteArray::number(kFrames) + "\n";
    for (int f = 0; f < kFrames; ++f) {
      pending += gretaFrame(f, {{3, 40 * f}, {19, 512}, {20, 512}, {49, 3000 * f}, {31, 100}});
      // Half of what is ready now, the rest with the next frame: lines arrive in pieces.
      const qsizetype half = pending.size() / 2;
      agent.write(pending.left(half));
      agent.flush();
      pending.remove(0, half);
      waitFor([] { return false; }, 40);
    }
    agent.write(pending);
    agent.flush();
    const double sendingSeconds = sending.elapsed() / 1000.0;
    QVERIFY(waitFor([&] { return frames.size() == kFrames; }, 30000));
    agent.disconnectFromHost();
    QVERIFY(waitFor([&] { return session.totals().disconnects == 1; }, 30000));

    const InputCounters totals = session.totals();
    QCOMPARE(totals.frames, (long long)kFrames);
    QCOMPARE(totals.problems(), 0LL);
    QCOMPARE(channel(frames.back().values, "open_jaw"), 40.0F * (kFrames - 1));
    QCOMPARE(*frames.back().frameRate, 25.0);
    QVERIFY(session.stopRecording());

    const FapReadResult recorded = FapReader::readFile(out);
    QCOMPARE(recorded.animation.fps, 25.0);
    // One recorded frame per 1/25 s of sending (sent at about that rate, about one per frame
    // sent; a loaded machine stretches the sending), each one of those sent, in order.
    qInfo("sent %d frames in %.2f s, recorded %d", kFrames, sendingSeconds,
          recorded.animation.frameCount());
    QVERIFY(recorded.animation.frameCount() <= sendingSeconds * 25 + 3);
    QVERIFY(recorded.animation.frameCount() >= 2);
    float maxYaw = 0, previousJaw = 0;
    for (const FapValues& v : recorded.animation.frames) {
      const float jaw = channel(v, "open_jaw");
      QVERIFY(jaw == std::round(jaw / 40) * 40 && jaw >= previousJaw && jaw <= 40 * (kFrames - 1));
      previousJaw = jaw;
      QCOMPARE(channel(v, "head_yaw"), jaw / 40 * 3000);  // from the same frame
      QCOMPARE(channel(v, "close_t_l_eyelid"), 512.0F);
      maxYaw = std::max(maxYaw, channel(v, "head_yaw"));
    }
    QCOMPARE(channel(recorded.animation.frames.back(), "open_jaw"), 40.0F * (kFrames - 1));
    QVERIFY(maxYaw > 0);  // the head turned
    QVERIFY(recorded.animation.animated.test(channelIndex(49)));
  }

  // An agent sends moods instead of frames (docs/live.md), over TCP between frames and over UDP
  // one line per datagram: they reach the mood handler in order, are counted, and are not
  // frames; a bad one is counted with its place.
  void moodLinesReachTheMoodHandler() {
    LiveSession session;
    std::vector<LiveMood> moods;
    int frames = 0;
    session.setFrameHandler([&](const LiveFrame&) { ++frames; });
    session.setMoodHandler([&](const LiveMood& m) { moods.push_back(m); });
    const quint16 tcpPort = session.listen(anyPort(StreamKind::FapTcp)).url().port;
    const quint16 udpPort = session.listen(anyPort(StreamKind::FapUdp)).url().port;

    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, tcpPort);
    QVERIFY(agent.waitForConnected(3000));
    agent.write("mood sadness=0.8 anger=0.2\n" + gretaFrame(0, {{3, 40}}) +
                "mood sadness=2\nmood joy=0.5\n");
    agent.flush();
    QVERIFY(waitFor([&] { return moods.size() == 2 && frames == 1; }, 30000));
    QCOMPARE(moods[0].levels[Mood::Sadness], 0.8);
    QCOMPARE(moods[0].levels[Mood::Anger], 0.2);
    QCOMPARE(moods[1].levels[Mood::Joy], 0.5);
    QCOMPARE(moods[1].levels[Mood::Sadness], 0.0);
    QVERIFY(waitFor([&] { return session.totals().malformed == 1; }, 30000));
    QVERIFY2(session.statusText().contains(":4:6: sadness: expected an intensity from 0 to 1"),
             qPrintable(session.statusText()));
    QVERIFY2(session.statusText().contains("2 mood lines"), qPrintable(session.statusText()));

    QUdpSocket udp;
    udp.writeDatagram(QByteArray("mood shame=0.4\n"), QHostAddress::LocalHost, udpPort);
    QVERIFY(waitFor([&] { return moods.size() == 3; }, 30000));
    QCOMPARE(moods[2].levels[Mood::Shame], 0.4);
    QCOMPARE(session.totals().moods, 3LL);
    QCOMPARE(session.totals().frames, 1LL);
  }

  // A phone sends Live Link Face packets; the shipped mapping turns them into FAPs.
  void liveLinkPacketsOverUdpBecomeFaps() {
    LiveSession session;
    std::vector<LiveFrame> frames;
    session.setFrameHandler([&](const LiveFrame& f) { frames.push_back(f); });
    const quint16 port = session.listen(anyPort(StreamKind::LiveLinkUdp)).url().port;
    QUdpSocket phone;
    std::array<float, 61> values{};
    values[kJawOpen] = 0.5F;
    values[kHeadYaw] = 0.2F;
    values[kBrowInnerUp] = 1.0F;
    values[kEyeBlinkLeft] = 1.0F;
    for (int f = 0; f < 5; ++f) {
      phone.writeDatagram(liveLinkPacket(values, 1000 + f), QHostAddress::LocalHost, port);
      waitFor([] { return false; }, 10);
    }
    QVERIFY(waitFor([&] { return frames.size() == 5; }));
    const FapValues& v = frames.back().values;
    QCOMPARE(channel(v, "open_jaw"), 350.0F);           // jawOpen x 700
    QCOMPARE(channel(v, "head_yaw"), 20000.0F);         // 0.2 rad in 1e-5 rad
    QCOMPARE(channel(v, "raise_l_i_eyebrow"), 400.0F);  // browInnerUp: both inner brows
    QCOMPARE(channel(v, "raise_r_i_eyebrow"), 400.0F);
    QCOMPARE(channel(v, "close_t_l_eyelid"), 1024.0F);  // eyeBlinkLeft: the lid closed
    QCOMPARE(channel(v, "close_t_r_eyelid"), 0.0F);
    QVERIFY(!frames.back().mask.test(channelIndex(kTearLeftFap)));  // tears: the player's own
    QCOMPARE(*frames.back().frameRate, 60.0);

    // A malformed packet is counted and named, never thrown.
    phone.writeDatagram(liveLinkPacket(values, 0, 60, 52), QHostAddress::LocalHost, port);
    phone.writeDatagram("garbage", QHostAddress::LocalHost, port);
    QVERIFY(waitFor([&] { return session.totals().malformed == 2; }));
    QVERIFY(session.statusText().contains("2 malformed"));
    QCOMPARE(frames.size(), std::size_t(5));
  }

  void liveLinkPacketErrorsNameTheByte() {
    std::array<float, 61> values{};
    const QByteArray good = liveLinkPacket(values);
    QCOMPARE(decodeLiveLinkPacket({good.constData(), std::size_t(good.size())}, "p").frameRate(),
             60.0);
    const auto refused = [](const QByteArray& bytes, const char* part) {
      try {
        decodeLiveLinkPacket({bytes.constData(), std::size_t(bytes.size())}, "phone");
      } catch (const FileError& e) {
        return std::string(e.what()).starts_with("phone") &&
               std::string(e.what()).find(part) != std::string::npos;
      }
      return false;
    };
    QVERIFY(refused(good.left(100), "the packet ends (100 bytes)"));
    QVERIFY(refused(liveLinkPacket(values, 0, 60, 61, 5), "packet version 5"));
    QVERIFY(refused(liveLinkPacket(values, 0, 60, 52), "value count 52"));
    QVERIFY(refused(good + "x", "1 bytes after the last value"));
    QByteArray huge = good;
    huge[1] = char(0x7f);  // a device id 2 GB long, in five bytes
    QVERIFY(refused(huge, "expected at most 256"));
    values[kJawOpen] = std::numeric_limits<float>::quiet_NaN();
    QVERIFY(refused(liveLinkPacket(values), "jawOpen is not a finite number"));
  }

  void mappingFileIsCheckedAndRoundTrips() {
    const LiveLinkMapping shipped = defaultLiveLinkMapping();
    QVERIFY(shipped.rows.size() > 50);
    QVERIFY(LiveLinkMapping::parse(shipped.toJson(), "again") == shipped);
    try {
      LiveLinkMapping::parse(R"({"format": "lacrima-livelink-mapping", "version": 1,
        "rows": [{"from": "jawOpen", "to": "open_mouth", "gain": 700}]})",
                             "mine.json");
      QFAIL("expected an error");
    } catch (const FileError& e) {
      QVERIFY2(std::string(e.what()).starts_with("mine.json:2:38: rows[0].to: expected a FAP name"),
               e.what());
    }
  }

  // Garbage, an endless line, a peer gone mid-frame and one connection too many: counted; the
  // input goes on, memory stays bounded.
  void hostileTcpPeersAreCounted() {
    LiveSession session;
    long long frames = 0;
    session.setFrameHandler([&](const LiveFrame&) { ++frames; });
    const quint16 port = session.listen(anyPort(StreamKind::FapTcp)).url().port;

    QTcpSocket garbage;
    garbage.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(garbage.waitForConnected(3000));
    std::mt19937 random(35);
    QByteArray noise(20000, '\0');
    for (char& c : noise) c = static_cast<char>(random());
    garbage.write(noise + "\n" + gretaFrame(0, {{3, 77}}));
    QVERIFY(waitFor([&] { return frames == 1; }));
    QVERIFY(session.totals().malformed > 0);

    // 16 MB without a newline, then a good frame: one over-long line, bounded memory.
    const long before = peakKilobytes();
    QTcpSocket endless;
    endless.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(endless.waitForConnected(3000));
    const QByteArray chunk(1 << 20, '1');
    for (int i = 0; i < 16; ++i) {
      endless.write(chunk);
      // Never more than a few MB in flight: the player reads as fast as it can.
      QVERIFY(waitFor([&] { return endless.bytesToWrite() < 4 << 20; }, 20000));
    }
    endless.write("\n" + gretaFrame(1, {{3, 88}}));
    QVERIFY(waitFor([&] { return frames == 2; }, 20000));
    QCOMPARE(session.totals().oversizedLines, 1LL);
    QVERIFY2(peakKilobytes() - before < 48 * 1024,
             qPrintable(QString("%1 kB more").arg(peakKilobytes() - before)));

    QTcpSocket leaver;
    leaver.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(leaver.waitForConnected(3000));
    leaver.write(gretaFrame(2, {{3, 99}}).left(138));  // the mask line and part of the values
    leaver.flush();
    waitFor([] { return false; }, 50);
    leaver.abort();
    QVERIFY(waitFor([&] { return session.totals().truncated == 1; }));

    std::vector<std::unique_ptr<QTcpSocket>> crowd;
    for (int i = 0; i < LiveInput::kMaxClients + 1; ++i) {
      crowd.push_back(std::make_unique<QTcpSocket>());
      crowd.back()->connectToHost(QHostAddress::LocalHost, port);
      QVERIFY(crowd.back()->waitForConnected(3000));
    }
    QVERIFY(waitFor([&] { return session.totals().refused >= 1; }));
    QVERIFY(session.statusText().contains("refused"));
  }

  // 10,000 datagrams a second for a second: the event loop keeps turning (a 10 ms timer is never
  // late by more than a fraction of a second), the excess is dropped and counted.
  void datagramFloodKeepsTheLoopResponsive() {
    LiveSession session;
    long long frames = 0;
    session.setFrameHandler([&](const LiveFrame&) { ++frames; });
    const quint16 port = session.listen(anyPort(StreamKind::FapUdp)).url().port;
    QUdpSocket flood;
    const QByteArray datagram = gretaFrame(0, {{3, 120}, {48, -500}});
    QElapsedTimer sinceTick;
    qint64 longestGap = 0;
    QTimer ticker;
    ticker.setInterval(10);
    connect(&ticker, &QTimer::timeout,
            [&] { longestGap = std::max(longestGap, sinceTick.restart()); });
    sinceTick.start();
    ticker.start();
    QElapsedTimer clock;
    clock.start();
    int sent = 0;
    while (sent < 10000) {
      // 100 datagrams every 10 ms: 10,000 a second.
      const int due = static_cast<int>(std::min<qint64>(10000, (clock.elapsed() / 10 + 1) * 100));
      for (; sent < due; ++sent) flood.writeDatagram(datagram, QHostAddress::LocalHost, port);
      QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    waitFor([] { return false; }, 300);
    const InputCounters c = session.totals();
    qInfo("sent %d in %lld ms: %lld decoded, %lld dropped as a flood, longest timer gap %lld ms",
          sent, clock.elapsed(), c.frames, c.flooded, longestGap);
    const double seconds = clock.elapsed() / 1000.0;
    const double budget = LiveInput::kMaxDatagramsPerSecond * (seconds + 1);
    QVERIFY(c.frames > 0);
    QVERIFY(c.frames <= budget);  // never more decoded than the budget allows
    // Read faster than the budget (every unloaded run: about 6,000 of 10,000 dropped): counted.
    if (c.frames + c.flooded > budget) {
      QVERIFY(c.flooded > 0);
      QVERIFY(session.statusText().contains("dropped (flood)"));
    }
    // 13 ms unloaded; the bound leaves room for a machine shared with builds.
    QVERIFY2(longestGap < 2000, qPrintable(QString::number(longestGap)));
  }
};

QTEST_GUILESS_MAIN(LiveInputsTest)
#include "LiveInputsTest.moc"
