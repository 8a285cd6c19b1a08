#include "ThreeJsonModel.h"

#include <lacrima/common/JsonInput.h>

#include <limits>
#include <type_traits>

namespace lacrima::rigging {

namespace {

// The MakeHuman body is 2.4 MB; the bounds leave a wide margin over any head.
constexpr qint64 kMaxFileBytes = qint64{256} << 20;
constexpr std::size_t kMaxVertices = std::size_t{1} << 22;
constexpr std::size_t kMaxFaceEntries = std::size_t{1} << 26;  // up to 22 entries a face
constexpr std::size_t kMaxMaterials = 4096;
constexpr std::size_t kMaxUvLayers = 16;
constexpr int kMaxIndex = std::numeric_limits<int>::max();

JsonValue readJsonObject(const std::string& path) {
  return JsonInput::load(path, {"three.js model", kMaxFileBytes}).root();
}

// A flat array of numbers, `Rows` per column, as a Rows x n matrix.
template <int Rows>
Eigen::Matrix<float, Rows, Eigen::Dynamic> flatMatrix(const JsonValue& array) {
  const std::vector<double> numbers = array.numbers(Rows * kMaxVertices);
  if (numbers.size() % Rows != 0)
    array.fail("expected a multiple of " + std::to_string(Rows) + " numbers, got " +
               array.describe());
  return Eigen::Map<const Eigen::Matrix<double, Rows, Eigen::Dynamic>>(
             numbers.data(), Rows, static_cast<Eigen::Index>(numbers.size() / Rows))
      .template cast<float>();
}

// An array of n arrays of exactly three numbers, as a 3 x n matrix.
template <typename Scalar>
Eigen::Matrix<Scalar, 3, Eigen::Dynamic> tripleRows(const JsonValue& array) {
  const std::vector<JsonValue> rows = array.array(kMaxVertices);
  Eigen::Matrix<Scalar, 3, Eigen::Dynamic> m(3, static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].isArray() || rows[i].size() != 3)
      rows[i].fail("expected an array of 3 numbers, got " + rows[i].describe());
    const Eigen::Index col = static_cast<Eigen::Index>(i);
    if constexpr (std::is_integral_v<Scalar>) {
      const std::vector<int> row = rows[i].integers(0, kMaxIndex, 3);
      m.col(col) << row[0], row[1], row[2];
    } else {
      const std::vector<double> row = rows[i].numbers(3);
      m.col(col) << static_cast<Scalar>(row[0]), static_cast<Scalar>(row[1]),
          static_cast<Scalar>(row[2]);
    }
  }
  return m;
}

Eigen::Vector3f colour(const JsonValue& object, const char* key, const Eigen::Vector3f& fallback) {
  if (!object.has(key)) return fallback;
  const JsonValue rgb = object[key];
  if (!rgb.isArray() || rgb.size() != 3)
    rgb.fail("expected an array of 3 numbers, got " + rgb.describe());
  const std::vector<double> value = rgb.numbers(3);
  return Eigen::Vector3d(value[0], value[1], value[2]).cast<float>();
}

std::string optionalText(const JsonValue& object, const char* key) {
  return object.has(key) ? object[key].string() : std::string();
}

ThreeMaterial materialFrom(const JsonValue& object) {
  object.object();
  ThreeMaterial m;
  m.name = optionalText(object, "DbgName");
  m.diffuseMap = optionalText(object, "mapDiffuse");
  m.diffuse = colour(object, "colorDiffuse", m.diffuse);
  m.specular = colour(object, "colorSpecular", m.specular);
  return m;
}

// Face type bits of the format: quad, material, face uv, corner uvs, face normal, corner
// normals, face colour, corner colours.
constexpr int kQuad = 1, kMaterial = 2, kFaceUv = 4, kCornerUv = 8, kFaceNormal = 16,
              kCornerNormal = 32, kFaceColour = 64, kCornerColour = 128;

// Reads "faces" and checks every vertex, uv and material index against what `m` has.
std::vector<ThreeFace> parseFaces(const JsonValue& faces, int uvLayers, const ThreeModel& m) {
  const std::vector<int> data = faces.integers(0, kMaxIndex, kMaxFaceEntries);
  std::vector<ThreeFace> out;
  std::size_t at = 0;
  // Reads the next entry of the face that started at `start`, or reports where it was cut off.
  auto next = [&](std::size_t start) {
    if (at >= data.size()) faces.element(start).fail("\"faces\" ends inside this face");
    return data[at++];
  };
  // The next entry, an index into something `m` has `count` of.
  auto index = [&](std::size_t start, Eigen::Index count, const char* what) {
    const std::size_t here = at;
    const int value = next(start);
    if (value >= count)
      faces.element(here).fail("face " + std::to_string(out.size()) + " uses " + what + " " +
                               std::to_string(value) + ", but there are only " +
                               std::to_string(count));
    return value;
  };
  const auto materialCount = static_cast<Eigen::Index>(m.materials.size());
  while (at < data.size()) {
    const std::size_t start = at;
    const int type = next(start);
    if (type > 255)
      faces.element(start).fail("unknown face type " + std::to_string(type) +
                                " (expected a three.js format 3 type below 256)");
    ThreeFace face;
    face.corners = (type & kQuad) ? 4 : 3;
    for (int c = 0; c < face.corners; ++c)
      face.vertex[static_cast<size_t>(c)] = index(start, m.vertices.cols(), "vertex");
    if (type & kMaterial) face.material = index(start, materialCount, "material");
    if (type & kFaceUv)
      for (int layer = 0; layer < uvLayers; ++layer) next(start);
    if (type & kCornerUv)
      for (int layer = 0; layer < uvLayers; ++layer)
        for (int c = 0; c < face.corners; ++c) {
          if (layer == 0)
            face.uv[static_cast<size_t>(c)] = index(start, m.uvs.cols(), "uv");
          else
            next(start);
        }
    if (type & kFaceNormal) next(start);
    if (type & kCornerNormal)
      for (int c = 0; c < face.corners; ++c) next(start);
    if (type & kFaceColour) next(start);
    if (type & kCornerColour)
      for (int c = 0; c < face.corners; ++c) next(start);
    out.push_back(face);
  }
  return out;
}

}  // namespace

ThreeModel readThreeModel(const std::string& path) {
  const JsonValue root = readJsonObject(path);
  ThreeModel m;
  m.path = path;

  m.vertices = flatMatrix<3>(root.required("vertices"));
  if (root.has("scale")) {
    const double scale = root["scale"].number();
    if (!(scale > 0))
      root["scale"].fail("expected a positive number, got " + root["scale"].describe());
    if (scale != 1.0) m.vertices /= static_cast<float>(scale);
  }

  std::vector<JsonValue> uvLayers;
  if (root.has("uvs")) uvLayers = root["uvs"].array(kMaxUvLayers);
  if (!uvLayers.empty()) m.uvs = flatMatrix<2>(uvLayers.front());

  if (root.has("materials"))
    for (const JsonValue& material : root["materials"].array(kMaxMaterials))
      m.materials.push_back(materialFrom(material));

  m.faces = parseFaces(root.required("faces"), static_cast<int>(uvLayers.size()), m);

  if (root.has("ref_vIdxs")) m.binding.refs = tripleRows<int>(root["ref_vIdxs"]);
  if (m.isProxy()) {
    m.binding.weights = tripleRows<float>(root.required("weights"));
    m.binding.offsets = tripleRows<float>(root.required("offsets"));
    const auto n = m.vertices.cols();
    if (m.binding.refs.cols() != n || m.binding.weights.cols() != n ||
        m.binding.offsets.cols() != n)
      root.fail("a proxy needs one \"ref_vIdxs\", \"weights\" and \"offsets\" entry per vertex (" +
                std::to_string(n) + " vertices; " + std::to_string(m.binding.refs.cols()) + ", " +
                std::to_string(m.binding.weights.cols()) + ", " +
                std::to_string(m.binding.offsets.cols()) + " entries)");
  }
  return m;
}

ThreeMaterial readThreeMaterialFile(const std::string& path) {
  return materialFrom(readJsonObject(path));
}

int findThreeMaterial(const ThreeModel& model, std::string_view name) {
  for (size_t i = 0; i < model.materials.size(); ++i)
    if (model.materials[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace lacrima::rigging
