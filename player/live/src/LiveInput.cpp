#include <lacrima/live/LiveInput.h>

#include <lacrima/common/FapTextStream.h>
#include <lacrima/common/MediaFiles.h>

#include <QNetworkDatagram>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUdpSocket>

#include <algorithm>
#include <chrono>
#include <list>
#include <stdexcept>

namespace lacrima::live {

namespace {

constexpr qint64 kReadChunk = 64 * 1024;
constexpr int kMaxRemotePeersListed = 16;

}  // namespace

double liveClockSeconds() {
  using Clock = std::chrono::steady_clock;
  static const Clock::time_point start = Clock::now();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

LiveLinkMapping defaultLiveLinkMapping() {
  return LiveLinkMapping::load(findMediaFile("livelink-mapping.json"));
}

struct LiveInput::Private {
  LiveInput* self;
  ListenUrl url;
  FrameHandler onFrame;
  MoodHandler onMood;
  InputCounters counters;
  QString lastProblem;
  LiveLinkMapping mapping;
  QStringList remote;

  QTcpServer* server = nullptr;
  struct Client {
    QPointer<QTcpSocket> socket;
    FapTextStream stream;
    FapStreamCounters seen;  // of stream, already added to counters
    bool scheduled = false;
  };
  std::list<Client> clients;

  QUdpSocket* udp = nullptr;
  double tokens = kMaxDatagramsPerSecond;  // datagrams that may still be decoded
  double refilled = 0;
  bool udpScheduled = false;

  void noteProblem(const std::string& text) { lastProblem = QString::fromStdString(text); }

  void notePeer(const QHostAddress& peer) {
    if (peer.isLoopback() || peer.isNull()) return;
    const QString text = peer.toString();
    if (!remote.contains(text) && remote.size() < kMaxRemotePeersListed) remote << text;
  }

  void deliver(const FapValues& values, const ChannelMask& mask, std::optional<double> rate) {
    ++counters.frames;
    LiveFrame frame;
    frame.values = values;
    frame.mask = mask;
    frame.arrival = liveClockSeconds();
    frame.frameRate = rate;
    if (onFrame) onFrame(frame);
  }

  void deliverMood(const MoodLevels& levels) {
    ++counters.moods;
    if (onMood) onMood(LiveMood{levels, liveClockSeconds()});
  }

  // --- TCP ---
  void accept() {
    while (QTcpSocket* socket = server->nextPendingConnection()) {
      if (static_cast<int>(clients.size()) >= kMaxClients) {
        ++counters.refused;
        lastProblem = QStringLiteral("%1: refused a connection from %2: %3 clients at most")
                          .arg(url.toString(), socket->peerAddress().toString())
                          .arg(kMaxClients);
        socket->abort();
        socket->deleteLater();
        continue;
      }
      ++counters.connections;
      notePeer(socket->peerAddress());
      socket->setReadBufferSize(kSocketBuffer);
      const QString name = url.toString() + QStringLiteral(" (") +
                           socket->peerAddress().toString() + QLatin1Char(':') +
                           QString::number(socket->peerPort()) + QLatin1Char(')');
      clients.push_back(Client{socket, FapTextStream(name.toStdString()), {}, false});
      Client* client = &clients.back();
      QObject::connect(socket, &QTcpSocket::readyRead, self, [this, client] { read(*client); });
      QObject::connect(socket, &QTcpSocket::disconnected, self, [this, client] { drop(*client); });
    }
    emit self->countersChanged();
  }

  bool alive(const Client* c) const {
    return std::any_of(clients.begin(), clients.end(), [c](const Client& o) { return &o == c; });
  }

  void read(Client& client) {
    client.scheduled = false;
    if (!client.socket) return;
    char chunk[kReadChunk];
    qint64 budget = kMaxBytesPerTurn;
    std::optional<double> rate;
    while (budget > 0 && client.socket->bytesAvailable() > 0) {
      const qint64 got = client.socket->read(chunk, std::min(kReadChunk, budget));
      if (got <= 0) break;
      budget -= got;
      counters.bytes += got;
      client.stream.feed(
          std::string_view(chunk, static_cast<std::size_t>(got)),
          [&](const FapTextFrame& frame) {
            deliver(frame.values, frame.mask, client.stream.frameRate());
          },
          [&](const MoodLevels& levels) { deliverMood(levels); });
    }
    account(client);
    // More waiting: go on in the next turn, after the window has had its own.
    if (client.socket->bytesAvailable() > 0 && !client.scheduled) {
      client.scheduled = true;
      QTimer::singleShot(0, self, [this, c = &client] {
        if (alive(c)) read(*c);
      });
    }
  }

  void account(Client& client) {
    const FapStreamCounters& now = client.stream.counters();
    counters.malformed += now.malformed - client.seen.malformed;
    counters.oversizedLines += now.oversizedLines - client.seen.oversizedLines;
    counters.truncated += now.truncated - client.seen.truncated;
    if (now.malformed != client.seen.malformed ||
        now.oversizedLines != client.seen.oversizedLines || now.truncated != client.seen.truncated)
      noteProblem(client.stream.lastProblem());
    client.seen = now;
    emit self->countersChanged();
  }

  void drop(Client& client) {
    if (client.socket && client.socket->bytesAvailable() > 0) read(client);
    client.stream.finish();
    ++counters.disconnects;
    account(client);
    if (client.socket) client.socket->deleteLater();
    // Erased after this turn: queued reads of this client may still be pending.
    QTimer::singleShot(0, self, [this, c = &client] {
      clients.remove_if([c](const Client& other) { return &other == c; });
    });
  }

  // --- UDP ---
  void readDatagrams() {
    udpScheduled = false;
    const double now = liveClockSeconds();
    tokens = std::min(kMaxDatagramsPerSecond, tokens + (now - refilled) * kMaxDatagramsPerSecond);
    refilled = now;
    const std::string name = url.toString().toStdString();
    for (int n = 0; n < kMaxDatagramsPerTurn && udp->hasPendingDatagrams(); ++n) {
      const QNetworkDatagram datagram = udp->receiveDatagram(65536);
      counters.bytes += datagram.data().size();
      notePeer(datagram.senderAddress());
      if (tokens < 1) {
        ++counters.flooded;
        continue;
      }
      tokens -= 1;
      const std::string_view bytes(datagram.data().constData(),
                                   static_cast<std::size_t>(datagram.data().size()));
      try {
        if (url.kind == StreamKind::LiveLinkUdp) {
          const LiveLinkPacket packet = decodeLiveLinkPacket(bytes, name);
          const double rate = packet.frameRate();
          deliver(mapping.retarget(packet), mapping.channels(),
                  rate > 0 ? std::optional<double>(rate) : std::nullopt);
        } else {
          const FapDatagram fap = decodeFapDatagram(bytes, name);
          if (fap.mood)
            deliverMood(*fap.mood);
          else
            deliver(fap.frame.values, fap.frame.mask, fap.frameRate);
        }
      } catch (const FileError& e) {
        ++counters.malformed;
        noteProblem(e.what());
      }
    }
    if (counters.flooded > 0 && lastProblem.isEmpty())
      lastProblem = url.toString() + QStringLiteral(
                                         ": datagrams arrive faster than %1 a second; "
                                         "the rest are dropped")
                                         .arg(kMaxDatagramsPerSecond);
    emit self->countersChanged();
    if (udp->hasPendingDatagrams() && !udpScheduled) {
      udpScheduled = true;
      QTimer::singleShot(0, self, [this] { readDatagrams(); });
    }
  }
};

LiveInput::LiveInput(const ListenUrl& url, FrameHandler onFrame, QObject* parent)
    : QObject(parent), d_(std::make_unique<Private>()) {
  d_->self = this;
  d_->url = url;
  d_->onFrame = std::move(onFrame);
  d_->refilled = liveClockSeconds();
  if (url.kind == StreamKind::LiveLinkUdp) d_->mapping = defaultLiveLinkMapping();
  if (url.kind == StreamKind::FapTcp) {
    d_->server = new QTcpServer(this);
    d_->server->setMaxPendingConnections(kMaxClients);
    if (!d_->server->listen(url.host, url.port)) {
      throw std::runtime_error(url.toString().toStdString() +
                               ": cannot listen: " + d_->server->errorString().toStdString());
    }
    d_->url.port = d_->server->serverPort();
    connect(d_->server, &QTcpServer::newConnection, this, [this] { d_->accept(); });
  } else {
    d_->udp = new QUdpSocket(this);
    if (!d_->udp->bind(url.host, url.port)) {
      throw std::runtime_error(url.toString().toStdString() +
                               ": cannot listen: " + d_->udp->errorString().toStdString());
    }
    d_->url.port = d_->udp->localPort();
    connect(d_->udp, &QUdpSocket::readyRead, this, [this] {
      if (!d_->udpScheduled) d_->readDatagrams();
    });
  }
}

LiveInput::~LiveInput() = default;

const ListenUrl& LiveInput::url() const { return d_->url; }
const InputCounters& LiveInput::counters() const { return d_->counters; }
const QString& LiveInput::lastProblem() const { return d_->lastProblem; }
QStringList LiveInput::remotePeers() const { return d_->remote; }
int LiveInput::connectedClients() const { return static_cast<int>(d_->clients.size()); }
void LiveInput::setMoodHandler(MoodHandler onMood) { d_->onMood = std::move(onMood); }
void LiveInput::setMapping(const LiveLinkMapping& mapping) { d_->mapping = mapping; }
const LiveLinkMapping& LiveInput::mapping() const { return d_->mapping; }

}  // namespace lacrima::live
