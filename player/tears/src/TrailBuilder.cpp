#include "VectorState.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/tears/DropFootprint.h>
#include <lacrima/tears/TearSimulation.h>
#include <lacrima/tears/TrailBuilder.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace lacrima::tears {
namespace {
constexpr double kRadian = std::numbers::pi / 180;
}  // namespace

std::size_t TrailMesh::bytes() const {
  return sizeof(*this) + (position_.size() + normal_.size()) * sizeof(Eigen::Vector3d) +
         alpha_.size() * sizeof(double) + triangle_.size() * sizeof(Eigen::Vector3i);
}

// The working buffers are left out: a copy does not take them (Scratch.h); nor are the skin's
// tables, which copies share (TrailSkin.h).
std::size_t TrailBuilder::bytes() const {
  return sizeof(*this) - sizeof(mesh_) + mesh_.bytes() + sections_.size() * sizeof(TrailSection) +
         segments_.size() * sizeof(TrailSegment) + tracks_.size() * sizeof(Track) +
         owner_.size() * sizeof(owner_.front());
}

TrailBuilder::TrailBuilder(std::vector<Eigen::Vector3i> skinTriangles,
                           const TrailSettings& settings)
    : skin_(std::move(skinTriangles)), settings_(settings) {
  if (!(settings_.drySeconds > 0) || !(settings_.minimumStepKernels > 0) ||
      settings_.maxSections < 2 || !(settings_.middleHeightFraction >= 0) ||
      !(settings_.contactAngleDegrees >= 0 && settings_.contactAngleDegrees <= 180))
    throw std::invalid_argument(
        "trail settings: dry time and step must be positive, at least two sections, a contact "
        "angle in [0, 180] degrees");
}

const TrailMesh& TrailBuilder::update(const TearSimulation& simulation,
                                      const Eigen::Matrix3Xf& headPositions, double dt) {
  const ParticleSet& particles = simulation.particles();
  // The simulation builds its grid on first use: only ask for it when there is something in it.
  const UniformGrid& grid = particles.empty() ? emptyGrid_ : simulation.grid();
  return update(particles, grid, simulation.kernelRadius(), simulation.particleRadius(),
                headPositions, dt);
}

const TrailMesh& TrailBuilder::update(const ParticleSet& particles, const UniformGrid& grid,
                                      double h, double particleRadius,
                                      const Eigen::Matrix3Xf& headPositions, double dt) {
  if (particles.empty() && sections_.empty() && tracks_.empty()) {  // nothing wet: no work
    milliseconds_ = 0;
    return mesh_;
  }
  clearUpperVectorState();
  const auto start = SteadyClock::now();
  if (headPositions.cols() <= skin_.maxVertex())
    throw std::invalid_argument("trails: fewer head positions than the skin uses");
  if (!(h > 0) || !std::isfinite(h))
    throw std::invalid_argument("trails: kernel radius must be positive");
  if (!(dt >= 0) || !std::isfinite(dt)) dt = 0;  // a bad frame time neither dries nor un-dries
  skin_.bind(headPositions);
  for (TrailSection& s : sections_) s.age += dt;
  if (particles.empty()) {
    tracks_.clear();
    owner_.clear();
  } else {
    advance(particles, grid, h, particleRadius);
  }
  dryAndCap();
  rebuildMesh();
  skin_.unbind();  // the positions belong to the caller
  milliseconds_ = millisecondsSince(start);
  return mesh_;
}

// Matches this update's drops to last update's tracks by particle id and continues them.
void TrailBuilder::advance(const ParticleSet& particles, const UniformGrid& grid, double h,
                           double particleRadius) {
  Buffers& w = *work_;
  w.finder.find(particles, grid);
  findPreviousTracks(particles);
  w.nextTracks.clear();
  w.predecessorUse.assign(tracks_.size(), 0);
  w.predecessor.clear();
  w.sources.clear();
  for (const FoundDrop& drop : w.finder.drops()) {
    w.votes.clear();  // (track, particles) — a drop rarely has more than two predecessors
    for (int k = drop.first; k < drop.first + drop.count; ++k) {
      const int previous = w.previousTrack[static_cast<std::size_t>(k)];
      if (previous < 0) continue;
      auto vote = std::find_if(w.votes.begin(), w.votes.end(),
                               [&](const auto& v) { return v.first == previous; });
      if (vote == w.votes.end())
        w.votes.emplace_back(previous, 1);
      else
        ++vote->second;
    }
    int predecessor = -1, best = 0;
    for (const auto& [track, count] : w.votes)
      if (count > best || (count == best && track < predecessor)) {
        predecessor = track;
        best = count;
      }
    w.predecessor.push_back(predecessor);
    w.sources.push_back(static_cast<int>(w.votes.size()));
    if (predecessor >= 0) ++w.predecessorUse[static_cast<std::size_t>(predecessor)];
  }
  w.heirsSeen.assign(tracks_.size(), 0);
  for (std::size_t d = 0; d < w.finder.drops().size(); ++d) {
    const FoundDrop& drop = w.finder.drops()[d];
    const int predecessor = w.predecessor[d];
    Track track;
    bool reshaped = false;
    if (predecessor >= 0) {
      const auto p = static_cast<std::size_t>(predecessor);
      track = tracks_[p];
      if (w.heirsSeen[p]++ > 0) ++branches_;  // every heir after the first is a branch
      reshaped = w.predecessorUse[p] > 1 || w.sources[d] > 1;  // split, or merged
    }
    continueTrack(track, particles, drop, h, particleRadius, reshaped);
    w.nextTracks.push_back(track);  // track d continues drop d
  }
  // The owners for the next update: every particle's id with its drop's track, by id.
  owner_.resize(w.byId.size());
  for (std::size_t r = 0; r < w.byId.size(); ++r)
    owner_[r] = {w.byId[r].first, w.dropOf[static_cast<std::size_t>(w.byId[r].second)]};
  tracks_.swap(w.nextTracks);
}

// previousTrack[k]: the track that owned the k-th particle of the finder's list in the last
// update, or -1 (a new particle). The list is sorted by id and merged with the owners, also
// sorted by id: one sort and a linear walk instead of a binary search per particle.
void TrailBuilder::findPreviousTracks(const ParticleSet& particles) {
  Buffers& w = *work_;
  const auto listed = w.finder.particleIndices();
  w.byId.resize(listed.size());
  w.dropOf.resize(listed.size());
  for (std::size_t k = 0; k < listed.size(); ++k)
    w.byId[k] = {particles.id[static_cast<std::size_t>(listed[k])], static_cast<int>(k)};
  const auto drops = w.finder.drops();
  for (std::size_t d = 0; d < drops.size(); ++d)
    std::fill_n(w.dropOf.begin() + drops[d].first, drops[d].count, static_cast<int>(d));
  std::sort(w.byId.begin(), w.byId.end());
  w.previousTrack.assign(listed.size(), -1);
  std::size_t o = 0;
  for (const auto& [id, k] : w.byId) {
    while (o < owner_.size() && owner_[o].first < id) ++o;
    if (o < owner_.size() && owner_[o].first == id)
      w.previousTrack[static_cast<std::size_t>(k)] = owner_[o].second;
  }
}

void TrailBuilder::continueTrack(Track& track, const ParticleSet& particles, const FoundDrop& drop,
                                 double h, double particleRadius, bool reshaped) {
  Buffers& w = *work_;
  skin_.contactSeeds(particles.contact, w.finder.particlesOf(drop), w.seeds);
  if (w.seeds.empty()) {
    // In the air (a drop that fell off the chin): it wets nothing, and its track ends, so where
    // it lands a new trail starts instead of a strip bridging the gap.
    track = Track{};
    return;
  }
  if (track.centre.triangle >= 0) w.seeds.push_back(track.centre.triangle);
  const SkinAnchor centre = skin_.closest(drop.centre, w.seeds);
  if (centre.triangle < 0) return;
  const Eigen::Vector3d c = skin_.point(centre);
  const Eigen::Vector3d n = skin_.normal(centre.triangle);
  if (reshaped) {  // the centre jumped with the split or merge: no motion to read, no section
    track.centre = centre;
    return;
  }
  if (track.centre.triangle >= 0) {
    // Both centres on the current skin: a face that moves carries the old centre along.
    Eigen::Vector3d motion = c - skin_.point(track.centre);
    motion -= motion.dot(n) * n;
    if (motion.norm() > 1e-3 * h) track.direction = motion.normalized();
  }
  track.centre = centre;
  Eigen::Vector3d t = track.direction - track.direction.dot(n) * n;  // the skin may have turned
  if (t.norm() < 1e-6) return;  // no direction yet: left and right are undefined
  t.normalize();
  if (track.lastSection >= 0) {
    SkinAnchor last = sections_[static_cast<std::size_t>(track.lastSection)].point[1];
    last.height = 0;
    if ((c - skin_.point(last)).norm() <= settings_.minimumStepKernels * h) return;
  }

  // Left of the motion seen from outside: a = n x t.
  const Eigen::Vector3d a = n.cross(t);
  double left = -std::numeric_limits<double>::infinity(),
         right = std::numeric_limits<double>::infinity(), top = 0;
  for (int i : w.finder.particlesOf(drop)) {
    const Eigen::Vector3d d = particles.position[static_cast<std::size_t>(i)] - c;
    const double across = d.dot(a);
    left = std::max(left, across);
    right = std::min(right, across);
    top = std::max(top, d.dot(n));
  }
  // The wetted width is the wider of the particles' extent and the footprint of a drop of their
  // volume (DropFootprint.h): a few particles spread as one cap, not as a chain of parcels.
  const double footprint = sphericalCap(drop.count * parcelVolume(particleRadius),
                                        settings_.contactAngleDegrees * kRadian)
                               .contactRadius;
  w.seeds.push_back(centre.triangle);
  TrailSection section;
  section.eye = drop.eye;
  section.point[0] = skin_.closest(c + std::max(left + particleRadius, footprint) * a, w.seeds);
  section.point[2] = skin_.closest(c + std::min(right - particleRadius, -footprint) * a, w.seeds);
  section.point[1] = centre;
  section.point[1].height = std::min(h, settings_.middleHeightFraction * (top + particleRadius));
  if (section.point[0].triangle < 0) section.point[0] = centre;
  if (section.point[2].triangle < 0) section.point[2] = centre;
  if (track.lastSection >= 0) {
    // A sharp turn: the inner boundary would run backwards across the last cross-section and
    // fold the strip over. The inner side pivots on the last section's point instead (its
    // triangles fan out from it; the one left without area is not drawn).
    const TrailSection& last = sections_[static_cast<std::size_t>(track.lastSection)];
    for (int side : {0, 2})
      if ((skin_.point(section.point[static_cast<std::size_t>(side)]) -
           skin_.point(last.point[static_cast<std::size_t>(side)]))
              .dot(t) <= 0)
        section.point[static_cast<std::size_t>(side)] = last.point[static_cast<std::size_t>(side)];
  }
  const int index = static_cast<int>(sections_.size());
  sections_.push_back(section);
  if (track.lastSection >= 0) segments_.push_back({track.lastSection, index});
  track.lastSection = index;
}

// Drops dry segments (the oldest first: segments are appended in time order, so their newer
// sections' ages fall along the list) and, past the cap, the oldest wet ones; then compacts
// the sections still referred to.
void TrailBuilder::dryAndCap() {
  Buffers& w = *work_;
  const double dry = settings_.drySeconds;
  std::size_t removed = 0;
  while (removed < segments_.size() &&
         sections_[static_cast<std::size_t>(segments_[removed].to)].age >= dry)
    ++removed;
  for (Track& track : tracks_)  // a drop resting longer than the drying time starts afresh
    if (track.lastSection >= 0 && sections_[static_cast<std::size_t>(track.lastSection)].age >= dry)
      track.lastSection = -1;

  const auto maxSections = static_cast<std::size_t>(settings_.maxSections);
  std::size_t live = 0;
  while (true) {
    w.referenced.assign(sections_.size(), 0);
    for (std::size_t s = removed; s < segments_.size(); ++s) {
      w.referenced[static_cast<std::size_t>(segments_[s].from)] = 1;
      w.referenced[static_cast<std::size_t>(segments_[s].to)] = 1;
    }
    for (const Track& track : tracks_)
      if (track.lastSection >= 0) w.referenced[static_cast<std::size_t>(track.lastSection)] = 1;
    live = static_cast<std::size_t>(std::count(w.referenced.begin(), w.referenced.end(), 1));
    if (live <= maxSections) break;
    if (removed < segments_.size()) {
      // Dropping the oldest segment of a chain frees its older section: about one per segment.
      removed = std::min(segments_.size(), removed + (live - maxSections));
    } else {
      for (Track& track : tracks_) track.lastSection = -1;  // more drops than the cap: restart them
    }
  }
  segments_.erase(segments_.begin(), segments_.begin() + static_cast<std::ptrdiff_t>(removed));

  w.remap.assign(sections_.size(), -1);
  std::size_t kept = 0;
  for (std::size_t s = 0; s < sections_.size(); ++s) {
    if (!w.referenced[s]) continue;
    w.remap[s] = static_cast<int>(kept);
    sections_[kept++] = sections_[s];
  }
  sections_.resize(kept);
  for (TrailSegment& segment : segments_) {
    segment.from = w.remap[static_cast<std::size_t>(segment.from)];
    segment.to = w.remap[static_cast<std::size_t>(segment.to)];
  }
  for (Track& track : tracks_)
    if (track.lastSection >= 0)
      track.lastSection = w.remap[static_cast<std::size_t>(track.lastSection)];
}

void TrailBuilder::rebuildMesh() {
  mesh_.position_.clear();
  mesh_.normal_.clear();
  mesh_.alpha_.clear();
  mesh_.triangle_.clear();
  wetArea_ = {0, 0};
  for (const TrailSection& section : sections_) {
    const double alpha = std::clamp(1.0 - section.age / settings_.drySeconds, 0.0, 1.0);
    for (const SkinAnchor& anchor : section.point) {
      mesh_.position_.push_back(skin_.point(anchor));
      mesh_.normal_.push_back(skin_.normal(anchor.triangle));
      mesh_.alpha_.push_back(alpha);
    }
  }
  for (const TrailSegment& segment : segments_) {
    const int l0 = 3 * segment.from, m0 = l0 + 1, r0 = l0 + 2;
    const int l1 = 3 * segment.to, m1 = l1 + 1, r1 = l1 + 2;
    const Eigen::Vector3i triangles[4] = {{l0, m0, m1}, {l0, m1, l1}, {m0, r0, r1}, {m0, r1, m1}};
    const auto eye = static_cast<std::size_t>(sections_[static_cast<std::size_t>(segment.to)].eye);
    for (const Eigen::Vector3i& t : triangles) {
      const Eigen::Vector3d& a = mesh_.position_[static_cast<std::size_t>(t[0])];
      const Eigen::Vector3d cross = (mesh_.position_[static_cast<std::size_t>(t[1])] - a)
                                        .cross(mesh_.position_[static_cast<std::size_t>(t[2])] - a);
      // Without area (a pivot) or facing into the skin (folded at a turn): not drawn.
      if (!(cross.dot(mesh_.normal_[static_cast<std::size_t>(t[0])]) > 0)) continue;
      mesh_.triangle_.push_back(t);
      const double area = 0.5 * cross.norm();
      double alpha = 0;
      for (int k = 0; k < 3; ++k) alpha += mesh_.alpha_[static_cast<std::size_t>(t[k])] / 3.0;
      wetArea_[eye] += area * alpha;
    }
  }
}

}  // namespace lacrima::tears
