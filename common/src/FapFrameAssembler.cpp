#include "FapFrameAssembler.h"

#include "FapInterpolation.h"

#include <algorithm>

namespace lacrima::inline common::detail {

namespace {

std::string areMissing(std::size_t first, std::size_t last) {
  if (first == last) return "frame " + std::to_string(first) + " is missing";
  return "frames " + std::to_string(first) + "-" + std::to_string(last) + " are missing";
}

// The items of the frames in file order, placed by frame number (`slots`); missing ones default.
template <class Item>
std::vector<Item> byNumber(std::vector<Item>& listed, const std::vector<int>& slots, bool inOrder) {
  if (inOrder) {
    // The common case, frames 0..n-1 in order: already dense, so no copy.
    std::vector<Item> dense = std::move(listed);
    dense.resize(slots.size());
    return dense;
  }
  std::vector<Item> dense(slots.size());
  for (std::size_t f = 0; f < slots.size(); ++f)
    if (slots[f] >= 0) dense[f] = listed[static_cast<std::size_t>(slots[f])];
  listed = {};  // peak memory: the copy replaces the list as soon as it is made
  return dense;
}

}  // namespace

FrameAssembler::FrameAssembler(const std::string& displayName, int maxFilledFrames)
    : displayName_(displayName), maxFilledFrames_(maxFilledFrames) {}

void FrameAssembler::setHeader(int headerFrames, int headerLine, int nframesColumn,
                               std::size_t expectedFrames) {
  headerFrames_ = headerFrames;
  headerLine_ = headerLine;
  nframesColumn_ = nframesColumn;
  values_.reserve(expectedFrames);
  origins_.reserve(expectedFrames);
}

FapValues& FrameAssembler::add(std::int64_t frameNumber, int line, int column) {
  if (frameNumber >= headerFrames_ && firstBeyondHeader_ < 0)
    firstBeyondHeader_ = static_cast<int>(origins_.size());
  origins_.push_back({frameNumber, line, column});
  if (!high_.empty()) high_.emplace_back();
  return values_.emplace_back();
}

HighLevelFrame& FrameAssembler::highLevel() {
  if (high_.empty()) high_.resize(values_.size());
  return high_.back();
}

void FrameAssembler::finish(FapAnimation& animation, Warnings& warnings) {
  animation.frames.clear();
  animation.highLevel.clear();
  if (origins_.empty()) {
    if (headerFrames_ > 0) {
      warnings.push_back({at(headerLine_, nframesColumn_), "the header announces " +
                                                               std::to_string(headerFrames_) +
                                                               " frames but the file holds none"});
    }
    return;
  }

  const Origin& highest =
      *std::max_element(origins_.begin(), origins_.end(),
                        [](const Origin& a, const Origin& b) { return a.number < b.number; });
  const auto listed = static_cast<std::int64_t>(origins_.size());
  // At most `listed` distinct frames exist: check this bound before anything is sized by a
  // frame number, so a huge number costs nothing.
  checkFillable(highest.number + 1 - listed, highest);
  std::vector<int> slots = slotsByNumber(highest.number, warnings);
  const auto present = static_cast<std::int64_t>(
      std::count_if(slots.begin(), slots.end(), [](int s) { return s >= 0; }));
  checkFillable(highest.number + 1 - present, highest);

  const std::int64_t total = std::max<std::int64_t>(headerFrames_, highest.number + 1);
  if (total - present > maxFilledFrames_) {
    throw FileError(at(headerLine_, nframesColumn_),
                    "the header announces " + std::to_string(headerFrames_) +
                        " frames but the file holds " + std::to_string(present) +
                        ": filling the rest would invent more than " +
                        std::to_string(maxFilledFrames_) + " frames");
  }
  if (highest.number >= headerFrames_) {
    const Origin& first = origins_[static_cast<std::size_t>(firstBeyondHeader_)];
    warnings.push_back(
        {at(first.line, first.column),
         "frame " + std::to_string(first.number) + " is at or beyond the header's frame count " +
             std::to_string(headerFrames_) +
             (headerFrames_ > 0 ? " (frames 0-" + std::to_string(headerFrames_ - 1) + ")" : "") +
             ": the animation is extended to " + std::to_string(total) + " frames"});
  }

  bool inOrder = present == listed;
  for (std::size_t i = 0; inOrder && i < origins_.size(); ++i)
    inOrder = origins_[i].number == static_cast<std::int64_t>(i);

  slots.resize(static_cast<std::size_t>(total), -1);
  animation.frames = byNumber(values_, slots, inOrder);
  if (!high_.empty()) animation.highLevel = byNumber(high_, slots, inOrder);
  fillGaps(animation, slots, warnings);
}

void FrameAssembler::checkFillable(std::int64_t missing, const Origin& culprit) const {
  if (missing <= maxFilledFrames_) return;
  throw FileError(at(culprit.line, culprit.column),
                  "frame number " + std::to_string(culprit.number) +
                      " is too far beyond the frames in the file: filling the gap would invent " +
                      std::to_string(missing) + " frames (at most " +
                      std::to_string(maxFilledFrames_) + ")");
}

std::vector<int> FrameAssembler::slotsByNumber(std::int64_t maxFrame, Warnings& warnings) const {
  std::vector<int> slots(static_cast<std::size_t>(maxFrame + 1), -1);
  for (std::size_t i = 0; i < origins_.size(); ++i) {
    const Origin& o = origins_[i];
    int& slot = slots[static_cast<std::size_t>(o.number)];
    if (slot >= 0) {
      warnings.push_back({at(o.line, o.column),
                          "frame " + std::to_string(o.number) + " appears again (first at line " +
                              std::to_string(origins_[static_cast<std::size_t>(slot)].line) +
                              "): the later one wins"});
    }
    slot = static_cast<int>(i);
  }
  return slots;
}

void FrameAssembler::fillGaps(FapAnimation& animation, const std::vector<int>& slots,
                              Warnings& warnings) const {
  auto& frames = animation.frames;
  auto& high = animation.highLevel;
  const std::size_t total = slots.size();
  auto present = [&](std::size_t f) { return slots[f] >= 0; };
  auto lineOf = [&](std::size_t f) { return origins_[static_cast<std::size_t>(slots[f])].line; };

  for (std::size_t first = 0; first < total; ++first) {
    if (present(first)) continue;
    std::size_t end = first;  // one past the gap
    while (end < total && !present(end)) ++end;
    const bool held = first == 0 || end == total;
    // A gap always has a present frame on one side at least: the highest number is present.
    const std::size_t source = first > 0 ? first - 1 : end;
    for (std::size_t g = first; g < end; ++g) {
      if (held) {
        frames[g] = frames[source];
      } else {
        const double t = static_cast<double>(g - source) / static_cast<double>(end - source);
        blendFrames(frames[source], frames[end], t, frames[g]);
      }
      // High-level codes are never interpolated: the gap keeps the previous frame's.
      if (!high.empty()) high[g] = high[source];
    }

    const std::string missing = areMissing(first, end - 1);
    const std::string from = std::to_string(source);
    if (first == 0) {
      warnings.push_back(
          {at(lineOf(end)), missing + ": held at frame " + from + ", the first in the file"});
    } else if (end == total) {
      warnings.push_back({at(headerLine_, nframesColumn_),
                          missing + " (the header announces " + std::to_string(headerFrames_) +
                              " frames): held at frame " + from + ", the last in the file"});
    } else {
      warnings.push_back({at(lineOf(end)), missing +
                                               ": filled by linear interpolation between frames " +
                                               from + " and " + std::to_string(end)});
    }
    first = end;
  }
}

}  // namespace lacrima::inline common::detail
