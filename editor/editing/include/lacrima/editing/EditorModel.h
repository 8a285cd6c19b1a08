#pragma once
// The editor's document model: the project, the current time, the key selection and the undo
// history. Widgets read from it and edit through it: every edit is one QUndoCommand
// (EditCommands.h) pushed on undoStack(), and only those commands change the document (the
// functions they apply it with are private to them).
//
// Editing follows the animator's "auto key" habit: the sliders always show the animation at
// the current time, and moving one writes that channel into the key at the current time,
// creating the key when there is none (it then holds only that channel, so the other channels
// keep interpolating through it). K keys every animated channel at its current value.
//
// Time is snapped to the project's frame grid (1 / fps), except that a key within half a frame
// is snapped to exactly, so keys written at off-grid times (hand-edited files) stay editable.
// Playback sets exact times.
//
// Selection is by key time (times identify keys: at most one key per time). Commands that
// move keys carry the selection with them, so undo and redo also restore what was selected.
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/editing/ChannelKeySelection.h>
#include <lacrima/editing/KeyChange.h>

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace lacrima::editing {

struct Preset;
struct MoodGenerationRequest;

// What a mood layer edit changes: the layer, and the colour curves a bake keys.
struct MoodLayerState {
  std::optional<MoodLayer> layer;
  FaceColourCurves colours;
  bool operator==(const MoodLayerState&) const = default;
};

// A channel and the value to write.
using ChannelValue = std::pair<int, float>;

class KeyEditCommand;
class LayersCommand;
class MoodsCommand;
class MoodLayerCommand;
class SettingsCommand;

class EditorModel : public QObject {
  Q_OBJECT
 public:
  explicit EditorModel(QObject* parent = nullptr);
  ~EditorModel() override;

  const ProjectDocument& document() const { return document_; }
  QUndoStack* undoStack() { return &undo_; }
  bool isModified() const { return !undo_.isClean(); }

  // New, open, import, recover: replaces the document, clears the history and the selection,
  // goes to the first key. `clean`: the document is what is on disk.
  void resetDocument(ProjectDocument document, bool clean);
  void markSaved() { undo_.setClean(); }

  // --- time -------------------------------------------------------------------------------
  double currentTime() const { return time_; }
  void setCurrentTime(double seconds);       // snapped, clamped to >= 0
  void setCurrentTimeExact(double seconds);  // playback
  double snapTime(double seconds) const;
  double frameDuration() const { return 1.0 / document_.fps; }
  int frameAt(double seconds) const;  // nearest frame number
  // The end of what plays (ProjectDocument::bakeRange): the last key, or a layer's later end
  // (the crying layer's, a pose layer's last intensity key); 0 when nothing plays.
  double endTime() const;

  // --- values at the current time -----------------------------------------------------
  // What the face shows: the keys with the layers mixed on (sliders show these; a slider edit
  // keys the value that makes the mix what the user set).
  const FapValues& currentValues() const { return values_; }
  // The keys' own values, without the layers.
  const FapValues& keyedValues() const { return keyedValues_; }
  float currentValue(int fap) const { return values_[channelIndex(fap)]; }
  int currentKeyIndex() const;             // key at the current time, or -1
  ChannelMask keyedAtCurrentTime() const;  // channels of that key
  const ChannelMask& animatedChannels() const { return animated_; }  // union over all keys

  // --- selection ----------------------------------------------------------------------
  const std::vector<double>& selectedTimes() const { return selection_; }
  void setSelectedTimes(std::vector<double> times);  // unknown times are dropped
  bool isSelected(double keyTime) const;
  void selectAll();
  void clearSelection() { setSelectedTimes({}); }

  // Channel keys selected in the dope sheet or the graph editor (ChannelKeySelection.h); the
  // model drops those an edit removes and clears it with the document.
  ChannelKeySelection& channelKeySelection() { return channelKeys_; }
  const ChannelKeySelection& channelKeySelection() const { return channelKeys_; }
  // The channels the graph editor draws (chosen in the dope sheet or the channel list).
  const ChannelMask& selectedChannels() const { return selectedChannels_; }
  void setSelectedChannels(ChannelMask channels);

  // --- posing without keys ---------------------------------------------------------------
  // Checking a rig is not animating: while posing only (the Head workspace), the slider edits
  // (setChannel, setChannels, resetChannels) pose the face over the animation at the current
  // time without writing keys or undo steps, and unkeyChannel and addKey do nothing but say
  // so. Turning it off drops the pose: currentValues() are the animation's again.
  bool posingOnly() const { return posingOnly_; }
  void setPosingOnly(bool on);
  // The channels the pose sets (empty when not posing only).
  const ChannelMask& posedChannels() const { return posed_; }

  // --- options ------------------------------------------------------------------------
  bool symmetricEdit() const { return symmetric_; }
  void setSymmetricEdit(bool on);
  // The channel the user touched last: the timeline draws its curve.
  int focusChannel() const { return focus_; }
  void setFocusChannel(int fap);

  // --- edits (each pushes one undo step; an edit that changes nothing pushes nothing) ---
  // A slider drag starts a session; changes within it merge into one undo step.
  int beginDragSession() { return ++dragSessions_; }
  void setChannel(int fap, double value, int dragSession = 0);
  void setChannels(std::vector<ChannelValue> values, const QString& text, int dragSession = 0);
  void resetChannels(std::span<const int> faps, const QString& text);  // to 0 where it matters
  void unkeyChannel(int fap);  // removes the channel from the key at the current time
  void addKey();               // every animated channel, at the current time
  void deleteKeys(std::vector<double> times);
  void deleteSelectedKeys() { deleteKeys(selection_); }
  // Moves keys by whole frames. A key landing on a key that does not move merges into it
  // (the moving key's channels win).
  void moveKeys(std::vector<double> times, int frames);
  // Keys with times relative to the first; they land at `at` and after, merging as above.
  void pasteKeys(const std::vector<Keyframe>& clip, double at);
  void setInterpolation(std::vector<double> times, Interpolation mode);
  // Applies a pose at the current time (a sequence from the current time on). `intensity`
  // scales the values (FAP 1/2 codes are not scaled). `replacePose`: channels the preset does
  // not set but that are non-zero now are keyed to 0, so the pose is the preset's alone.
  // Channels first keyed by it are also keyed at the previous key, at the value they had, so
  // the animation before that key does not change (a first key holds back to frame 0).
  void applyPreset(const Preset& preset, double intensity, bool replacePose);
  // A pose preset as a layer (PoseLayer.h) instead of keys: its pose at intensity 1, with
  // intensity keys rising from 0 half a second before the current time to `intensity` at it
  // (one key when there is no room before). Sequences cannot be layers (message).
  void applyPresetAsLayer(const Preset& preset, double intensity);
  void setLayerMuted(int index, bool muted);
  void removeLayer(int index);
  // Keys layer `index`'s intensity at the current time (replacing a key there); unkey removes it.
  void keyLayerIntensity(int index, double value);
  void unkeyLayerIntensity(int index);
  // The project's mood curves (MoodCurves.h), as the graph editor's Moods view edits them: the
  // whole set after the edit, one undo step (nothing when it equals the current one). Values
  // are clamped to [0, 1] and times to [0, 86400].
  void editMoods(MoodCurves after, const QString& text);
  // Keys `mood` at the current time to `value` (replacing a key there); unkey removes it.
  void keyMood(Mood mood, double value);
  void unkeyMood(Mood mood);
  // The procedural crying layer (MoodLayer.h), each one undo step. addMoodLayer: the layer over
  // the request's range with its seed, following the mood curves; with constant moods
  // (request.curves unset) the request's moods are first keyed as curves over the range (its
  // script's keys, from `start`; the moods' old keys within the range go), in the same step.
  // It replaces a layer the project has. Throws std::invalid_argument (a seed above
  // MoodLayer::kMaxSeed, a range that does not run forward or is too long) changing nothing.
  void addMoodLayer(const MoodGenerationRequest& request);
  void setMoodLayerMuted(bool muted);
  void setMoodLayerSeed(std::uint64_t seed);  // seeds above MoodLayer::kMaxSeed: message
  void removeMoodLayer();
  // Writes what the layer adds into keys (planMoodGeneration with addToKeys: keys plus layer,
  // reduced at tolerance 1) and its colours into the colour curves (a key every 0.25 s within
  // its range), and removes it: one undo step, the face unchanged within the reduction's
  // tolerance. A muted layer is not baked (message).
  void bakeMoodLayer();
  // The layer's take as the preview evaluates it (nullptr without one, or muted).
  const MoodLayerTake* moodTake() { return document_.moodTake(moodCache_); }
  int moodGenerations() const { return moodCache_.generations(); }
  // Mirrors left <-> right: the selected keys, else the key at the current time, else the
  // current pose as a new key.
  void mirror();
  // Name, fps, default interpolation, tear sources, scene and head (the keys of `settings` are
  // ignored).
  void setSettings(const ProjectDocument& settings, const QString& text);

  // Any key edit planned elsewhere (dope sheet, graph editor): one undo step named `text`. With
  // `selectionAfter`, the key-row selection becomes it and undo restores the one before; with
  // `channelKeysAfter`, the same for the channel-key selection.
  void editKeys(const KeyChange& change, const QString& text,
                std::optional<std::vector<double>> selectionAfter = std::nullopt,
                std::optional<std::vector<ChannelKey>> channelKeysAfter = std::nullopt);

 signals:
  void documentReset();
  void keysChanged();
  void settingsChanged();
  void layersChanged();
  void moodsChanged();
  void moodLayerChanged();
  void timeChanged(double seconds);
  void valuesChanged();  // currentValues() changed (time or keys)
  void selectionChanged();
  void selectedChannelsChanged();
  void symmetricEditChanged(bool on);
  void posingOnlyChanged(bool on);
  void focusChannelChanged(int fap);
  // A user-visible note about an edit that could not be done ("nothing to mirror").
  void message(const QString& text);

 private:
  // What the commands do and undo: the one way the document changes after resetDocument().
  friend class KeyEditCommand;
  friend class LayersCommand;
  friend class MoodsCommand;
  friend class MoodLayerCommand;
  friend class SettingsCommand;
  void applyKeyChange(const KeyChange& change, bool redo);
  void applySettings(const ProjectDocument& settings);
  void applyLayers(const std::vector<PoseLayer>& layers);
  void applyMoods(const MoodCurves& moods);
  void applyMoodLayer(const MoodLayerState& state);
  void pushMoodLayer(MoodLayerState after, const QString& text);

  void refreshValues();
  void pushKeyEdit(const KeyChange& change, const QString& text,
                   std::optional<std::vector<double>> selectionAfter);
  Keyframe keyOrNewAt(double seconds) const;
  std::optional<Keyframe> holdBefore(const Keyframe& pose) const;
  double shiftedTime(double seconds, int frames) const;
  float sanitised(int fap, double value) const;
  void pushLayers(std::vector<PoseLayer> after, const QString& text);

  ProjectDocument document_;
  QUndoStack undo_;
  double time_ = 0.0;
  FapValues values_{};
  FapValues keyedValues_{};
  ChannelMask animated_;
  std::vector<double> selection_;
  ChannelKeySelection channelKeys_{document_.keys};  // after document_, whose keys it reads
  ChannelMask selectedChannels_;
  bool symmetric_ = false;
  int focus_ = 3;
  int dragSessions_ = 0;
  bool posingOnly_ = false;
  ChannelMask posed_;         // channels the pose sets, over the animation
  FapValues poseValues_{};    // their values
  MoodLayerCache moodCache_;  // the mood layer's take, generated again when its inputs change
};

}  // namespace lacrima::editing
