#pragma once
// A binary glTF 2.0 document (.glb) built piece by piece: the head with its morph targets and
// materials, plain triangle meshes, nodes, a skin and keyframed animation channels. The rig
// export (GlbExport.h) writes the head alone; the animation export (lacrima/export/) adds the
// eyes' and head's joints, the FAP weights over time and the tears frame by frame.
//
// Debian's tinygltf writes the JSON and the GLB container; it stays private to this file's
// implementation. The buffer layout is ours: one buffer, every view on a 4-byte boundary,
// accessor min/max on every float accessor (the spec requires them on POSITION and on animation
// inputs), little-endian data.
//
// Every position the document writes (the head, its morph deltas, joints, meshes) is multiplied
// by `unitScale` first: heads come in any unit, glTF's is the metre.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/exporters/RigExport.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lacrima::exporters {

// Joints a head's vertices follow rigidly: each vertex is bound with weight 1 to one joint.
struct GltfHeadSkin {
  struct Joint {
    std::string name;
    int parent = -1;                                     // a joint before this one, or -1
    Eigen::Vector3f position = Eigen::Vector3f::Zero();  // head coordinates, at rest
  };
  std::vector<Joint> joints;       // joints[0] is the root of the skeleton
  std::vector<int> jointOfVertex;  // one per head vertex
};

// A water-like material (KHR_materials_transmission, _ior and _volume, which Blender 3.4's
// importer and three.js read): clear, glossy, refracting; or, without transmission, a glossy
// film with water's reflectance (IOR) over what is under it, tinted and alpha-blended.
struct GltfWater {
  std::string name;
  Eigen::Vector4f baseColor{1, 1, 1, 1};
  double roughness = 0.05;
  double transmission = 1.0;        // 0: no KHR_materials_transmission
  double ior = 1.333;               // water
  double thickness = 0;             // KHR_materials_volume thicknessFactor, metres; 0: thin walled
  bool vertexAlphaBlended = false;  // alphaMode BLEND (with COLOR_0's alpha, if any)
};

// One primitive of a plain mesh, in head coordinates. `alpha`, when given, becomes COLOR_0
// (white, with this alpha per vertex).
struct GltfSurface {
  const Eigen::Matrix3Xd* positions = nullptr;
  const Eigen::Matrix3Xd* normals = nullptr;
  const Eigen::Matrix3Xi* triangles = nullptr;
  const Eigen::VectorXd* alpha = nullptr;
  int material = -1;
};

enum class GltfInterpolation { Linear, Step };

class GltfDocument {
 public:
  explicit GltfDocument(double unitScale = 1.0);
  ~GltfDocument();
  GltfDocument(const GltfDocument&) = delete;
  GltfDocument& operator=(const GltfDocument&) = delete;

  // A node under `parent` (-1: the scene's root).
  int addNode(const std::string& name, int parent = -1);
  void setTranslation(int node, const Eigen::Vector3d& headUnits);  // scaled by unitScale
  void setScale(int node, const Eigen::Vector3d& scale);
  void setMesh(int node, int mesh);

  // The head as one mesh on a new node under `parent`: one primitive per sub-mesh with
  // triangles, its materials and textures (see GlbExport.h for the conventions), one morph target
  // per pose named `targetNames[i]` (mesh.extras.targetNames). With `skin`, the joints become
  // nodes under `parent` (their local translations from their rest positions) and the head is
  // skinned to them. Returns the head's node; `jointNodes` receives the joints' nodes.
  int addHead(const HeadMesh& head, const std::vector<ExportedPose>& poses,
              const std::vector<std::string>& targetNames, int parent,
              const GltfHeadSkin* skin = nullptr, std::vector<int>* jointNodes = nullptr);

  int addWaterMaterial(const GltfWater& water);
  // A mesh of the non-empty surfaces; nullopt when all are empty.
  std::optional<int> addMesh(const std::string& name, std::span<const GltfSurface> surfaces);

  // Animation channels; `times` in seconds, strictly increasing. The one animation is created
  // with the first channel (glTF allows no animation without channels).
  void setAnimationName(const std::string& name);
  // `weights`: times.size() rows of `targets` weights each, row-major.
  void animateWeights(int node, std::span<const float> times, std::span<const float> weights,
                      int targets);
  void animateRotation(int node, std::span<const float> times,
                       std::span<const Eigen::Quaternionf> rotations);
  void animateScale(int node, std::span<const float> times, std::span<const Eigen::Vector3f> scales,
                    GltfInterpolation interpolation);

  std::size_t binaryBytes() const;
  // The .glb, written atomically. Throws FileError naming `path` with the reason.
  void save(const std::string& path) const;

 private:
  struct Model;
  class HeadBuilder;
  std::unique_ptr<Model> model_;
};

}  // namespace lacrima::exporters
