// lacrima-send: streams a .fap file or a Lacrima project to a live input in real time, in the
// FAP text formats the player listens to (docs/live.md): over TCP the file's own text (its
// header, then a mask line and a value line per frame), over UDP one frame per datagram (with
// the header line, so every datagram names the rate). With --mood it sends one mood line instead
// (`mood sadness=0.8 anger=0 joy=0 shame=0`): the player's crying generator then drives the
// face. Exit codes as the other tools: 0 success,
// 1 bad input or a failed connection, 2 wrong usage.
#include <lacrima/common/CommandLineNumbers.h>
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/common/ProjectPath.h>
#include <lacrima/common/mood/Moods.h>
#include <lacrima/live/ListenUrl.h>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTcpSocket>
#include <QThread>
#include <QUdpSocket>

#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

using namespace lacrima;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

FapAnimation loadAnimation(const std::string& path) {
  if (isProjectPath(path)) return ProjectDocument::load(path, ProjectDocument::Use::Bake).bake();
  FapReadResult read = FapReader::readFile(path);
  for (const Diagnostic& w : read.warnings)
    std::fprintf(stderr, "warning: %s\n", w.toString().c_str());
  return std::move(read.animation);
}

// The portable text of the animation (FapWriter), cut into its header and one piece per frame
// (its mask line and value line).
struct FramesText {
  std::string header;
  std::vector<std::string> frames;
};

FramesText frameTexts(const FapAnimation& animation) {
  const std::string text = FapWriter::toText(animation);
  FramesText out;
  std::size_t at = text.find('\n') + 1;
  out.header = text.substr(0, at);
  while (at < text.size()) {
    const std::size_t maskEnd = text.find('\n', at) + 1;
    const std::size_t valueEnd = text.find('\n', maskEnd) + 1;
    out.frames.push_back(text.substr(at, valueEnd - at));
    at = valueEnd;
  }
  return out;
}

// The mood line of docs/live.md, every mood named (a line sets all four).
std::string moodLine(const MoodLevels& levels) {
  std::string line = "mood";
  for (Mood mood : kMoods) {
    char number[32];
    const auto [end, ec] = std::to_chars(number, number + sizeof number, levels[mood]);
    line += ' ' + std::string(moodName(mood)) + '=' + std::string(number, end);
  }
  return line + '\n';
}

// Sends `line` once; false after saying why it could not.
bool sendLine(const live::ListenUrl& url, const std::string& line) {
  if (url.kind == live::StreamKind::FapUdp) {
    QUdpSocket udp;
    if (udp.writeDatagram(line.data(), static_cast<qint64>(line.size()), url.host, url.port) < 0) {
      std::fprintf(stderr, "lacrima-send: %s: %s\n", qPrintable(url.toString()),
                   qPrintable(udp.errorString()));
      return false;
    }
    return true;
  }
  QTcpSocket tcp;
  tcp.connectToHost(url.host, url.port);
  if (!tcp.waitForConnected(5000)) {
    std::fprintf(stderr, "lacrima-send: %s: cannot connect: %s\n", qPrintable(url.toString()),
                 qPrintable(tcp.errorString()));
    return false;
  }
  tcp.write(line.data(), static_cast<qint64>(line.size()));
  if (!tcp.waitForBytesWritten(5000) && tcp.bytesToWrite() > 0) {
    std::fprintf(stderr, "lacrima-send: %s: %s\n", qPrintable(url.toString()),
                 qPrintable(tcp.errorString()));
    return false;
  }
  tcp.disconnectFromHost();
  if (tcp.state() != QAbstractSocket::UnconnectedState) tcp.waitForDisconnected(2000);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("lacrima-send");
  QCoreApplication::setApplicationVersion(LACRIMA_VERSION);
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Streams a FAP file or a Lacrima project to a live input in real time, so a player can\n"
      "be tried without an agent:\n\n"
      "  lacrima-player --listen fap+tcp://127.0.0.1:5555 &\n"
      "  lacrima-send media/demo/crying.fap --to fap+tcp://127.0.0.1:5555\n\n"
      "fap+tcp sends the FAP text (header, then a mask line and a value line per frame);\n"
      "fap+udp sends one frame per datagram, each with the header line.\n\n"
      "Or set the player's crying generator with a mood line (docs/live.md):\n\n"
      "  lacrima-send --mood sadness=0.8,anger=0.2 --to fap+tcp://127.0.0.1:5555\n\n"
      "Exit codes: 0 success, 1 bad input or failed connection, 2 wrong usage.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("FILE", "A .fap file or a project (.lacrima or .json).", "[FILE]");
  parser.addOptions({
      {"to", "Where to send: fap+tcp://HOST:PORT or fap+udp://HOST:PORT.", "URL"},
      {"rate", "Frames per second (default: the file's).", "FPS"},
      {"loop", "Start again from the first frame at the end, until interrupted."},
      {"mood",
       "Send one mood line instead of a FILE: sadness, anger, joy, shame, each 0..1 (moods not "
       "named are 0).",
       "MOODS"},
  });
  parser.process(app);
  const QStringList files = parser.positionalArguments();
  const bool mood = parser.isSet("mood");
  if (files.size() != (mood ? 0 : 1) || !parser.isSet("to")) {
    std::fprintf(stderr,
                 "lacrima-send: give one FILE or --mood MOODS, and --to URL (see --help)\n");
    return kExitUsage;
  }
  if (mood && (parser.isSet("rate") || parser.isSet("loop"))) {
    std::fprintf(stderr, "lacrima-send: --rate and --loop go with a FILE, not --mood\n");
    return kExitUsage;
  }
  MoodLevels levels;
  if (mood) {
    try {
      levels = parseMoodLevels(parser.value("mood").toStdString());
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "lacrima-send: --mood: %s\n", e.what());
      return kExitUsage;
    }
  }
  QString error;
  const std::optional<live::ListenUrl> url = live::parseListenUrl(parser.value("to"), error);
  if (!url || url->kind == live::StreamKind::LiveLinkUdp || url->port == 0) {
    std::fprintf(
        stderr, "lacrima-send: --to: %s\n",
        (url ? QStringLiteral("expected fap+tcp or fap+udp and a port other than 0, not '%1'")
                   .arg(parser.value("to"))
             : error)
            .toLocal8Bit()
            .constData());
    return kExitUsage;
  }
  if (mood) {
    const std::string line = moodLine(levels);
    if (!sendLine(*url, line)) return kExitBadInput;
    std::fprintf(stderr, "lacrima-send: sent '%.*s' to %s\n", static_cast<int>(line.size() - 1),
                 line.data(), qPrintable(url->toString()));
    return kExitOk;
  }
  FapAnimation animation;
  try {
    animation = loadAnimation(files.front().toStdString());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-send: %s\n", e.what());
    return kExitBadInput;
  }
  if (parser.isSet("rate")) {
    std::string rateError;
    const std::optional<double> rate = readNumberOption(
        "--rate", "frames per second", parser.value("rate").toStdString(), 0.1, 1000, rateError);
    if (!rate) {
      std::fprintf(stderr, "lacrima-send: %s\n", rateError.c_str());
      return kExitUsage;
    }
    animation.fps = *rate;
  }
  const FramesText text = frameTexts(animation);
  if (text.frames.empty()) {
    std::fprintf(stderr, "lacrima-send: %s holds no frames\n", qPrintable(files.front()));
    return kExitBadInput;
  }

  QTcpSocket tcp;
  QUdpSocket udp;
  const bool overTcp = url->kind == live::StreamKind::FapTcp;
  if (overTcp) {
    tcp.connectToHost(url->host, url->port);
    if (!tcp.waitForConnected(5000)) {
      std::fprintf(stderr, "lacrima-send: %s: cannot connect: %s\n", qPrintable(url->toString()),
                   qPrintable(tcp.errorString()));
      return kExitBadInput;
    }
    tcp.write(text.header.data(), static_cast<qint64>(text.header.size()));
  }
  std::fprintf(stderr, "lacrima-send: %zu frames at %g fps to %s%s\n", text.frames.size(),
               animation.fps, qPrintable(url->toString()), parser.isSet("loop") ? ", looping" : "");
  QElapsedTimer clock;
  clock.start();
  long long sent = 0;
  do {
    for (const std::string& frame : text.frames) {
      // Frame `sent` leaves at sent / fps seconds: late frames go at once, none is skipped.
      const qint64 due = static_cast<qint64>(static_cast<double>(sent) * 1e9 / animation.fps);
      const qint64 wait = due - clock.nsecsElapsed();
      if (wait > 0) QThread::usleep(static_cast<unsigned long>(wait / 1000));
      if (overTcp) {
        tcp.write(frame.data(), static_cast<qint64>(frame.size()));
        if (!tcp.waitForBytesWritten(5000) && tcp.bytesToWrite() > 0) {
          std::fprintf(stderr, "lacrima-send: %s: %s\n", qPrintable(url->toString()),
                       qPrintable(tcp.errorString()));
          return kExitBadInput;
        }
      } else {
        const std::string datagram = text.header + frame;
        udp.writeDatagram(datagram.data(), static_cast<qint64>(datagram.size()), url->host,
                          url->port);
      }
      ++sent;
    }
  } while (parser.isSet("loop"));
  if (overTcp) {
    tcp.disconnectFromHost();
    if (tcp.state() != QAbstractSocket::UnconnectedState) tcp.waitForDisconnected(2000);
  }
  std::fprintf(stderr, "lacrima-send: sent %lld frames in %.2f s\n", sent,
               clock.elapsed() / 1000.0);
  return kExitOk;
}
