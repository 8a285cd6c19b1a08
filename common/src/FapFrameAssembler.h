#pragma once
// Turns the frames of a .fap file, in the order the file lists them, into a dense animation:
// places them by number, lets a later duplicate win, fills gaps, extends past nframes.
// Private to lacrima_common (used by FapReader).
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapAnimation.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lacrima::inline common::detail {

class FrameAssembler {
 public:
  FrameAssembler(const std::string& displayName, int maxFilledFrames);

  // nframes from the header and where it was written. `expectedFrames` only sizes the first
  // allocation, so callers must bound it by the input size.
  void setHeader(int headerFrames, int headerLine, int nframesColumn, std::size_t expectedFrames);

  // Starts the next frame of the file; returns its values, all 0, to fill in.
  FapValues& add(std::int64_t frameNumber, int line, int column);

  // High-level FAPs of the frame last added (the parallel list starts on first use).
  HighLevelFrame& highLevel();

  // Moves the dense frames into `animation` (frames, highLevel) and appends warnings.
  // Throws FileError when filling would invent more than maxFilledFrames frames.
  void finish(FapAnimation& animation, Warnings& warnings);

 private:
  struct Origin {
    std::int64_t number;
    int line;
    int column;
  };

  std::vector<int> slotsByNumber(std::int64_t maxFrame, Warnings& warnings) const;
  void checkFillable(std::int64_t missing, const Origin& culprit) const;
  void fillGaps(FapAnimation& animation, const std::vector<int>& slots, Warnings& warnings) const;
  SourceLocation at(int line, int column = 0) const { return {displayName_, line, column}; }

  const std::string& displayName_;
  int maxFilledFrames_;
  int headerFrames_ = 0;
  int headerLine_ = 0;
  int nframesColumn_ = 0;

  std::vector<FapValues> values_;     // in file order
  std::vector<HighLevelFrame> high_;  // in file order; empty until FAP 1 or 2 appears
  std::vector<Origin> origins_;       // in file order
  int firstBeyondHeader_ = -1;        // index in origins_ of the first number >= nframes
};

}  // namespace lacrima::inline common::detail
