#pragma once
// A Lacrima project: the editor's document, saved as versioned JSON.
//
// {
//   "format": "lacrima-project", "version": 2,
//   "name": "sad crying", "fps": 22, "interpolation": "linear",
//   "keys": [ { "time": 0.5, "interpolation": "smooth",
//               "values": { "open_jaw": 120, "tears_l_eye": 12 },
//               "shapes": { "open_jaw": { "interpolation": "bezier", "handles": "free",
//                                         "in": [-0.2, 0], "out": [0.1, 35] } } } ],
//                                  (version 2; only channels whose shape is not the key's own)
//   "tearSources": { "left": [x, y, z], "right": null },          (head frame; null = rig default)
//   "scene": { "particles": false, "surface": true, "trails": true, "textureBlending": true,
//              "redness": "animation" | "tears", "blush": false,
//              "simulation": { "adhesion": 20, ... },            (overrides of TearParameters)
//              "quality": "preview" | "balanced" | "reference",     (version 2; optional, each;
//              "solver": "wcsph" | "dfsph" | "pbf" | ...,            absent = balanced and the
//              "tension": "mueller" | "akinci" | ...,                level's own choices; keys
//              "neighbours": "grid" | "octree" | ... },              of the method registries,
//                                                                    TearQuality.h)
//   "head": { "mesh": "heads/ict.obj", "fdp": "heads/ict.fdp.json" }, (optional; absent = the
//                                                                     default head)
//   "layers": [ { "name": "sob", "muted": false, "pose": { "open_jaw": 80, ... },
//                 "intensity": [ { "time": 3.5, "value": 0 },
//                                { "time": 4, "value": 1, "interpolation": "smooth" } ] } ]
//                                                      (version 2; optional; see PoseLayer.h)
//   "colours": { "redness": [ { "time": 0, "value": 0.1, "interpolation": "linear" } ],
//                "blush": [ ... ] }        (version 2; optional, each; values in [0, 1]; keyed
//                                            colours replace the player's computed ones,
//                                            FaceColours.h)
//   "moods": { "sadness": [ { "time": 2, "value": 0.8, "interpolation": "smooth" } ],
//              "anger": [...], "joy": [...], "shame": [...] }
//                                          (version 2; optional, each; values in [0, 1]; what
//                                            Generate crying... and the mood layer follow,
//                                            MoodCurves.h; by themselves never baked)
//   "moodLayer": { "seed": 4, "start": 2, "end": 30, "muted": false }
//                                          (version 2; optional; the crying generator over
//                                            [start, end] following "moods", evaluated, not
//                                            keyed: MoodLayer.h)
// }
// Head paths in the file are relative to the project file's folder (absolute ones are read as
// they are). load() makes them absolute, so the document names the same files wherever it is
// saved next; save() writes them relative to the new file's folder again (see HeadFiles).
// Version 1 files (no shapes; linear and smooth only) read as they always did, and bake to the
// same frames. Unknown or invalid fields are errors naming the JSON path and, for syntax errors,
// the line and column. A document written and read back compares equal.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FaceColours.h>
#include <lacrima/common/JsonValue.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/common/PoseLayer.h>
#include <lacrima/common/TearParameters.h>
#include <lacrima/common/TearQuality.h>
#include <lacrima/common/mood/MoodCurves.h>
#include <lacrima/common/mood/MoodLayer.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lacrima::inline common {

struct TearSources {
  std::optional<Eigen::Vector3d> left, right;  // nullopt: the rig's default, under each eye
  bool operator==(const TearSources&) const = default;
};

// What the player should show. Tears are simulated only when a tear channel is non-zero;
// these switch the effects built on top of them.
struct SceneSettings {
  enum class Redness { Animation, Tears };  // eye redness follows time (2009) or tears shed

  bool particles = false;  // draw particle spheres (inspection)
  bool surface = true;     // tear surface mesh
  bool trails = true;      // wet trails
  bool textureBlending = true;
  Redness redness = Redness::Animation;
  bool blush = false;
  TearParameterValues simulation;  // overrides; absent names use the defaults
  TearQualitySettings quality;     // how accurately (and expensively) the tears are simulated

  bool operator==(const SceneSettings&) const = default;
};

// The head a project is animated on: a mesh assimp reads and its feature-point file
// (lacrima-fdp). In memory the paths are absolute once a project is loaded (or chosen in the
// editor); only a document read with fromJson()/read() keeps them as written.
struct HeadFiles {
  std::string mesh;
  std::string fdp;
  bool operator==(const HeadFiles&) const = default;
};

struct ProjectDocument {
  static constexpr int kSchemaVersion = 2;
  static constexpr long long kMaxFileBytes = 64LL << 20;  // larger project files are refused

  std::string name = "untitled";
  double fps = 22.0;
  Interpolation defaultInterpolation = Interpolation::Linear;  // for new keys
  KeyframeSequence keys;
  std::vector<PoseLayer> layers;  // mixed onto the keys in this order (PoseLayer.h)
  TearSources tearSources;
  SceneSettings scene;
  std::optional<HeadFiles> head;       // nullopt: the default head
  FaceColourCurves colours;            // keyed redness and blush; empty: computed by the player
  MoodCurves moods;                    // keyed moods for the crying generator; empty: none
  std::optional<MoodLayer> moodLayer;  // the generator following `moods`, mixed on the keys

  bool operator==(const ProjectDocument& other) const;

  std::string toJson() const;  // head paths as stored

  // What a project is read for. To Bake (play, export from scripts), a project whose animation
  // would exceed kMaxBakedFrames at its own rate is refused as it is read, at the key that
  // sets its length; to Edit, it opens, so that the editor can shorten it.
  enum class Use { Edit, Bake };
  // `methods`: the tear method keys a simulating app accepts (TearMethodKeys); without them any
  // well-formed key is kept as written.
  // Throws FileError with `displayName` and the line/column or JSON path of the problem.
  static ProjectDocument fromJson(std::string_view json, const std::string& displayName,
                                  Use use = Use::Edit, const TearMethodKeys* methods = nullptr);
  // A project stored as a value of a larger document (a recovery file holds one). Throws
  // FileError naming the line, column and JSON path of the problem.
  static ProjectDocument read(const JsonValue& value, Use use = Use::Edit,
                              const TearMethodKeys* methods = nullptr);

  // Reads `path` and resolves the head's relative paths against its folder.
  static ProjectDocument load(const std::string& path, Use use = Use::Edit,
                              const TearMethodKeys* methods = nullptr);
  // Atomic (temporary file, then rename). The head's paths are written relative to the folder
  // of `path` when the two share more than the filesystem root, absolute otherwise, so a
  // "Save As" elsewhere still names the same files and a project folder can be moved whole.
  void save(const std::string& path) const;

  // Head paths made absolute against `folder` (what load() does), or relative to it (what
  // save() writes). No-ops without a head.
  void resolveHeadPaths(const std::string& folder);
  void relativizeHeadPaths(const std::string& folder);
  // The first head file that does not exist, as "project: head.mesh: ..." naming the missing
  // file and what to do; nullopt when both exist or there is no head. `projectPath` names the
  // project in the message.
  std::optional<Diagnostic> missingHeadFile(const std::string& projectPath) const;

  // The animation the project plays and exports, at its own rate or at `rate`, named after it:
  // the keys with the layers mixed on (pose layers, then the mood layer), from the earliest to
  // the latest key of either. More than kMaxBakedFrames throw std::length_error before anything
  // is allocated. The mood layer's take comes from `cache` (generated there when it is not yet).
  FapAnimation bake() const { return bake(fps); }
  FapAnimation bake(double rate) const;
  FapAnimation bake(double rate, MoodLayerCache& cache) const;
  // The first and last time bake() covers: the keys', the unmuted layers' intensity keys' and
  // the unmuted mood layer's range (start > end when there is nothing to bake).
  std::pair<double, double> bakeRange() const;
  // Every channel at `seconds`: the keys with the layers mixed on.
  FapValues evaluate(double seconds, MoodLayerCache& cache) const;
  // The face colours at `seconds`: the keyed curves, the mood layer's within its range.
  KeyedColours coloursAt(double seconds, MoodLayerCache& cache) const;
  // The mood layer's take at the project's rate (nullptr without one, or muted).
  const MoodLayerTake* moodTake(MoodLayerCache& cache) const {
    return cache.take(moods, moodLayer, fps);
  }
  static ProjectDocument fromAnimation(const FapAnimation& animation);  // a key per frame
};

}  // namespace lacrima::inline common
