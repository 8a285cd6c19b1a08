#pragma once
// A synthetic head for the pose suites and `lacrima-bench poses`, mirror-symmetric bit for bit
// about x = 0 so that left/right tests can demand exact mirror images:
//   skin      a curved face sheet, x in [-1, 1], y in [-1.25, 0.75], carrying the MPEG-4
//             feature points of groups 2-5 and 8-10 at grid vertices;
//   eye_l/_r  sphere eyeballs (poles on the z axis, front pole = pupil 3.5/3.6) with a
//             slightly larger spherical cap in front for each cornea;
//   tongue    a flat strip facing up, with 6.1 at its tip, 6.2 mid-body, 6.3/6.4 at its sides.
// The FAPUs come from the feature points (ES0 = 1, IRISD0 = 0.25, ENS0 = 0.375, MNS0 = 0.1875,
// MW0 = 0.75). Influences fall off with Euclidean distance inside the point's own sub-mesh,
// w = (1 - (d/r)^2)^2, with the radii the rigging library starts from (MW0 for the chin, MW0/4
// for lips and tongue, ES0/4 for eyelids and ears, ES0/3 brows, ES0/2 cheeks, ENS0/4 nose).
// 3.5/3.6 move their whole eyeball rigidly (weight 1), 6.3/6.4 each half of the tongue.
#include <lacrima/common/FapTable.h>
#include <lacrima/common/Fapu.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseBaking.h>

#include <Eigen/Core>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace lacrima::synthetic {

struct HeadSpec {
  int cellsPerUnit = 16;  // face sheet: (2c + 1) x (2c + 1) vertices
  int eyeRings = 16;      // latitude steps from the front pole to the back pole
  int eyeSegments = 24;   // longitude steps
  int corneaRings = 4;
  int tongueHalfColumns = 4;  // tongue strip: 2h + 1 columns across
  int tongueRows = 8;
  double radiusScale = 1.0;  // multiplies every influence radius
};

inline constexpr float kEyeRadius = 0.2f;
inline constexpr float kCorneaRadius = 0.21f;
inline constexpr double kCorneaPolarAngle = 40.0 * std::numbers::pi / 180.0;
inline constexpr float kTongueY = -0.7f;
inline constexpr float kTongueHalfWidth = 0.2f;
inline constexpr float kTongueFrontZ = 0.1f;
inline constexpr float kTongueLength = 0.4f;

inline Eigen::Vector3f leftEyeCentre() { return {0.5f, 0.0f, 0.0f}; }
inline Eigen::Vector3f rightEyeCentre() { return {-0.5f, 0.0f, 0.0f}; }
inline Eigen::Vector3f neckPivot() { return {0.0f, -1.5f, -0.5f}; }

struct Head {
  HeadMesh mesh;
  FapuSet fapu;
  std::map<std::string, FeaturePointInfluence> influences;
  std::map<std::string, Eigen::Vector3f> featurePoints;
  std::map<std::string, int> featureVertex;  // the vertex at each feature point
  RotationGroup eyeLeft, eyeRight;
  std::vector<int> mirror;  // vertex -> its image under x -> -x

  // A rig that points at this head's mesh: keep the Head alive (and unmoved) while it is used.
  RigInput rig() const {
    RigInput in;
    in.mesh = &mesh;
    in.fapu = fapu;
    in.influences = influences;
    in.featurePoints = featurePoints;
    in.eyeLeft = eyeLeft;
    in.eyeRight = eyeRight;
    in.neckPivot = neckPivot();
    return in;
  }
};

namespace detail {

inline float sheetDepth(float x, float y) {
  // x enters squared only, so mirrored vertices get the same depth bit for bit.
  return 0.3f - 0.15f * x * x - 0.1f * (y + 0.25f) * (y + 0.25f);
}

// Appends a sub-mesh; returns its first vertex.
inline int appendSubmesh(HeadMesh& mesh, const std::string& name,
                         const std::vector<Eigen::Vector3f>& points,
                         const std::vector<Eigen::Vector3i>& localTriangles, bool flipWinding) {
  const int first = mesh.vertexCount();
  const int count = static_cast<int>(points.size());
  mesh.positions.conservativeResize(3, first + count);
  for (int k = 0; k < count; ++k) mesh.positions.col(first + k) = points[static_cast<size_t>(k)];
  HeadSubmesh sub;
  sub.name = name;
  sub.firstVertex = first;
  sub.vertexCount = count;
  for (const Eigen::Vector3i& t : localTriangles)
    sub.triangles.push_back(flipWinding ? Eigen::Vector3i(t[0] + first, t[2] + first, t[1] + first)
                                        : Eigen::Vector3i(t + Eigen::Vector3i::Constant(first)));
  mesh.submeshes.push_back(std::move(sub));
  return first;
}

// Two counter-clockwise (seen from the side `a -> b` x `a -> d` points to) triangles per quad
// (a, b, c, d) of a grid whose vertex (i, j) is i + j * columns.
inline void gridTriangles(int columns, int rows, std::vector<Eigen::Vector3i>& out) {
  for (int j = 0; j + 1 < rows; ++j)
    for (int i = 0; i + 1 < columns; ++i) {
      const int a = i + j * columns, b = a + 1, c = b + columns, d = a + columns;
      out.emplace_back(a, b, c);
      out.emplace_back(a, c, d);
    }
}

// A sphere (or its front cap up to `maxPolar`) about `centre`, poles on the z axis. Vertex 0 is
// the front pole (+z); rings follow at polar angles k * step; a full sphere ends in the back
// pole. Outward-facing triangles.
inline void sphere(const Eigen::Vector3f& centre, float radius, int rings, int segments,
                   double maxPolar, bool full, std::vector<Eigen::Vector3f>& points,
                   std::vector<Eigen::Vector3i>& triangles) {
  const double step = maxPolar / rings;
  points.push_back(centre + Eigen::Vector3f(0, 0, radius));
  const int lastRing = full ? rings - 1 : rings;
  for (int k = 1; k <= lastRing; ++k) {
    const double polar = k * step;
    for (int s = 0; s < segments; ++s) {
      const double azimuth = 2.0 * std::numbers::pi * s / segments;
      points.push_back(centre + Eigen::Vector3f(float(radius * std::sin(polar) * std::cos(azimuth)),
                                                float(radius * std::sin(polar) * std::sin(azimuth)),
                                                float(radius * std::cos(polar))));
    }
  }
  auto ring = [&](int k, int s) { return 1 + (k - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) triangles.emplace_back(0, ring(1, s), ring(1, s + 1));
  for (int k = 1; k < lastRing; ++k)
    for (int s = 0; s < segments; ++s) {
      triangles.emplace_back(ring(k, s), ring(k + 1, s), ring(k + 1, s + 1));
      triangles.emplace_back(ring(k, s), ring(k + 1, s + 1), ring(k, s + 1));
    }
  if (full) {
    const int back = static_cast<int>(points.size());
    points.push_back(centre - Eigen::Vector3f(0, 0, radius));
    for (int s = 0; s < segments; ++s)
      triangles.emplace_back(ring(lastRing, s), back, ring(lastRing, s + 1));
  }
}

// Influence radius by feature-point group, as fractions of the face's FAPUs.
inline double influenceRadius(const std::string& id, const FapuSet& f) {
  const int group = std::stoi(id.substr(0, id.find('.')));
  const int index = std::stoi(id.substr(id.find('.') + 1));
  switch (group) {
    case 2:
      return index == 1 || index >= 10 ? f.mw0 : f.mw0 / 4;
    case 6:
    case 8:
      return f.mw0 / 4;
    case 3:
    case 10:
      return f.es0 / 4;
    case 4:
      return f.es0 / 3;
    case 9:
      return f.ens0 / 4;
    default:
      return f.es0 / 2;
  }
}

struct SheetPoint {
  const char* left;   // id at +x (or the centre id)
  const char* right;  // mirrored id at -x, or nullptr for a point on the midline
  double x, y;
};

// Targets on a 1/16 grid; snapped to the nearest sheet vertex for other resolutions.
inline const std::vector<SheetPoint>& sheetPoints() {
  static const std::vector<SheetPoint> points{
      {"2.1", nullptr, 0, -1.125},     {"2.2", nullptr, 0, -0.5625},
      {"2.3", nullptr, 0, -0.6875},    {"2.4", "2.5", 0.3125, -0.625},
      {"2.6", "2.7", 0.1875, -0.5625}, {"2.8", "2.9", 0.1875, -0.6875},
      {"2.10", nullptr, 0, -0.9375},   {"3.1", "3.2", 0.5, 0.125},
      {"3.3", "3.4", 0.5, -0.125},     {"4.1", "4.2", 0.25, 0.3125},
      {"4.3", "4.4", 0.5, 0.375},      {"4.5", "4.6", 0.75, 0.3125},
      {"5.1", "5.2", 0.6875, -0.4375}, {"5.3", "5.4", 0.5625, -0.25},
      {"8.1", nullptr, 0, -0.5},       {"8.2", nullptr, 0, -0.75},
      {"8.3", "8.4", 0.375, -0.625},   {"8.5", "8.6", 0.1875, -0.5},
      {"8.7", "8.8", 0.1875, -0.75},   {"9.1", "9.2", 0.1875, -0.3125},
      {"9.3", nullptr, 0, -0.25},      {"9.15", nullptr, 0, -0.375},
      {"10.1", "10.2", 0.9375, 0.125}, {"10.3", "10.4", 0.9375, -0.125},
  };
  return points;
}

inline void addFalloffInfluence(Head& head, const std::string& id, const HeadSubmesh& sub,
                                double radius) {
  const Eigen::Vector3f p = head.featurePoints.at(id);
  FeaturePointInfluence& influence = head.influences[id];
  for (int v = sub.firstVertex; v < sub.firstVertex + sub.vertexCount; ++v) {
    const double d = (head.mesh.positions.col(v) - p).cast<double>().norm();
    if (d >= radius) continue;
    const double t = 1.0 - (d / radius) * (d / radius);
    influence.vertices.push_back(v);
    influence.weights.push_back(static_cast<float>(t * t));
  }
}

}  // namespace detail

inline Head buildHead(const HeadSpec& spec = {}) {
  using namespace detail;
  Head head;
  HeadMesh& mesh = head.mesh;
  mesh.positions.resize(3, 0);

  // Face sheet; column i sits at x = (i - c) / c, so columns i and 2c - i are exact mirrors.
  const int c = spec.cellsPerUnit, columns = 2 * c + 1, rows = 2 * c + 1;
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3i> triangles;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const float x = float(i - c) / float(c), y = -1.25f + float(j) / float(c);
      points.emplace_back(x, y, sheetDepth(x, y));
    }
  gridTriangles(columns, rows, triangles);
  const int skin = appendSubmesh(mesh, "skin", points, triangles, false);
  auto sheetVertex = [&](int i, int j) { return skin + i + j * columns; };

  // Eyes and corneas: the right ones are the left ones mirrored, with the winding flipped so
  // they still face outward.
  auto mirrored = [](std::vector<Eigen::Vector3f> p) {
    for (Eigen::Vector3f& q : p) q.x() = -q.x();
    return p;
  };
  std::vector<Eigen::Vector3f> eye, cornea;
  std::vector<Eigen::Vector3i> eyeTriangles, corneaTriangles;
  sphere(leftEyeCentre(), kEyeRadius, spec.eyeRings, spec.eyeSegments, std::numbers::pi, true, eye,
         eyeTriangles);
  sphere(leftEyeCentre(), kCorneaRadius, spec.corneaRings, spec.eyeSegments, kCorneaPolarAngle,
         false, cornea, corneaTriangles);
  const int eyeL = appendSubmesh(mesh, "eye_l", eye, eyeTriangles, false);
  const int corneaL = appendSubmesh(mesh, "cornea_l", cornea, corneaTriangles, false);
  const int eyeR = appendSubmesh(mesh, "eye_r", mirrored(eye), eyeTriangles, true);
  const int corneaR = appendSubmesh(mesh, "cornea_r", mirrored(cornea), corneaTriangles, true);

  // Tongue strip in the x-z plane facing up: column i at x = (i - h) / h * half width, row j
  // running back from the tip.
  const int h = spec.tongueHalfColumns, tongueColumns = 2 * h + 1, tongueRows = spec.tongueRows + 1;
  points.clear();
  triangles.clear();
  for (int j = 0; j < tongueRows; ++j)
    for (int i = 0; i < tongueColumns; ++i)
      points.emplace_back(kTongueHalfWidth * float(i - h) / float(h), kTongueY,
                          kTongueFrontZ - kTongueLength * float(j) / float(spec.tongueRows));
  gridTriangles(tongueColumns, tongueRows, triangles);
  const int tongue = appendSubmesh(mesh, "tongue", points, triangles, false);
  auto tongueVertex = [&](int i, int j) { return tongue + i + j * tongueColumns; };

  const int n = mesh.vertexCount();
  head.mirror.resize(static_cast<size_t>(n));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i)
      head.mirror[size_t(sheetVertex(i, j))] = sheetVertex(columns - 1 - i, j);
  for (int k = 0; k < static_cast<int>(eye.size()); ++k) {
    head.mirror[size_t(eyeL + k)] = eyeR + k;
    head.mirror[size_t(eyeR + k)] = eyeL + k;
  }
  for (int k = 0; k < static_cast<int>(cornea.size()); ++k) {
    head.mirror[size_t(corneaL + k)] = corneaR + k;
    head.mirror[size_t(corneaR + k)] = corneaL + k;
  }
  for (int j = 0; j < tongueRows; ++j)
    for (int i = 0; i < tongueColumns; ++i)
      head.mirror[size_t(tongueVertex(i, j))] = tongueVertex(tongueColumns - 1 - i, j);

  // Feature points at vertices.
  auto place = [&](const std::string& id, int v) {
    head.featureVertex[id] = v;
    head.featurePoints[id] = mesh.positions.col(v);
  };
  for (const SheetPoint& p : sheetPoints()) {
    const int i = c + static_cast<int>(std::lround(p.x * c));
    const int j = static_cast<int>(std::lround((p.y + 1.25) * c));
    place(p.left, sheetVertex(i, j));
    if (p.right) place(p.right, sheetVertex(columns - 1 - i, j));
  }
  place("3.5", eyeL);  // front poles
  place("3.6", eyeR);
  const int middleRow = spec.tongueRows / 2;
  place("6.1", tongueVertex(h, 0));
  place("6.2", tongueVertex(h, middleRow));
  place("6.3", tongueVertex(tongueColumns - 1, middleRow));
  place("6.4", tongueVertex(0, middleRow));
  head.featurePoints["7.1"] = neckPivot();

  auto point = [&](const char* id) { return head.featurePoints.at(id).cast<double>(); };
  head.fapu = computeFapu({point("3.1"), point("3.2"), point("3.3"), point("3.4"), point("3.5"),
                           point("3.6"), point("9.15"), point("2.2"), point("8.3"), point("8.4")});

  // Influences.
  for (const auto& [id, v] : head.featureVertex) {
    const HeadSubmesh& sub = mesh.submeshes[size_t(mesh.submeshOfVertex(v))];
    if (sub.name == "skin" || id == "6.1" || id == "6.2")
      addFalloffInfluence(head, id, sub, spec.radiusScale * influenceRadius(id, head.fapu));
  }
  auto rigid = [&](const std::string& id, std::initializer_list<int> firsts, int count0,
                   int count1) {
    FeaturePointInfluence& influence = head.influences[id];
    int k = 0;
    for (int first : firsts) {
      for (int v = first; v < first + (k == 0 ? count0 : count1); ++v) {
        influence.vertices.push_back(v);
        influence.weights.push_back(1.0f);
      }
      ++k;
    }
  };
  rigid("3.5", {eyeL, corneaL}, int(eye.size()), int(cornea.size()));
  rigid("3.6", {eyeR, corneaR}, int(eye.size()), int(cornea.size()));
  for (int j = 0; j < tongueRows; ++j)
    for (int i = 0; i < tongueColumns; ++i) {
      // Each half, the midline in both: the two sides curl alike.
      if (i >= h) head.influences["6.3"].vertices.push_back(tongueVertex(i, j));
      if (i <= h) head.influences["6.4"].vertices.push_back(tongueVertex(i, j));
    }
  for (const char* id : {"6.3", "6.4"})
    head.influences[id].weights.assign(head.influences[id].vertices.size(), 1.0f);

  auto group = [&](int first, int count0, int corneaFirst, int count1,
                   const Eigen::Vector3f& centre) {
    RotationGroup g;
    for (int v = first; v < first + count0; ++v) g.vertices.push_back(v);
    for (int v = corneaFirst; v < corneaFirst + count1; ++v) g.vertices.push_back(v);
    g.centre = centre;
    return g;
  };
  head.eyeLeft = group(eyeL, int(eye.size()), corneaL, int(cornea.size()), leftEyeCentre());
  head.eyeRight = group(eyeR, int(eye.size()), corneaR, int(cornea.size()), rightEyeCentre());

  mesh.computeNormals();
  return head;
}

}  // namespace lacrima::synthetic
