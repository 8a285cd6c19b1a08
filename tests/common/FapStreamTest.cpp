// FapTextStream and decodeFapDatagram: FAP text arriving in pieces goes through the file
// reader's parser (same frames, same diagnostics), never stops at a bad line, and holds at most
// one line of memory.
#include "../support/FapMaskLine.h"

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTextStream.h>

#include <QtTest>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace lacrima;

namespace {

using lacrima::test::mask;

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::vector<FapTextFrame> feedAll(FapTextStream& stream, std::string_view bytes) {
  std::vector<FapTextFrame> frames;
  stream.feed(bytes, [&](const FapTextFrame& f) { frames.push_back(f); });
  return frames;
}

}  // namespace

class FapStreamTest : public QObject {
  Q_OBJECT

 private slots:
  // The demo, cut at random places, decodes to exactly the frames the file reader gives.
  void demoInRandomPiecesMatchesTheFileReader() {
    const std::string path = std::string(LACRIMA_SOURCE_DIR) + "/media/demo/crying.fap";
    const std::string text = readText(path);
    const FapReadResult file = FapReader::readFile(path);
    std::mt19937 random(35);
    for (int round = 0; round < 3; ++round) {
      FapTextStream stream("tcp");
      std::vector<FapTextFrame> frames;
      for (std::size_t at = 0; at < text.size();) {
        const std::size_t n = std::min<std::size_t>(1 + random() % 700, text.size() - at);
        stream.feed(std::string_view(text).substr(at, n),
                    [&](const FapTextFrame& f) { frames.push_back(f); });
        at += n;
      }
      stream.finish();
      QCOMPARE(int(frames.size()), file.animation.frameCount());
      for (std::size_t i = 0; i < frames.size(); ++i) {
        QCOMPARE(frames[i].number, std::int64_t(i));
        QVERIFY(frames[i].values == file.animation.frames[i]);  // bit for bit
        QVERIFY((frames[i].mask & ~file.animation.animated).none());
      }
      QCOMPARE(stream.counters().frames, (long long)frames.size());
      QCOMPARE(stream.counters().malformed + stream.counters().truncated, 0LL);
      QVERIFY(stream.frameRate().has_value());
      QCOMPARE(*stream.frameRate(), file.animation.fps);
    }
  }

  // A stream may start at a mask line: no header, no rate.
  void headerIsOptional() {
    FapTextStream stream("s");
    const auto frames =
        feedAll(stream, mask({3, 48}) + "\n7 120 -400\n" + mask({3}) + "\r\n8 60\r\n");
    QCOMPARE(int(frames.size()), 2);
    QCOMPARE(frames[0].number, std::int64_t(7));
    QCOMPARE(frames[0].values[channelIndex(3)], 120.0F);
    QCOMPARE(frames[0].values[channelIndex(48)], -400.0F);
    QCOMPARE(frames[1].values[channelIndex(48)], 0.0F);  // masked off: neutral
    QVERIFY(!stream.frameRate());
  }

  // A bad line is counted with the file reader's message, and the next frame is read.
  void badLinesAreCountedAndSkipped() {
    const std::string bad = mask({3}) + "\n0 wide\n";
    FapTextStream stream("fap+tcp://127.0.0.1:5555");
    const auto frames = feedAll(stream, "hello there\n" + bad + mask({3}) + "\n1 50\n");
    QCOMPARE(int(frames.size()), 1);
    QCOMPARE(frames[0].values[channelIndex(3)], 50.0F);
    QCOMPARE(stream.counters().malformed, 2LL);
    // The same text as a file: the same message at the same column.
    try {
      FapReader::parse("2.1 a 22 1\n" + bad, "x");
      QFAIL("expected an error");
    } catch (const FileError& e) {
      QVERIFY2(stream.lastProblem().ends_with(":3:3: " + e.message()),
               stream.lastProblem().c_str());
      QCOMPARE(e.where().column, 3);
    }
  }

  // A line without end costs at most one line of memory; it is counted once and skipped.
  void endlessLineIsSkippedWithBoundedMemory() {
    FapTextStream stream("s");
    const std::string chunk(50'000, '1');
    for (int i = 0; i < 200; ++i) {  // 10 MB without a newline
      feedAll(stream, chunk);
      QVERIFY(stream.bufferedBytes() <= FapTextParser::kMaxLineLength);
    }
    const std::string next = std::string("\n").append(mask({5})).append("\n0 9\n");
    const auto frames = feedAll(stream, next);
    QCOMPARE(stream.counters().oversizedLines, 1LL);
    QCOMPARE(int(frames.size()), 1);
    QCOMPARE(frames[0].values[channelIndex(5)], 9.0F);
    QVERIFY(stream.lastProblem().find("longer than") != std::string::npos);
  }

  // A peer that leaves in the middle of a frame: counted, and a new connection starts clean.
  void disconnectMidFrameIsTruncated() {
    FapTextStream stream("s");
    feedAll(stream, mask({3}) + "\n0 1");
    stream.finish();
    QCOMPARE(stream.counters().truncated, 1LL);
    feedAll(stream, mask({3}) + "\n");
    stream.finish();
    QCOMPARE(stream.counters().truncated, 2LL);
    const auto frames = feedAll(stream, mask({3}) + "\n4 2\n");
    QCOMPARE(int(frames.size()), 1);
    QCOMPARE(stream.counters().malformed, 0LL);
  }

  // A mood line (docs/live.md) sets the generator's moods between frames; the frames go on.
  void moodLinesGoToTheirOwnHandler() {
    FapTextStream stream("fap+tcp://127.0.0.1:5555");
    std::vector<MoodLevels> moods;
    int frames = 0;
    const auto feed = [&](std::string_view bytes) {
      stream.feed(
          bytes, [&](const FapTextFrame&) { ++frames; },
          [&](const MoodLevels& levels) { moods.push_back(levels); });
    };
    feed("mood sadness=0.8 anger=0.25\n" + mask({3}) + "\n0 5\n  mood\nmood joy=1\n");
    QCOMPARE(frames, 1);
    QCOMPARE(int(moods.size()), 3);
    QCOMPARE(moods[0][Mood::Sadness], 0.8);
    QCOMPARE(moods[0][Mood::Anger], 0.25);
    QCOMPARE(moods[0][Mood::Joy], 0.0);  // not named: 0
    QVERIFY(moods[1] == MoodLevels{});   // `mood` alone: neutral
    QCOMPARE(moods[2][Mood::Joy], 1.0);
    QCOMPARE(moods[2][Mood::Sadness], 0.0);
    QCOMPARE(stream.counters().moods, 3LL);
    QCOMPARE(stream.counters().malformed, 0LL);

    // Bad ones are counted with their place and what was expected; the stream goes on.
    const std::pair<const char*, const char*> bad[] = {
        {"mood sadness=1.5", ":6:6: sadness: expected an intensity from 0 to 1, got '1.5'"},
        {"mood grief=0.5", ":7:6: unknown mood 'grief'; expected sadness, anger, joy or shame"},
        {"mood joy=0.2 joy=0.3", ":8:14: mood 'joy' is named twice"},
        {"mood sadness=0.8,anger=0.2", ":9:17: expected blanks between moods"},
        {"mood sadness", ":10:6: expected mood=intensity"},
        {"mood sadness=nan", ":11:6: sadness: expected an intensity from 0 to 1, got 'nan'"},
    };
    for (const auto& [line, expected] : bad) {
      feed(std::string(line) + "\n");
      QVERIFY2(stream.lastProblem().find(expected) != std::string::npos,
               stream.lastProblem().c_str());
    }
    QCOMPARE(stream.counters().malformed, 6LL);
    QCOMPARE(int(moods.size()), 3);
    feed("mood shame=0.5\n");
    QCOMPARE(moods.back()[Mood::Shame], 0.5);

    // A file holds frames only.
    try {
      FapReader::parse("2.1 a 22 1\nmood sadness=1\n" + mask({3}) + "\n0 1\n", "take.fap");
      QFAIL("expected an error");
    } catch (const FileError& e) {
      QVERIFY2(std::string(e.what()).starts_with("take.fap:2:1: a mood line is a live stream's"),
               e.what());
    }

    // One mood line per datagram.
    const FapDatagram d = decodeFapDatagram("mood anger=0.7\n", "udp");
    QVERIFY(d.mood);
    QCOMPARE((*d.mood)[Mood::Anger], 0.7);
    QVERIFY(!decodeFapDatagram(mask({19}) + "\n0 1", "udp").mood);
    for (const std::string& twice :
         {std::string("mood joy=1\nmood joy=0\n"), "mood joy=1\n" + mask({19}) + "\n0 1\n"}) {
      try {
        decodeFapDatagram(twice, "udp");
        QFAIL("expected an error");
      } catch (const FileError& e) {
        QVERIFY2(std::string(e.what()).find("one mood line") != std::string::npos, e.what());
      }
    }
  }

  void datagramHoldsOneFrame() {
    const FapDatagram d =
        decodeFapDatagram("2.1 greta 25 0\n" + mask({19, 69}, 70) + "\n3 80 12\n", "udp");
    QCOMPARE(d.frame.number, std::int64_t(3));
    QCOMPARE(d.frame.values[channelIndex(19)], 80.0F);
    QCOMPARE(d.frame.values[channelIndex(69)], 12.0F);
    QCOMPARE(*d.frameRate, 25.0);
    QVERIFY(!decodeFapDatagram(mask({19}) + "\n0 1", "udp").frameRate);

    for (const std::string& bad :
         {std::string(), mask({19}) + "\n", mask({19}) + "\n0 1\n" + mask({19}) + "\n0 1\n",
          std::string("\x01\x02garbage"), mask({69}, 70) + "\n0 -3\n"}) {
      try {
        decodeFapDatagram(bad, "udp");
        QFAIL("expected an error");
      } catch (const FileError& e) {
        QVERIFY(std::string(e.what()).starts_with("udp"));
      }
    }
  }
};

QTEST_GUILESS_MAIN(FapStreamTest)
#include "FapStreamTest.moc"
