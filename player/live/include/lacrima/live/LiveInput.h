#pragma once
// One live input: a socket listening at a ListenUrl, decoding what arrives into FAP frames. TCP
// streams go through FapTextStream, datagrams through decodeFapDatagram or
// decodeLiveLinkPacket (then the Live Link mapping), so every problem is counted, never thrown,
// and the input goes on.
//
// It runs on the Qt event loop of its thread and never blocks it: a turn reads at most
// kMaxBytesPerTurn of a connection or kMaxDatagramsPerTurn datagrams, and goes on in the next
// turn. Memory is bounded whatever peers send: each connection holds at most its socket buffer
// (kSocketBuffer) and one line; at most kMaxClients connections are served (more are refused);
// datagrams beyond kMaxDatagramsPerSecond are read and dropped (counted as a flood).
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/LiveLinkMapping.h>
#include <lacrima/common/mood/Moods.h>
#include <lacrima/live/ListenUrl.h>

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace lacrima::live {

// Seconds of a steady clock shared by inputs, sources and recorders of this process.
double liveClockSeconds();

struct LiveFrame {
  FapValues values{};
  ChannelMask mask;                 // channels the frame sets; the rest are neutral
  double arrival = 0;               // liveClockSeconds() when it was decoded
  std::optional<double> frameRate;  // the rate the stream names, when it names one
};

// A mood line of a FAP stream (docs/live.md): the crying generator's moods, in place of frames.
struct LiveMood {
  MoodLevels levels;
  double arrival = 0;  // liveClockSeconds() when it was decoded
};

struct InputCounters {
  long long frames = 0;
  long long moods = 0;           // mood lines read
  long long malformed = 0;       // lines or datagrams refused
  long long oversizedLines = 0;  // lines over the limit, skipped
  long long truncated = 0;       // connections that ended inside a frame
  long long flooded = 0;         // datagrams dropped over the rate limit
  long long connections = 0;     // accepted so far
  long long disconnects = 0;
  long long refused = 0;  // connections over kMaxClients
  long long bytes = 0;
  long long problems() const { return malformed + oversizedLines + truncated + flooded + refused; }
};

class LiveInput : public QObject {
  Q_OBJECT
 public:
  static constexpr int kMaxClients = 8;
  static constexpr qint64 kSocketBuffer = 256 * 1024;
  static constexpr qint64 kMaxBytesPerTurn = 1 << 20;
  static constexpr int kMaxDatagramsPerTurn = 1024;
  static constexpr double kMaxDatagramsPerSecond = 2000;

  using FrameHandler = std::function<void(const LiveFrame&)>;
  using MoodHandler = std::function<void(const LiveMood&)>;

  // Binds now; throws std::runtime_error naming the URL and the system's reason when it cannot.
  LiveInput(const ListenUrl& url, FrameHandler onFrame, QObject* parent = nullptr);
  ~LiveInput() override;

  // The URL as bound (the port the system chose for port 0).
  const ListenUrl& url() const;
  const InputCounters& counters() const;
  // The last problem in words ("fap+tcp://...:3:5: expected ..."); empty when none.
  const QString& lastProblem() const;
  // Peers from other machines that sent something (a loopback peer is not listed).
  QStringList remotePeers() const;
  int connectedClients() const;
  // Where mood lines go (none by default: they are counted, then ignored).
  void setMoodHandler(MoodHandler onMood);
  // Live Link inputs: the table from blendshapes to FAPs (the shipped one until set).
  void setMapping(const LiveLinkMapping& mapping);
  const LiveLinkMapping& mapping() const;

 signals:
  void countersChanged();

 private:
  struct Private;
  std::unique_ptr<Private> d_;
};

// The Live Link mapping shipped in media/ (livelink-mapping.json), found like every media file.
LiveLinkMapping defaultLiveLinkMapping();

}  // namespace lacrima::live
