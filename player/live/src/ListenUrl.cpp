#include <lacrima/live/ListenUrl.h>

#include <QRegularExpression>

namespace lacrima::live {

QString schemeOf(StreamKind kind) {
  switch (kind) {
    case StreamKind::FapTcp:
      return QStringLiteral("fap+tcp");
    case StreamKind::FapUdp:
      return QStringLiteral("fap+udp");
    case StreamKind::LiveLinkUdp:
      return QStringLiteral("livelink+udp");
  }
  return {};
}

QString ListenUrl::toString() const {
  const QString address = host.protocol() == QAbstractSocket::IPv6Protocol
                              ? QLatin1Char('[') + host.toString() + QLatin1Char(']')
                              : host.toString();
  return schemeOf(kind) + QStringLiteral("://") + address + QLatin1Char(':') +
         QString::number(port);
}

std::optional<ListenUrl> parseListenUrl(const QString& text, QString& error) {
  static const QRegularExpression form(
      QStringLiteral(R"(^([a-z+]+)://(\[[0-9a-fA-F:.]+\]|[^:/\[\]]*):([0-9]{1,5})/?$)"));
  const QRegularExpressionMatch m = form.match(text.trimmed());
  const QString expected =
      QStringLiteral(
          "expected fap+tcp://HOST:PORT, fap+udp://HOST:PORT or livelink+udp://HOST:PORT "
          "(HOST an IP address, left out for 127.0.0.1), not '%1'")
          .arg(text);
  if (!m.hasMatch()) {
    error = expected;
    return std::nullopt;
  }
  ListenUrl url;
  const QString scheme = m.captured(1);
  if (scheme == QLatin1String("fap+tcp")) {
    url.kind = StreamKind::FapTcp;
  } else if (scheme == QLatin1String("fap+udp")) {
    url.kind = StreamKind::FapUdp;
  } else if (scheme == QLatin1String("livelink+udp")) {
    url.kind = StreamKind::LiveLinkUdp;
  } else {
    error = expected;
    return std::nullopt;
  }
  QString host = m.captured(2);
  if (host.startsWith(QLatin1Char('['))) host = host.mid(1, host.size() - 2);
  if (host.isEmpty() || host == QLatin1String("localhost")) {
    url.host = QHostAddress(QHostAddress::LocalHost);
  } else if (!url.host.setAddress(host)) {
    error = QStringLiteral(
                "'%1' is not an IP address (give one, e.g. 127.0.0.1 or 0.0.0.0 for "
                "every interface)")
                .arg(host);
    return std::nullopt;
  }
  const int port = m.captured(3).toInt();
  if (port > 65535) {
    error = QStringLiteral("port %1 is above 65535").arg(port);
    return std::nullopt;
  }
  url.port = static_cast<quint16>(port);
  return url;
}

}  // namespace lacrima::live
