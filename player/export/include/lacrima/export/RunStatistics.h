#pragma once
// What a run simulated, in a form two runs can be compared by: lacrima-player --stats writes it
// and lacrima-batch keeps it in each job's job.json. The tear state hash chains every frame's
// FrameProducer::tearStateHash, so two runs with the same hash simulated the same particles at
// every frame shown, not only at the last.
#include <lacrima/playback/Playback.h>

#include <cstdint>
#include <string>

namespace lacrima::exporting {

struct RunStatistics {
  int frames = 0;
  int framesWithTears = 0;  // frames with at least one particle
  int peakParticles = 0;
  std::uint64_t tearStateHash = 0xcbf29ce484222325ull;  // FNV-1a's offset basis: no frame yet

  // Takes the frame `playback` shows now.
  void add(const playback::Playback& playback);
  // {"frames": ..., "frames_with_tears": ..., "peak_particles": ..., "tear_state_hash": "16 hex"}
  std::string toJson() const;
};

}  // namespace lacrima::exporting
