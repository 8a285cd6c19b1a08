#include <lacrima/editing/EditorModel.h>

#include "TouchedKeys.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditCommands.h>
#include <lacrima/editing/Mirror.h>
#include <lacrima/editing/PresetLibrary.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace lacrima::editing {
namespace {

// The project format's bound on channel values (ProjectDocument rejects larger ones).
constexpr double kValueLimit = 1e7;

QString channelName(int fap) {
  return QString::fromUtf8(fapInfo(fap).name.data(), static_cast<int>(fapInfo(fap).name.size()));
}

std::vector<double> timesOf(const std::vector<Keyframe>& keys) {
  std::vector<double> out;
  out.reserve(keys.size());
  for (const Keyframe& k : keys) out.push_back(k.time);
  return out;
}

// `onto` with the channels of `from` written over it; the default mode and time are `from`'s,
// and every channel keeps the shape it had in the key it comes from.
Keyframe mergedOnto(const Keyframe& onto, const Keyframe& from) {
  Keyframe out;
  out.time = from.time;
  out.interpolation = from.interpolation;
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (from.has(fap)) {
      out.takeChannel(from, fap);
    } else if (onto.has(fap)) {
      out.takeChannel(onto, fap);
    }
  }
  return out;
}

}  // namespace

EditorModel::EditorModel(QObject* parent) : QObject(parent) {}

EditorModel::~EditorModel() {
  // Commands refer to this model; clear them while it is still whole.
  undo_.clear();
}

void EditorModel::resetDocument(ProjectDocument document, bool clean) {
  undo_.clear();
  document_ = std::move(document);
  selection_.clear();
  channelKeys_.clear();
  animated_.reset();
  for (const Keyframe& key : document_.keys.keys()) animated_ |= key.channels;
  time_ = document_.keys.empty() ? 0.0 : document_.keys.startTime();
  refreshValues();
  if (clean) {
    undo_.setClean();
  } else {
    // An unsaved document (import, recovery) must show as modified: a clean stack at index 0
    // is reset by an invisible step that marks it dirty without adding history to undo.
    undo_.resetClean();
  }
  emit documentReset();
  emit layersChanged();
  emit moodsChanged();
  emit keysChanged();
  emit settingsChanged();
  emit selectionChanged();
  emit timeChanged(time_);
  emit valuesChanged();
}

// --- time ---------------------------------------------------------------------------------

double EditorModel::snapTime(double seconds) const {
  if (!std::isfinite(seconds)) seconds = 0.0;
  // Keys live within [0, kMaxKeyTime]: a project with a later key would not load again.
  seconds = std::clamp(seconds, 0.0, kMaxKeyTime);
  const double frame = frameDuration();
  const auto& keys = document_.keys.keys();
  const auto it = std::lower_bound(keys.begin(), keys.end(), seconds,
                                   [](const Keyframe& k, double t) { return k.time < t; });
  double nearestKey = -1.0;
  double nearestDistance = 0.5 * frame;
  for (auto k = (it == keys.begin() ? it : it - 1); k != keys.end() && k <= it; ++k) {
    const double d = std::abs(k->time - seconds);
    if (d < nearestDistance) {
      nearestDistance = d;
      nearestKey = k->time;
    }
  }
  if (nearestKey >= 0.0) return nearestKey;
  const double snapped = std::round(seconds * document_.fps) / document_.fps;
  return snapped <= kMaxKeyTime ? snapped : std::floor(kMaxKeyTime * document_.fps) / document_.fps;
}

double EditorModel::endTime() const {
  const auto [start, end] = document_.bakeRange();
  return start <= end ? end : 0.0;
}

int EditorModel::frameAt(double seconds) const {
  return static_cast<int>(std::lround(seconds * document_.fps));
}

void EditorModel::setCurrentTime(double seconds) { setCurrentTimeExact(snapTime(seconds)); }

void EditorModel::setCurrentTimeExact(double seconds) {
  if (!std::isfinite(seconds)) return;
  seconds = std::clamp(seconds, 0.0, kMaxKeyTime);
  if (seconds == time_) return;
  time_ = seconds;
  refreshValues();
  emit timeChanged(time_);
  emit valuesChanged();
}

void EditorModel::refreshValues() {
  keyedValues_ = document_.keys.evaluate(time_);
  try {
    values_ = document_.evaluate(time_, moodCache_);
  } catch (const std::invalid_argument&) {
    // A mood layer too long at the project's rate (more than kMaxBakedFrames frames, a rate
    // chosen since or a file opened to be fixed): it adds nothing until the rate or the layer
    // changes, as the player and exports refuse such a project with the figures.
    values_ = mixLayers(keyedValues_, document_.layers, time_);
  }
  for (int i = 0; i < kChannelCount; ++i)
    if (posed_.test(static_cast<std::size_t>(i)))
      values_[static_cast<std::size_t>(i)] = poseValues_[static_cast<std::size_t>(i)];
}

void EditorModel::setPosingOnly(bool on) {
  if (on == posingOnly_) return;
  posingOnly_ = on;
  const bool hadPose = posed_.any();
  posed_.reset();
  emit posingOnlyChanged(on);
  if (!hadPose) return;
  refreshValues();
  emit valuesChanged();
}

int EditorModel::currentKeyIndex() const { return findKey(document_.keys, time_); }

ChannelMask EditorModel::keyedAtCurrentTime() const {
  const int index = currentKeyIndex();
  return index < 0 ? ChannelMask{}
                   : document_.keys.keys()[static_cast<std::size_t>(index)].channels;
}

// --- selection ----------------------------------------------------------------------------

void EditorModel::setSelectedTimes(std::vector<double> times) {
  std::vector<double> valid;
  for (double t : times) {
    const int index = findKey(document_.keys, t);
    if (index >= 0) valid.push_back(document_.keys.keys()[static_cast<std::size_t>(index)].time);
  }
  std::sort(valid.begin(), valid.end());
  valid.erase(std::unique(valid.begin(), valid.end()), valid.end());
  if (valid == selection_) return;
  selection_ = std::move(valid);
  emit selectionChanged();
}

void EditorModel::setSelectedChannels(ChannelMask channels) {
  if (channels == selectedChannels_) return;
  selectedChannels_ = channels;
  emit selectedChannelsChanged();
}

bool EditorModel::isSelected(double keyTime) const {
  const auto it = std::lower_bound(selection_.begin(), selection_.end(), keyTime - kSameKeyTime);
  return it != selection_.end() && std::abs(*it - keyTime) < kSameKeyTime;
}

void EditorModel::selectAll() { setSelectedTimes(timesOf(document_.keys.keys())); }

void EditorModel::setSymmetricEdit(bool on) {
  if (on == symmetric_) return;
  symmetric_ = on;
  emit symmetricEditChanged(on);
}

void EditorModel::setFocusChannel(int fap) {
  if (!isValidFap(fap) || fap == focus_) return;
  focus_ = fap;
  emit focusChannelChanged(fap);
}

// --- edits --------------------------------------------------------------------------------

float EditorModel::sanitised(int fap, double value) const {
  if (!std::isfinite(value)) value = 0.0;
  if (isTearChannel(fap))
    return static_cast<float>(std::clamp(std::round(value), 0.0, double(kMaxTearParticles)));
  if (isHighLevelFap(fap))
    return static_cast<float>(std::clamp(std::round(value), 0.0, double(fapInfo(fap).sliderMax)));
  return static_cast<float>(std::clamp(value, -kValueLimit, kValueLimit));
}

Keyframe EditorModel::keyOrNewAt(double seconds) const {
  const int index = findKey(document_.keys, seconds);
  if (index >= 0) return document_.keys.keys()[static_cast<std::size_t>(index)];
  Keyframe key;
  key.time = seconds;
  key.interpolation = document_.defaultInterpolation;
  return key;
}

void EditorModel::pushKeyEdit(const KeyChange& change, const QString& text,
                              std::optional<std::vector<double>> selectionAfter) {
  if (change.isNoOp()) return;
  std::optional<std::vector<double>> before;
  if (selectionAfter) before = selection_;
  undo_.push(new KeyEditCommand(*this, change, text, std::move(before), std::move(selectionAfter)));
}

void EditorModel::editKeys(const KeyChange& change, const QString& text,
                           std::optional<std::vector<double>> selectionAfter,
                           std::optional<std::vector<ChannelKey>> channelKeysAfter) {
  if (!channelKeysAfter) {
    pushKeyEdit(change, text, std::move(selectionAfter));
    return;
  }
  if (change.isNoOp()) return;
  std::optional<std::vector<double>> before;
  if (selectionAfter) before = selection_;
  auto command = std::make_unique<KeyEditCommand>(*this, change, text, std::move(before),
                                                  std::move(selectionAfter));
  command->setChannelKeySelections(channelKeys_.keys(), std::move(*channelKeysAfter));
  undo_.push(command.release());  // the stack owns its commands
}

void EditorModel::setChannel(int fap, double value, int dragSession) {
  // The History names every channel the edit sets, the mirror one included.
  const auto partner = symmetric_ ? symmetricPartner(fap, static_cast<float>(value)) : std::nullopt;
  const QString text =
      partner ? QStringLiteral("Set %1 and %2").arg(channelName(fap), channelName(partner->first))
              : QStringLiteral("Set %1").arg(channelName(fap));
  setChannels({{fap, static_cast<float>(value)}}, text, dragSession);
}

void EditorModel::setChannels(std::vector<ChannelValue> values, const QString& text,
                              int dragSession) {
  if (symmetric_) {
    const std::size_t given = values.size();
    for (std::size_t i = 0; i < given; ++i) {
      const auto partner = symmetricPartner(values[i].first, values[i].second);
      if (!partner) continue;
      const bool listed =
          std::any_of(values.begin(), values.begin() + static_cast<long>(given),
                      [&](const ChannelValue& v) { return v.first == partner->first; });
      if (!listed) values.push_back(*partner);
    }
  }
  if (posingOnly_) {
    for (const auto& [fap, value] : values) {
      if (!isValidFap(fap)) continue;
      const auto i = static_cast<std::size_t>(channelIndex(fap));
      poseValues_[i] = values_[i] = sanitised(fap, value);
      posed_.set(i);
    }
    emit valuesChanged();
    return;
  }
  Keyframe key = keyOrNewAt(time_);
  ChannelMask channels;
  for (const auto& [fap, value] : values) {
    if (!isValidFap(fap)) continue;
    // Layers add onto the keys: key what makes the mix the value asked for.
    const int i = channelIndex(fap);
    key.set(fap, sanitised(fap, value - (values_[i] - keyedValues_[i])));
    channels.set(i);
  }
  if (channels.none()) return;
  const KeyChange change = planReplace(document_.keys, {}, std::span<const Keyframe>(&key, 1));
  if (change.isNoOp()) return;
  undo_.push(new SetChannelsCommand(*this, change, text, time_, channels, dragSession));
}

void EditorModel::resetChannels(std::span<const int> faps, const QString& text) {
  const ChannelMask keyed = keyedAtCurrentTime();
  std::vector<ChannelValue> zeros;
  for (int fap : faps)
    if (isValidFap(fap) && (currentValue(fap) != 0.0f || keyed.test(channelIndex(fap))))
      zeros.emplace_back(fap, 0.0f);
  if (zeros.empty()) return;
  const bool symmetric = symmetric_;
  symmetric_ = false;  // a reset names every channel it resets
  setChannels(std::move(zeros), text);
  symmetric_ = symmetric;
}

void EditorModel::unkeyChannel(int fap) {
  if (posingOnly_) {
    emit message(tr("Posing only: nothing is keyed here (Animate keys the animation)"));
    return;
  }
  const int index = currentKeyIndex();
  if (index < 0 || !isValidFap(fap)) return;
  Keyframe key = document_.keys.keys()[static_cast<std::size_t>(index)];
  if (!key.has(fap)) return;
  key.clear(fap);
  pushKeyEdit(planReplace(document_.keys, {}, std::span<const Keyframe>(&key, 1)),
              QStringLiteral("Remove %1 from key").arg(channelName(fap)), std::nullopt);
}

void EditorModel::addKey() {
  if (posingOnly_) {
    emit message(tr("Posing only: nothing is keyed here (Animate keys the animation)"));
    return;
  }
  if (animated_.none()) {
    emit message(tr("Nothing to key yet: move a slider or apply a preset first."));
    return;
  }
  Keyframe key = keyOrNewAt(time_);
  for (int fap = 1; fap <= kChannelCount; ++fap)
    if (animated_.test(channelIndex(fap))) key.set(fap, keyedValues_[channelIndex(fap)]);
  const std::vector<double> selection{time_};
  pushKeyEdit(planReplace(document_.keys, {}, std::span<const Keyframe>(&key, 1)), tr("Add key"),
              selection);
}

void EditorModel::deleteKeys(std::vector<double> times) {
  if (times.empty()) return;
  std::vector<double> remaining;
  for (double t : selection_)
    if (std::none_of(times.begin(), times.end(),
                     [&](double d) { return std::abs(d - t) < kSameKeyTime; }))
      remaining.push_back(t);
  const QString text =
      times.size() == 1 ? tr("Delete key") : tr("Delete %1 keys").arg(times.size());
  pushKeyEdit(planReplace(document_.keys, times, {}), text, remaining);
}

double EditorModel::shiftedTime(double seconds, int frames) const {
  return shiftedByFrames(seconds, frames, document_.fps);
}

void EditorModel::moveKeys(std::vector<double> times, int frames) {
  std::vector<Keyframe> moving;
  for (double t : times) {
    const int index = findKey(document_.keys, t);
    if (index >= 0) moving.push_back(document_.keys.keys()[static_cast<std::size_t>(index)]);
  }
  if (moving.empty() || frames == 0) return;
  std::sort(moving.begin(), moving.end(),
            [](const Keyframe& a, const Keyframe& b) { return a.time < b.time; });
  // Never before 0 s: the block stops at the start.
  const int earliestFrame =
      static_cast<int>(std::floor(moving.front().time * document_.fps + 1e-6));
  frames = std::max(frames, -earliestFrame);
  if (frames == 0) return;
  const std::vector<double> from = timesOf(moving);
  std::vector<Keyframe> written;
  for (const Keyframe& key : moving) {
    Keyframe moved = key;
    moved.time = std::max(0.0, shiftedTime(key.time, frames));
    const int there = findKey(document_.keys, moved.time);
    const bool stays =
        there >= 0 && std::none_of(from.begin(), from.end(), [&](double t) {
          return std::abs(t - document_.keys.keys()[static_cast<std::size_t>(there)].time) <
                 kSameKeyTime;
        });
    if (stays) moved = mergedOnto(document_.keys.keys()[static_cast<std::size_t>(there)], moved);
    written.push_back(moved);
  }
  const QString text = moving.size() == 1 ? tr("Move key") : tr("Move %1 keys").arg(moving.size());
  pushKeyEdit(planReplace(document_.keys, from, written), text, timesOf(written));
}

void EditorModel::pasteKeys(const std::vector<Keyframe>& clip, double at) {
  if (clip.empty()) return;
  std::vector<Keyframe> written;
  for (const Keyframe& key : clip) {
    Keyframe placed = key;
    placed.time = snapTime(at + key.time);
    const int there = findKey(document_.keys, placed.time);
    if (there >= 0)
      placed = mergedOnto(document_.keys.keys()[static_cast<std::size_t>(there)], placed);
    // Two clip keys snapping to one frame: the later one wins, as in a file.
    written.push_back(placed);
  }
  const QString text = clip.size() == 1 ? tr("Paste key") : tr("Paste %1 keys").arg(clip.size());
  pushKeyEdit(planReplace(document_.keys, {}, written), text, timesOf(written));
}

void EditorModel::setInterpolation(std::vector<double> times, Interpolation mode) {
  std::vector<Keyframe> written;
  for (double t : times) {
    const int index = findKey(document_.keys, t);
    if (index < 0) continue;
    Keyframe key = document_.keys.keys()[static_cast<std::size_t>(index)];
    key.interpolation = mode;
    written.push_back(key);
  }
  if (written.empty()) return;
  const QString text = mode == Interpolation::Smooth ? tr("Make smooth") : tr("Make linear");
  pushKeyEdit(planReplace(document_.keys, {}, written), text, std::nullopt);
}

void EditorModel::applyPreset(const Preset& preset, double intensity, bool replacePose) {
  if (preset.keys.empty()) return;
  intensity = std::clamp(std::isfinite(intensity) ? intensity : 1.0, 0.0, 2.0);
  const auto scaled = [&](int fap, float v) {
    return isHighLevelFap(fap) ? v : sanitised(fap, v * intensity);
  };
  std::vector<Keyframe> written;
  for (std::size_t k = 0; k < preset.keys.size(); ++k) {
    const Keyframe& source = preset.keys[k];
    const double at = k == 0 ? time_ : snapTime(time_ + source.time);
    Keyframe key = keyOrNewAt(at);
    if (!written.empty() && std::abs(written.back().time - key.time) < kSameKeyTime) continue;
    if (k == 0 && replacePose) {
      for (int fap = 1; fap <= kChannelCount; ++fap)
        if (!source.has(fap) && keyedValues_[channelIndex(fap)] != 0.0f) key.set(fap, 0.0f);
    }
    for (int fap = 1; fap <= kChannelCount; ++fap)
      if (source.has(fap)) key.set(fap, scaled(fap, source.value(fap)));
    // A sequence carries its own modes; a pose keeps the key's (or the project's default).
    if (preset.isSequence()) key.interpolation = source.interpolation;
    written.push_back(key);
  }
  const std::vector<double> selection = timesOf(written);
  if (std::optional<Keyframe> hold = holdBefore(written.front())) written.push_back(*hold);
  pushKeyEdit(planReplace(document_.keys, {}, written),
              tr("Apply %1").arg(QString::fromStdString(preset.name)), selection);
}

// A channel holds its first key's value before that key, so a pose keyed at t on channels with
// no key before t would also show before t, back to frame 0. Where an earlier key exists, those
// channels are keyed there too, at the value they had: the animation up to that key stays
// exactly what it was, and the new pose rises from it.
std::optional<Keyframe> EditorModel::holdBefore(const Keyframe& pose) const {
  const auto& keys = document_.keys.keys();
  const auto firstAtPose = std::partition_point(keys.begin(), keys.end(), [&](const Keyframe& k) {
    return k.time < pose.time - kSameKeyTime;
  });
  if (firstAtPose == keys.begin()) return std::nullopt;
  ChannelMask keyedBefore;
  for (auto it = keys.begin(); it != firstAtPose; ++it) keyedBefore |= it->channels;
  const ChannelMask unheld = pose.channels & ~keyedBefore;
  if (unheld.none()) return std::nullopt;
  Keyframe hold = *std::prev(firstAtPose);
  const FapValues before = document_.keys.evaluate(hold.time);
  for (int i = 0; i < kChannelCount; ++i) {
    if (unheld.test(i)) hold.set(fapNumber(i), before[i]);
  }
  return hold;
}

void EditorModel::mirror() {
  std::vector<Keyframe> written;
  for (double t : selection_) {
    const int index = findKey(document_.keys, t);
    if (index >= 0)
      written.push_back(mirrored(document_.keys.keys()[static_cast<std::size_t>(index)]));
  }
  if (written.empty()) {
    const int index = currentKeyIndex();
    if (index >= 0) {
      written.push_back(mirrored(document_.keys.keys()[static_cast<std::size_t>(index)]));
    } else {
      Keyframe pose = keyOrNewAt(time_);
      for (int fap = 1; fap <= kChannelCount; ++fap)
        if (animated_.test(channelIndex(fap))) pose.set(fap, keyedValues_[channelIndex(fap)]);
      if (pose.channels.none()) {
        emit message(tr("Nothing to mirror: the face is neutral."));
        return;
      }
      written.push_back(mirrored(pose));
    }
  }
  pushKeyEdit(planReplace(document_.keys, {}, written), tr("Mirror left/right"), std::nullopt);
}

void EditorModel::setSettings(const ProjectDocument& settings, const QString& text) {
  ProjectDocument before = document_;
  ProjectDocument after = settings;
  before.keys = {};
  after.keys = {};
  if (before == after) return;
  undo_.push(new SettingsCommand(*this, std::move(before), std::move(after), text));
}

// --- applied by commands ------------------------------------------------------------------

void EditorModel::applyKeyChange(const KeyChange& change, bool redo) {
  applyKeys(document_.keys, change.times, redo ? change.after : change.before);
  animated_.reset();
  for (const Keyframe& key : document_.keys.keys()) animated_ |= key.channels;
  // Keys that vanished leave the selection.
  std::vector<double> kept;
  for (double t : selection_)
    if (findKey(document_.keys, t) >= 0) kept.push_back(t);
  if (kept != selection_) {
    selection_ = std::move(kept);
    emit selectionChanged();
  }
  channelKeys_.prune();
  refreshValues();
  emit keysChanged();
  emit valuesChanged();
}

void EditorModel::applySettings(const ProjectDocument& settings) {
  const double oldFps = document_.fps;
  document_.name = settings.name;
  document_.fps = settings.fps;
  document_.defaultInterpolation = settings.defaultInterpolation;
  document_.tearSources = settings.tearSources;
  document_.scene = settings.scene;
  document_.head = settings.head;
  emit settingsChanged();
  if (oldFps != document_.fps) {
    setCurrentTime(time_);
    refreshValues();  // a mood layer is generated at the project's rate
    emit valuesChanged();
  }
}

}  // namespace lacrima::editing
