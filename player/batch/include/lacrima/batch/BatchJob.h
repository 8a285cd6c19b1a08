#pragma once
// One job of a batch: what to animate, on which head, how, and what to write (docs/batch.md).
//
// A job's id comes from its content: the canonical text of its settings, in which every input
// file is named as the manifest writes it and fingerprinted by the SHA-256 of its bytes. The same
// job on another machine, under another mount point, has the same id; a changed input file gives
// a new one, so stale results are never taken for new ones.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::batch {

// What a job writes into its folder.
enum class Output { Frames, Masks, Alpha, Video, Gltf, TearMeshes };
inline constexpr int kOutputCount = 6;

std::string_view outputName(Output output);                 // "frames", ..., "tear-meshes"
std::optional<Output> outputByName(std::string_view name);  // the inverse
bool needsDisplay(Output output);                           // rendered through OGRE and X

// An input file: as the manifest names it, and where it is on this machine.
struct InputFile {
  std::string written;   // relative to the manifest's folder, or absolute, as written
  std::string resolved;  // absolute
  bool operator==(const InputFile&) const = default;
};

struct BatchJob {
  std::optional<InputFile> animation;  // a .fap file or a project; or
  std::string mood;                    // a take of the crying generator (lacrima-fap generate):
  std::uint64_t seed = 1;              // "sadness=0.8,anger=0.2" as toString(MoodLevels)
  double seconds = 10;                 // writes it; seed and seconds only count with it
  std::optional<InputFile> mesh, fdp;  // both or neither: the head (default: the file's)
  bool tears = true;                   // false: lacrima-player --no-tears
  std::string quality;                 // "", "preview", "balanced", "reference"
  std::string view = "framing";        // lacrima-player --view
  int width = 640, height = 360;
  int firstFrame = 0, lastFrame = -1;  // -1: to the end
  std::vector<Output> outputs;         // in kOutputCount order, no repeats
  bool operator==(const BatchJob&) const = default;

  bool wants(Output output) const;
  bool needsDisplay() const;
  std::string framesText() const;  // "0-109" or "all"
  // For people: "sadness=0.8 seed 3" or the animation's file name, then the settings.
  std::string label() const;
};

// SHA-256 of a file's bytes in hex; throws FileError when it cannot be read.
std::string fileSha256(const std::string& path);

// Compact JSON of the job's settings in a fixed order, every input file as written plus its
// "sha256" from `fingerprint` (path -> hex digest, memoised by the caller).
std::string canonicalJson(const BatchJob& job,
                          const std::function<std::string(const std::string&)>& fingerprint);

// The first 16 hex digits of the SHA-256 of canonicalJson: 64 bits, so a collision among even a
// million jobs has odds of about 1 in 40 million.
std::string jobId(const std::string& canonical);

}  // namespace lacrima::batch
