#include <lacrima/live/LiveSession.h>

namespace lacrima::live {

LiveSession::LiveSession(QObject* parent) : QObject(parent) {}
LiveSession::~LiveSession() = default;

LiveInput& LiveSession::listen(const ListenUrl& url) {
  auto input = std::make_unique<LiveInput>(
      url,
      [this](const LiveFrame& frame) {
        ++frames_;
        lastActivity_ = frame.arrival;
        if (recorder_) recorder_->add(frame);
        if (handler_) handler_(frame);
        emit frameArrived();
      },
      this);
  input->setMoodHandler([this](const LiveMood& mood) {
    lastActivity_ = mood.arrival;
    if (moodHandler_) moodHandler_(mood);
    emit frameArrived();
  });
  if (mappingSet_ && url.kind == StreamKind::LiveLinkUdp) input->setMapping(mapping_);
  connect(input.get(), &LiveInput::countersChanged, this, &LiveSession::countersChanged);
  if (inputs_.empty()) lastActivity_ = liveClockSeconds();
  inputs_.push_back(std::move(input));
  return *inputs_.back();
}

void LiveSession::stopListening() { inputs_.clear(); }

void LiveSession::setMapping(const LiveLinkMapping& mapping) {
  mapping_ = mapping;
  mappingSet_ = true;
  for (const auto& input : inputs_)
    if (input->url().kind == StreamKind::LiveLinkUdp) input->setMapping(mapping);
}

void LiveSession::startRecording(const std::string& path, std::optional<double> rate) {
  recorder_ = std::make_unique<LiveRecorder>(path, rate);
}

bool LiveSession::stopRecording() {
  if (!recorder_) return false;
  const std::unique_ptr<LiveRecorder> recorder = std::move(recorder_);
  return recorder->stop();
}

void LiveSession::recordGenerated(const FapValues& values, double arrival) {
  if (!recorder_) return;
  LiveFrame frame;
  frame.values = values;
  frame.arrival = arrival;
  for (int i = 0; i < kChannelCount; ++i)
    if (values[static_cast<std::size_t>(i)] != 0) frame.mask.set(i);
  recorder_->add(frame);
}

InputCounters LiveSession::totals() const {
  InputCounters sum;
  for (const auto& input : inputs_) {
    const InputCounters& c = input->counters();
    sum.frames += c.frames;
    sum.moods += c.moods;
    sum.malformed += c.malformed;
    sum.oversizedLines += c.oversizedLines;
    sum.truncated += c.truncated;
    sum.flooded += c.flooded;
    sum.connections += c.connections;
    sum.disconnects += c.disconnects;
    sum.refused += c.refused;
    sum.bytes += c.bytes;
  }
  return sum;
}

double LiveSession::idleSeconds() const { return liveClockSeconds() - lastActivity_; }

namespace {

QString counted(long long n, const char* one, const char* many) {
  return QStringLiteral("%1 %2").arg(n).arg(QLatin1String(n == 1 ? one : many));
}

}  // namespace

QString LiveSession::statusText() const {
  QStringList lines;
  for (const auto& input : inputs_) {
    const InputCounters& c = input->counters();
    QStringList parts;
    if (input->url().kind == StreamKind::FapTcp)
      parts << counted(input->connectedClients(), "client", "clients");
    parts << counted(c.frames, "frame", "frames");
    const auto add = [&](long long n, const QString& what) {
      if (n > 0) parts << QStringLiteral("%1 %2").arg(n).arg(what);
    };
    add(c.moods, c.moods == 1 ? tr("mood line") : tr("mood lines"));
    add(c.malformed, tr("malformed"));
    add(c.oversizedLines, tr("over-long lines"));
    add(c.truncated, tr("cut off mid-frame"));
    add(c.flooded, tr("dropped (flood)"));
    add(c.refused, tr("connections refused"));
    add(c.disconnects, tr("disconnects"));
    QString line =
        input->url().toString() + QStringLiteral(": ") + parts.join(QStringLiteral(", "));
    if (!input->url().isLoopback()) line += tr(" [reachable from other machines]");
    if (!input->remotePeers().isEmpty())
      line += tr(" [remote: %1]").arg(input->remotePeers().join(QStringLiteral(", ")));
    if (!input->lastProblem().isEmpty())
      line += tr(" (last problem: %1)").arg(input->lastProblem());
    lines << line;
  }
  return lines.join(QLatin1Char('\n'));
}

}  // namespace lacrima::live
