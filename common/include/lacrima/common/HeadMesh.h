#pragma once
// A head as plain data: one vertex array shared by named sub-meshes, in the face frame
// (+y up, +x the face's own left, +z forward). Loaders fill it, rigging reads it, pose
// blending deforms copies of its positions, the tear simulation collides with its skin.
#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

struct HeadMaterial {
  std::string name;
  std::string diffuseTexture;  // absolute path, or empty for a plain colour
  Eigen::Vector4f diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  Eigen::Vector3f specular{0.1f, 0.1f, 0.1f};
  float shininess = 16.0f;
  bool transparent = false;  // texture alpha matters (eyelashes, eyebrows)
};

// A sub-mesh owns the contiguous vertex range [firstVertex, firstVertex + vertexCount):
// a feature point's "vertex i of sub-mesh S" is global vertex S.firstVertex + i.
struct HeadSubmesh {
  std::string name;   // role for the default head: skin, eye_l, eye_r, cornea_l, cornea_r,
                      // teeth_upper, teeth_lower, tongue, eyelashes, eyebrows; else as loaded
  int material = -1;  // index into HeadMesh::materials, -1 for none
  int firstVertex = 0;
  int vertexCount = 0;
  std::vector<Eigen::Vector3i> triangles;  // global vertex indices, counter-clockwise outside
  // Its role in the rig (skin, eye_left, eye_right, jaw, tongue, attached, ignored, rigid), set
  // when the head is rigged; empty before. The scene draws untextured parts by it. Last and
  // defaulted, so that a part written as {name, material, first, count, triangles} needs none.
  std::string role = {};
};

struct HeadMesh {
  Eigen::Matrix3Xf positions;  // 3 x n
  Eigen::Matrix3Xf normals;    // 3 x n, unit
  Eigen::Matrix2Xf uvs;        // 2 x n, or 2 x 0 when the mesh has none (v down, OGRE style)
  std::vector<HeadSubmesh> submeshes;
  std::vector<HeadMaterial> materials;

  int vertexCount() const { return static_cast<int>(positions.cols()); }
  int triangleCount() const;

  const HeadSubmesh* findSubmesh(std::string_view name) const;  // nullptr if absent
  int submeshOfVertex(int vertex) const;                        // -1 if none

  // Area-weighted vertex normals. Vertices at the same position (uv seams) share one normal,
  // so lighting shows no seams.
  void computeNormals();

  // Axis-aligned bounds of all positions.
  Eigen::Vector3f boundsMin() const;
  Eigen::Vector3f boundsMax() const;
};

// For each vertex, the lowest-numbered vertex at exactly the same position (uv-seam copies
// share one root). Used wherever topology matters more than texture layout.
std::vector<int> weldCoincidentVertices(const Eigen::Matrix3Xf& positions);

// Area-weighted unit normals of `positions` over `triangles`, accumulated per weld root so seam
// copies get the same normal; vertices on no triangle get +z.
void accumulateNormals(const Eigen::Matrix3Xf& positions,
                       const std::vector<Eigen::Vector3i>& triangles, const std::vector<int>& weld,
                       Eigen::Matrix3Xf& normals);

}  // namespace lacrima::inline common
