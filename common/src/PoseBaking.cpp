#include <lacrima/common/PoseBaking.h>

#include <lacrima/common/FapTable.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <locale>
#include <numeric>
#include <span>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace lacrima::inline common {
namespace {

// Sparse weights after validation, ascending by vertex.
struct WeightedVertices {
  std::vector<int> vertices;
  std::vector<float> weights;
};

std::string fapLabel(int fap) {
  return "FAP " + std::to_string(fap) + " (" + std::string(fapInfo(fap).name) + ")";
}

// Numbers in messages read the same whatever the user's locale.
std::string number(double value) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << value;
  return out.str();
}

bool nameContains(std::string_view name, std::string_view part) {
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower.find(part) != std::string::npos;
}

// uv-seam copies grouped by weld root, as compressed rows: the copies of root r are
// members_[start_[r] .. start_[r + 1]), ascending (a root is its own first copy).
class SeamGroups {
 public:
  explicit SeamGroups(const Eigen::Matrix3Xf& positions)
      : root_(weldCoincidentVertices(positions)), start_(root_.size() + 1, 0) {
    for (int r : root_) ++start_[static_cast<std::size_t>(r) + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    members_.resize(root_.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t v = 0; v < root_.size(); ++v)
      members_[static_cast<std::size_t>(fill[static_cast<std::size_t>(root_[v])]++)] =
          static_cast<int>(v);
  }

  int root(int v) const { return root_[static_cast<std::size_t>(v)]; }
  std::span<const int> copies(int root) const {
    const auto r = static_cast<std::size_t>(root);
    return {members_.data() + start_[r], static_cast<std::size_t>(start_[r + 1] - start_[r])};
  }

 private:
  std::vector<int> root_;
  std::vector<int> start_;
  std::vector<int> members_;
};

// Gathers weights per weld root (largest wins), then hands them out to every seam copy.
// The scratch array is dense but only touched entries are visited, so the cost follows the
// influence's size, not the head's.
class SeamExpander {
 public:
  SeamExpander(const SeamGroups& seams, int vertexCount)
      : seams_(seams),
        vertexCount_(vertexCount),
        rootWeight_(static_cast<std::size_t>(vertexCount), 0.0f) {}

  struct Problems {
    int rejected = 0;  // index out of range, or weight not finite and positive
    int clamped = 0;   // weight above 1
  };

  void add(int v, float w, Problems& problems) {
    if (v < 0 || v >= vertexCount_ || !std::isfinite(w) || w <= 0.0f) {
      ++problems.rejected;
      return;
    }
    if (w > 1.0f) {
      ++problems.clamped;
      w = 1.0f;
    }
    const int r = seams_.root(v);
    float& slot = rootWeight_[static_cast<std::size_t>(r)];
    if (slot == 0.0f) touched_.push_back(r);
    slot = std::max(slot, w);
  }

  WeightedVertices take() {
    std::vector<std::pair<int, float>> entries;
    for (int r : touched_) {
      float& slot = rootWeight_[static_cast<std::size_t>(r)];
      for (int copy : seams_.copies(r)) entries.emplace_back(copy, slot);
      slot = 0.0f;
    }
    touched_.clear();
    std::sort(entries.begin(), entries.end());  // ascending vertices keep the blend's writes local
    WeightedVertices out;
    out.vertices.reserve(entries.size());
    out.weights.reserve(entries.size());
    for (const auto& [v, w] : entries) {
      out.vertices.push_back(v);
      out.weights.push_back(w);
    }
    return out;
  }

 private:
  const SeamGroups& seams_;
  int vertexCount_;
  std::vector<float> rootWeight_;
  std::vector<int> touched_;
};

class Baker {
 public:
  explicit Baker(const RigInput& input)
      : in_(input),
        mesh_(*input.mesh),
        n_(mesh_.vertexCount()),
        seams_(mesh_.positions),
        expander_(seams_, n_) {}

  PoseSet bake(std::vector<int>& baked) {
    PoseSet set;
    set.vertexCount = n_;
    checkUnits();
    set.eyeLeft = eyeGroup(in_.eyeLeft, "left", 23, 25);
    set.eyeRight = eyeGroup(in_.eyeRight, "right", 24, 26);
    set.head = headGroup();

    for (int fap = 3; fap <= kFapCount; ++fap) {
      VertexPose& pose = set.poses[static_cast<std::size_t>(channelIndex(fap))];
      switch (fapInfo(fap).motion) {
        case FapMotion::Translation:
          pose = translation(fap);
          break;
        case FapMotion::Dilation:
          pose = dilation(fap, fap == 29 ? set.eyeLeft : set.eyeRight);
          break;
        case FapMotion::Curl:
          pose = curl(fap);
          break;
        default:
          break;
      }
    }
    const ChannelMask driven = set.drivenChannels();
    for (int i = 0; i < kChannelCount; ++i)
      if (driven.test(static_cast<std::size_t>(i))) baked.push_back(fapNumber(i));
    return set;
  }

  std::vector<std::string> warnings;

 private:
  static bool usable(double unit) { return std::isfinite(unit) && unit > 0.0; }

  // One warning per bad FAPU listing every FAP it silences, instead of one per FAP.
  void checkUnits() {
    for (FapUnit unit : {FapUnit::IRISD, FapUnit::ES, FapUnit::ENS, FapUnit::MNS, FapUnit::MW}) {
      if (usable(in_.fapu.unitValue(unit))) continue;
      std::string faps;
      for (int fap = 3; fap <= kFapCount; ++fap)
        if (fapInfo(fap).unit == unit) faps += (faps.empty() ? "" : ", ") + std::to_string(fap);
      warnings.push_back("FAPU " + std::string(toString(unit)) + " = " +
                         number(in_.fapu.unitValue(unit)) + " is not positive and finite; FAPs " +
                         faps + " get no pose");
    }
  }

  // The validated, seam-expanded influence of a feature point, or nullptr when the rig has
  // none. Cached: several FAPs share a point (2.1 drives 3, 14 and 15).
  const WeightedVertices* influence(const std::string& id) {
    if (auto hit = cache_.find(id); hit != cache_.end()) return &hit->second;
    const auto found = in_.influences.find(id);
    if (found == in_.influences.end()) return nullptr;
    return &cache_.emplace(id, validated(found->second, "feature point " + id)).first->second;
  }

  // The influence of `fap`'s own pose: its entry in fapInfluences, else its point's.
  const WeightedVertices* influenceOf(int fap) {
    const auto found = in_.fapInfluences.find(fap);
    if (found == in_.fapInfluences.end()) return influence(std::string(fapInfo(fap).featurePoint));
    const std::string key = "FAP " + std::to_string(fap);
    if (auto hit = cache_.find(key); hit != cache_.end()) return &hit->second;
    return &cache_.emplace(key, validated(found->second, fapLabel(fap) + "'s own influence"))
                .first->second;
  }

  WeightedVertices validated(const FeaturePointInfluence& raw, const std::string& id) {
    SeamExpander::Problems problems;
    const std::size_t count = std::min(raw.vertices.size(), raw.weights.size());
    if (raw.vertices.size() != raw.weights.size())
      warnings.push_back(id + ": " + std::to_string(raw.vertices.size()) + " vertices but " +
                         std::to_string(raw.weights.size()) +
                         " weights; the unmatched entries are skipped");
    for (std::size_t k = 0; k < count; ++k)
      expander_.add(raw.vertices[k], raw.weights[k], problems);
    if (problems.rejected)
      warnings.push_back(id + ": " + std::to_string(problems.rejected) +
                         " influence entries skipped (vertex outside the head, or weight not "
                         "positive and finite)");
    if (problems.clamped)
      warnings.push_back(id + ": " + std::to_string(problems.clamped) +
                         " weights above 1 clamped to 1");
    return expander_.take();
  }

  // d_v = w_p(v) * unitValue * dir, as one outer product over the influence.
  VertexPose translation(int fap) {
    const FapInfo& info = fapInfo(fap);
    const double unit = in_.fapu.unitValue(info.unit);
    if (!usable(unit)) return {};  // reported once by checkUnits
    const std::string id(info.featurePoint);
    const WeightedVertices* weights = influenceOf(fap);
    if (!weights || weights->vertices.empty()) {
      warnings.push_back(fapLabel(fap) + ": " +
                         (weights ? "the influence of feature point " + id + " has no valid entry"
                                  : "no influence for feature point " + id) +
                         "; no pose");
      return {};
    }
    VertexPose pose;
    pose.vertices = weights->vertices;
    const Eigen::Map<const Eigen::RowVectorXf> w(
        weights->weights.data(), static_cast<Eigen::Index>(weights->weights.size()));
    const Eigen::Vector3f step = info.positiveMotion * static_cast<float>(unit);
    pose.offsets.noalias() = step * w;
    return pose;
  }

  // See PoseBaking.h for the radial profile.
  VertexPose dilation(int fap, const RotationGroup& eye) {
    const std::string id(fapInfo(fap).featurePoint);
    const std::string side = fap == 29 ? "left" : "right";
    auto none = [&](const std::string& why) {
      warnings.push_back(fapLabel(fap) + ": " + why + "; pose empty");
      return VertexPose{};
    };
    const double step = in_.fapu.unitValue(FapUnit::IRISD);
    if (!usable(step)) return {};  // reported once by checkUnits
    if (eye.vertices.empty()) return none("no " + side + " eyeball vertices");
    const auto pupil = in_.featurePoints.find(id);
    if (pupil == in_.featurePoints.end()) return none("no position for pupil feature point " + id);
    const Eigen::Vector3d centre = eye.centre.cast<double>();
    const Eigen::Vector3d axisVector = pupil->second.cast<double>() - centre;
    const double axisLength = axisVector.norm();
    if (!std::isfinite(axisLength) || axisLength <= 0.0)
      return none("pupil feature point " + id + " is not finite or coincides with the " + side +
                  " eye's centre, so the eye has no axis");
    const Eigen::Vector3d axis = axisVector / axisLength;

    const double irisRadius = 512.0 * step;       // IRISD0 / 2
    const double pupilRadius = irisRadius / 3.0;  // neutral pupil: a third of the iris
    const double edgeShift = 0.5 * step;          // diameter grows one step per unit
    const std::vector<char>& cornea = corneaMask();

    std::vector<int> vertices;
    std::vector<Eigen::Vector3f> offsets;
    for (int v : eye.vertices) {
      if (cornea[static_cast<std::size_t>(v)]) continue;  // clear cornea keeps its shape
      const Eigen::Vector3d d = mesh_.positions.col(v).cast<double>() - centre;
      const double along = d.dot(axis);
      if (along <= 0.0) continue;  // the back of the eyeball has no iris
      const Eigen::Vector3d radial = d - along * axis;
      const double r = radial.norm();
      // On the axis the direction is undefined and the shift is zero anyway; a corrupt
      // (non-finite) vertex is left alone rather than poisoning the pose.
      if (!std::isfinite(r) || r >= irisRadius || r <= 1e-9 * irisRadius) continue;
      const double profile =
          r <= pupilRadius ? r / pupilRadius : (irisRadius - r) / (irisRadius - pupilRadius);
      vertices.push_back(v);
      offsets.push_back((radial * (edgeShift * profile / r)).cast<float>());
    }
    if (vertices.empty())
      return none("no " + side +
                  " eyeball vertex lies in front of its centre within the iris "
                  "disc of radius IRISD0/2 = " +
                  number(irisRadius));
    return packed(std::move(vertices), offsets);
  }

  // See PoseBaking.h for the tongue set and midline.
  VertexPose curl(int fap) {
    WeightedVertices tongue = tongueWeights(fap);
    if (tongue.vertices.empty()) return {};
    const double midline = tongueMidline(tongue);
    const double unit = in_.fapu.unitValue(fapInfo(fap).unit);  // AU: 1e-5 rad
    std::vector<int> vertices;
    std::vector<Eigen::Vector3f> offsets;
    for (std::size_t k = 0; k < tongue.vertices.size(); ++k) {
      const int v = tongue.vertices[k];
      const double rise = tongue.weights[k] * std::abs(mesh_.positions(0, v) - midline) * unit;
      if (rise == 0.0 || !std::isfinite(rise)) continue;  // the midline stays; corrupt vertices too
      vertices.push_back(v);
      offsets.emplace_back(0.0f, static_cast<float>(rise), 0.0f);
    }
    if (vertices.empty()) {
      warnings.push_back(fapLabel(fap) + ": every tongue vertex lies on the midline; pose empty");
      return {};
    }
    return packed(std::move(vertices), offsets);
  }

  WeightedVertices tongueWeights(int fap) {
    const WeightedVertices* left = influence("6.3");
    const WeightedVertices* right = influence("6.4");
    SeamExpander::Problems ignored;  // already validated by influence()
    for (const WeightedVertices* side : {left, right})
      if (side)
        for (std::size_t k = 0; k < side->vertices.size(); ++k)
          expander_.add(side->vertices[k], side->weights[k], ignored);
    WeightedVertices tongue = expander_.take();
    if (!tongue.vertices.empty()) return tongue;

    for (const HeadSubmesh& s : mesh_.submeshes) {
      if (!nameContains(s.name, "tongue")) continue;
      const int first = std::clamp(s.firstVertex, 0, n_);
      const int last = std::clamp(s.firstVertex + s.vertexCount, first, n_);
      if (first == last) continue;
      tongue.vertices.resize(static_cast<std::size_t>(last - first));
      std::iota(tongue.vertices.begin(), tongue.vertices.end(), first);
      tongue.weights.assign(tongue.vertices.size(), 1.0f);
      warnings.push_back(fapLabel(fap) +
                         ": no usable influence for feature points 6.3 and 6.4; "
                         "curling the whole '" +
                         s.name + "' sub-mesh");
      return tongue;
    }
    warnings.push_back(fapLabel(fap) +
                       ": no usable influence for feature points 6.3 and 6.4 and "
                       "no sub-mesh named like 'tongue'; pose empty");
    return {};
  }

  double tongueMidline(const WeightedVertices& tongue) const {
    const auto& points = in_.featurePoints;
    auto x = [&](const char* id) {
      const auto p = points.find(id);
      return p == points.end() ? std::numeric_limits<double>::quiet_NaN() : double(p->second.x());
    };
    // The first candidate that exists and is finite (NaN propagates through the mean).
    for (const double candidate : {0.5 * (x("6.3") + x("6.4")), x("6.2"), x("6.1")})
      if (std::isfinite(candidate)) return candidate;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int v : tongue.vertices) {
      const double vx = mesh_.positions(0, v);
      if (!std::isfinite(vx)) continue;
      low = std::min(low, vx);
      high = std::max(high, vx);
    }
    return low <= high ? 0.5 * (low + high) : 0.0;
  }

  // Validated, seam-closed eyeball group; empty (with a warning) when unusable.
  RotationGroup eyeGroup(const RotationGroup& raw, const std::string& side, int yawFap,
                         int pitchFap) {
    const std::string faps = "FAPs " + std::to_string(yawFap) + " and " + std::to_string(pitchFap);
    RotationGroup group;
    if (raw.vertices.empty()) {
      warnings.push_back(faps + ": no " + side + " eyeball vertices; the " + side +
                         " eye does not turn");
      return group;
    }
    if (!raw.centre.allFinite()) {
      warnings.push_back(faps + ": the " + side + " eye's centre is not finite; the " + side +
                         " eye does not turn");
      return group;
    }
    group.vertices = closedOverSeams(raw.vertices, "the " + side + " eyeball group");
    group.centre = raw.centre;
    return group;
  }

  RotationGroup headGroup() {
    RotationGroup group;
    if (!in_.neckPivot.allFinite()) {
      warnings.push_back(
          "FAPs 48, 49 and 50: the neck pivot is not finite; the head does not turn");
      return group;
    }
    group.centre = in_.neckPivot;
    if (in_.headVertices.empty()) {
      group.vertices.resize(static_cast<std::size_t>(n_));
      std::iota(group.vertices.begin(), group.vertices.end(), 0);
    } else {
      group.vertices = closedOverSeams(in_.headVertices, "the head group");
    }
    return group;
  }

  // Ascending, unique, in range, with every seam copy of a member (a group that split a seam
  // would tear the mesh when it turns).
  std::vector<int> closedOverSeams(const std::vector<int>& vertices, const std::string& what) {
    SeamExpander::Problems problems;
    for (int v : vertices) expander_.add(v, 1.0f, problems);
    if (problems.rejected)
      warnings.push_back(what + ": " + std::to_string(problems.rejected) +
                         " vertex indices outside the head skipped");
    return expander_.take().vertices;
  }

  const std::vector<char>& corneaMask() {
    if (cornea_.empty()) {
      cornea_.assign(static_cast<std::size_t>(n_), 0);
      for (const HeadSubmesh& s : mesh_.submeshes) {
        if (!nameContains(s.name, "cornea")) continue;
        const int first = std::clamp(s.firstVertex, 0, n_);
        const int last = std::clamp(s.firstVertex + s.vertexCount, first, n_);
        std::fill(cornea_.begin() + first, cornea_.begin() + last, 1);
      }
    }
    return cornea_;
  }

  static VertexPose packed(std::vector<int> vertices, const std::vector<Eigen::Vector3f>& offsets) {
    VertexPose pose;
    pose.vertices = std::move(vertices);
    pose.offsets.resize(3, static_cast<Eigen::Index>(offsets.size()));
    for (std::size_t k = 0; k < offsets.size(); ++k)
      pose.offsets.col(static_cast<Eigen::Index>(k)) = offsets[k];
    return pose;
  }

  const RigInput& in_;
  const HeadMesh& mesh_;
  int n_;
  SeamGroups seams_;
  SeamExpander expander_;
  std::map<std::string, WeightedVertices> cache_;
  std::vector<char> cornea_;
};

}  // namespace

PoseSet bakePoses(const RigInput& input, PoseBakeReport* report) {
  if (!input.mesh) throw std::invalid_argument("bakePoses: RigInput::mesh is null");
  Baker baker(input);
  std::vector<int> baked;
  PoseSet set = baker.bake(baked);
  if (report) {
    report->bakedFaps = std::move(baked);
    report->warnings = std::move(baker.warnings);
  }
  return set;
}

}  // namespace lacrima::inline common
