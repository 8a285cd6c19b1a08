#include <lacrima/export/RunStatistics.h>

#include <lacrima/common/JsonWriter.h>

#include <algorithm>
#include <cstdio>

namespace lacrima::exporting {

void RunStatistics::add(const playback::Playback& playback) {
  const playback::FrameProducer& producer = playback.producer();
  const int particles = producer.particleCount();
  ++frames;
  framesWithTears += particles > 0 ? 1 : 0;
  peakParticles = std::max(peakParticles, particles);
  // FNV-1a over the frame's hash, byte by byte, as tears::stateHash mixes particles.
  std::uint64_t frame = producer.tearStateHash();
  for (int byte = 0; byte < 8; ++byte, frame >>= 8)
    tearStateHash = (tearStateHash ^ (frame & 0xffu)) * 0x100000001b3ull;
}

std::string RunStatistics::toJson() const {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(tearStateHash));
  JsonWriter json;
  json.beginObject();
  json.field("frames", frames);
  json.field("frames_with_tears", framesWithTears);
  json.field("peak_particles", peakParticles);
  json.field("tear_state_hash", std::string_view(hash));
  json.endObject();
  return std::move(json).finish();
}

}  // namespace lacrima::exporting
