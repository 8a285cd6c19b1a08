#include "ThreeJsonModel.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/JsonSyntaxError.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QString>

#include <cmath>
#include <limits>
#include <type_traits>

namespace lacrima::rigging {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw FileError(SourceLocation{path}, message);
}

QJsonObject readJsonObject(const std::string& path) {
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly))
    fail(path, "cannot open: " + file.errorString().toStdString());
  const QByteArray bytes = file.readAll();
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
  if (error.error != QJsonParseError::NoError) {
    const std::string_view text(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    throw FileError(jsonSyntaxErrorLocation(text, error, path),
                    "not valid JSON (" + error.errorString().toStdString() + ")");
  }
  if (!document.isObject()) fail(path, "expected a JSON object at the top level");
  return document.object();
}

// The array under `key`; an empty array when the key is absent and not required.
QJsonArray arrayField(const QJsonObject& object, const char* key, const std::string& path,
                      bool required) {
  const QJsonValue value = object.value(QLatin1String(key));
  if (value.isUndefined() && !required) return {};
  if (!value.isArray()) fail(path, std::string("expected an array \"") + key + "\"");
  return value.toArray();
}

double numberAt(const QJsonArray& array, qsizetype i, const char* key, const std::string& path) {
  const QJsonValue value = array.at(i);
  if (!value.isDouble())
    fail(path, std::string("\"") + key + "\"[" + std::to_string(i) + "]: expected a number");
  return value.toDouble();
}

int indexAt(const QJsonArray& array, qsizetype i, const char* key, const std::string& path) {
  const double value = numberAt(array, i, key, path);
  if (value != std::floor(value) || value < 0 || value > std::numeric_limits<int>::max())
    fail(path, std::string("\"") + key + "\"[" + std::to_string(i) +
                   "]: expected a non-negative whole number");
  return static_cast<int>(value);
}

// A flat array of numbers, `width` per column, as a width x n matrix.
template <int Rows>
Eigen::Matrix<float, Rows, Eigen::Dynamic> flatMatrix(const QJsonArray& array, const char* key,
                                                      const std::string& path) {
  if (array.size() % Rows != 0)
    fail(path, std::string("\"") + key + "\" has " + std::to_string(array.size()) +
                   " numbers, expected a multiple of " + std::to_string(Rows));
  Eigen::Matrix<float, Rows, Eigen::Dynamic> m(Rows, array.size() / Rows);
  for (qsizetype i = 0; i < array.size(); ++i)
    m(static_cast<Eigen::Index>(i % Rows), static_cast<Eigen::Index>(i / Rows)) =
        static_cast<float>(numberAt(array, i, key, path));
  return m;
}

// An array of n arrays of exactly three numbers, as a 3 x n matrix.
template <typename Scalar>
Eigen::Matrix<Scalar, 3, Eigen::Dynamic> tripleRows(const QJsonArray& array, const char* key,
                                                    const std::string& path) {
  Eigen::Matrix<Scalar, 3, Eigen::Dynamic> m(3, array.size());
  for (qsizetype i = 0; i < array.size(); ++i) {
    const QJsonArray row = array.at(i).toArray();
    if (row.size() != 3)
      fail(path, std::string("\"") + key + "\"[" + std::to_string(i) +
                     "]: expected an array of 3 numbers");
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(i);
      if constexpr (std::is_integral_v<Scalar>)
        m(k, col) = indexAt(row, k, key, path);
      else
        m(k, col) = static_cast<Scalar>(numberAt(row, k, key, path));
    }
  }
  return m;
}

Eigen::Vector3f colour(const QJsonObject& object, const char* key, const Eigen::Vector3f& fallback,
                       const std::string& path) {
  const QJsonValue value = object.value(QLatin1String(key));
  if (value.isUndefined()) return fallback;
  const QJsonArray rgb = value.toArray();
  if (!value.isArray() || rgb.size() != 3)
    fail(path, std::string("\"") + key + "\": expected an array of 3 numbers");
  return {static_cast<float>(numberAt(rgb, 0, key, path)),
          static_cast<float>(numberAt(rgb, 1, key, path)),
          static_cast<float>(numberAt(rgb, 2, key, path))};
}

ThreeMaterial materialFrom(const QJsonObject& object, const std::string& path) {
  ThreeMaterial m;
  m.name = object.value(QLatin1String("DbgName")).toString().toStdString();
  m.diffuseMap = object.value(QLatin1String("mapDiffuse")).toString().toStdString();
  m.diffuse = colour(object, "colorDiffuse", m.diffuse, path);
  m.specular = colour(object, "colorSpecular", m.specular, path);
  return m;
}

// Face type bits of the format: quad, material, face uv, corner uvs, face normal, corner
// normals, face colour, corner colours.
constexpr int kQuad = 1, kMaterial = 2, kFaceUv = 4, kCornerUv = 8, kFaceNormal = 16,
              kCornerNormal = 32, kFaceColour = 64, kCornerColour = 128;

std::vector<ThreeFace> parseFaces(const QJsonArray& data, int uvLayers, const std::string& path) {
  std::vector<ThreeFace> faces;
  const qsizetype size = data.size();
  qsizetype at = 0;
  // Reads the next entry of the face that started at `start`, or reports where it was cut off.
  auto next = [&](qsizetype start) {
    if (at >= size)
      fail(path, "\"faces\" ends inside the face starting at entry " + std::to_string(start));
    return indexAt(data, at++, "faces", path);
  };
  while (at < size) {
    const qsizetype start = at;
    const int type = next(start);
    if (type > 255)
      fail(path, "\"faces\"[" + std::to_string(start) + "]: unknown face type " +
                     std::to_string(type) + " (expected a three.js format 3 type below 256)");
    ThreeFace face;
    face.corners = (type & kQuad) ? 4 : 3;
    for (int c = 0; c < face.corners; ++c) face.vertex[static_cast<size_t>(c)] = next(start);
    if (type & kMaterial) face.material = next(start);
    if (type & kFaceUv)
      for (int layer = 0; layer < uvLayers; ++layer) next(start);
    if (type & kCornerUv)
      for (int layer = 0; layer < uvLayers; ++layer)
        for (int c = 0; c < face.corners; ++c) {
          const int uv = next(start);
          if (layer == 0) face.uv[static_cast<size_t>(c)] = uv;
        }
    if (type & kFaceNormal) next(start);
    if (type & kCornerNormal)
      for (int c = 0; c < face.corners; ++c) next(start);
    if (type & kFaceColour) next(start);
    if (type & kCornerColour)
      for (int c = 0; c < face.corners; ++c) next(start);
    faces.push_back(face);
  }
  return faces;
}

void checkIndices(const ThreeModel& m) {
  const auto vertexCount = m.vertices.cols();
  const auto uvCount = m.uvs.cols();
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const ThreeFace& face = m.faces[f];
    for (int c = 0; c < face.corners; ++c) {
      const auto k = static_cast<size_t>(c);
      if (face.vertex[k] >= vertexCount)
        fail(m.path, "face " + std::to_string(f) + " uses vertex " +
                         std::to_string(face.vertex[k]) + ", but there are only " +
                         std::to_string(vertexCount));
      if (face.uv[k] >= uvCount)
        fail(m.path, "face " + std::to_string(f) + " uses uv " + std::to_string(face.uv[k]) +
                         ", but there are only " + std::to_string(uvCount));
    }
    if (face.material >= static_cast<int>(m.materials.size()))
      fail(m.path, "face " + std::to_string(f) + " uses material " + std::to_string(face.material) +
                       ", but there are only " + std::to_string(m.materials.size()));
  }
}

}  // namespace

ThreeModel readThreeModel(const std::string& path) {
  const QJsonObject root = readJsonObject(path);
  ThreeModel m;
  m.path = path;

  m.vertices = flatMatrix<3>(arrayField(root, "vertices", path, true), "vertices", path);
  const double scale = root.value(QLatin1String("scale")).toDouble(1.0);
  if (!(scale > 0)) fail(path, "\"scale\" must be a positive number");
  if (scale != 1.0) m.vertices /= static_cast<float>(scale);

  const QJsonArray uvLayers = arrayField(root, "uvs", path, false);
  if (!uvLayers.isEmpty()) {
    if (!uvLayers.at(0).isArray()) fail(path, "\"uvs\": expected an array of uv layers");
    m.uvs = flatMatrix<2>(uvLayers.at(0).toArray(), "uvs", path);
  }

  for (const QJsonValue& material : arrayField(root, "materials", path, false))
    m.materials.push_back(materialFrom(material.toObject(), path));

  m.faces =
      parseFaces(arrayField(root, "faces", path, true), static_cast<int>(uvLayers.size()), path);
  checkIndices(m);

  const QJsonArray refs = arrayField(root, "ref_vIdxs", path, false);
  if (!refs.isEmpty()) {
    m.binding.refs = tripleRows<int>(refs, "ref_vIdxs", path);
    m.binding.weights = tripleRows<float>(arrayField(root, "weights", path, true), "weights", path);
    m.binding.offsets = tripleRows<float>(arrayField(root, "offsets", path, true), "offsets", path);
    const auto n = m.vertices.cols();
    if (m.binding.refs.cols() != n || m.binding.weights.cols() != n ||
        m.binding.offsets.cols() != n)
      fail(path, "a proxy needs one \"ref_vIdxs\", \"weights\" and \"offsets\" entry per vertex (" +
                     std::to_string(n) + " vertices; " + std::to_string(m.binding.refs.cols()) +
                     ", " + std::to_string(m.binding.weights.cols()) + ", " +
                     std::to_string(m.binding.offsets.cols()) + " entries)");
  }
  return m;
}

ThreeMaterial readThreeMaterialFile(const std::string& path) {
  return materialFrom(readJsonObject(path), path);
}

int findThreeMaterial(const ThreeModel& model, std::string_view name) {
  for (size_t i = 0; i < model.materials.size(); ++i)
    if (model.materials[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace lacrima::rigging
