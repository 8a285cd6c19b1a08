#pragma once
// Where a live input listens (or lacrima-send sends): `fap+tcp://HOST:PORT`,
// `fap+udp://HOST:PORT` or `livelink+udp://HOST:PORT`. HOST may be left out
// (`fap+tcp://:5555`): inputs then bind to loopback, 127.0.0.1, and reach no other machine
// unless the user names an address (0.0.0.0 for every interface). PORT 0 asks the system for a
// free port (tests, scripts: the input says which it got).
#include <QHostAddress>
#include <QString>

#include <optional>

namespace lacrima::live {

enum class StreamKind { FapTcp, FapUdp, LiveLinkUdp };

struct ListenUrl {
  StreamKind kind = StreamKind::FapTcp;
  QHostAddress host = QHostAddress::LocalHost;
  quint16 port = 0;

  // "fap+tcp://127.0.0.1:5555", as the user can type it again.
  QString toString() const;
  bool isLoopback() const { return host.isLoopback(); }
};

// The URL, or nullopt with `error` saying what was expected.
std::optional<ListenUrl> parseListenUrl(const QString& text, QString& error);

QString schemeOf(StreamKind kind);

}  // namespace lacrima::live
