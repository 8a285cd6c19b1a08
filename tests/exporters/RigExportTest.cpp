// Rig export: the .mesh and .material read back through OGRE without a window, the .glb read
// back through assimp and byte by byte, and the failure paths (missing folder, missing
// texture, bad poses) leave the target folder exactly as it was.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/exporters/GlbExport.h>
#include <lacrima/exporters/HeadlessOgre.h>
#include <lacrima/exporters/OgreMeshExport.h>
#include <lacrima/exporters/RigExport.h>

#include <OgreAnimation.h>
#include <OgreAnimationTrack.h>
#include <OgreHardwareBufferManager.h>
#include <OgreKeyFrame.h>
#include <OgreMaterial.h>
#include <OgreMaterialManager.h>
#include <OgreMesh.h>
#include <OgreMeshManager.h>
#include <OgrePass.h>
#include <OgrePose.h>
#include <OgreResourceGroupManager.h>
#include <OgreSubMesh.h>
#include <OgreTechnique.h>
#include <OgreTextureUnitState.h>

#include <assimp/cimport.h>
#include <assimp/scene.h>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cstdint>
#include <cstring>
#include <map>
#include <memory>

using namespace lacrima;

namespace {

constexpr int kOpenJaw = 3;
constexpr int kDilateLeftPupil = 29;
constexpr int kRaiseLeftInnerBrow = 31;
const char* const kGroup = "RigExportTest";

std::string str(const QString& s) { return s.toStdString(); }

// Three sub-meshes over 19 vertices:
//   skin       vertices 0-11, a 4 x 3 grid in the z = 0 plane, textured, material "skin";
//   eyelashes  vertices 12-15, one quad, transparent material "lashes";
//   cornea_l   vertices 16-18, one triangle, material "clear" (a cornea by its sub-mesh role).
HeadMesh syntheticHead(const std::string& texturePath) {
  HeadMesh head;
  head.positions.resize(3, 19);
  head.uvs.resize(2, 19);
  HeadSubmesh skin{"skin", 0, 0, 12, {}};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 4; ++col) {
      const int v = row * 4 + col;
      head.positions.col(v) =
          Eigen::Vector3f(0.25f * static_cast<float>(col), 0.5f * static_cast<float>(row), 0.0f);
      head.uvs.col(v) =
          Eigen::Vector2f(static_cast<float>(col) / 3.0f, 1.0f - static_cast<float>(row) / 2.0f);
    }
  }
  for (int row = 0; row < 2; ++row) {
    for (int col = 0; col < 3; ++col) {
      const int v = row * 4 + col;
      skin.triangles.emplace_back(v, v + 1, v + 5);
      skin.triangles.emplace_back(v, v + 5, v + 4);
    }
  }
  HeadSubmesh lashes{"eyelashes", 1, 12, 4, {{12, 13, 14}, {12, 14, 15}}};
  head.positions.col(12) = Eigen::Vector3f(0.1f, 1.1f, 0.2f);
  head.positions.col(13) = Eigen::Vector3f(0.4f, 1.1f, 0.2f);
  head.positions.col(14) = Eigen::Vector3f(0.4f, 1.2f, 0.25f);
  head.positions.col(15) = Eigen::Vector3f(0.1f, 1.2f, 0.25f);
  HeadSubmesh cornea{"cornea_l", 2, 16, 3, {{16, 17, 18}}};
  head.positions.col(16) = Eigen::Vector3f(0.5f, 0.9f, 0.3f);
  head.positions.col(17) = Eigen::Vector3f(0.6f, 0.9f, 0.3f);
  head.positions.col(18) = Eigen::Vector3f(0.55f, 1.0f, 0.32f);
  for (int v = 12; v < 19; ++v)
    head.uvs.col(v) = Eigen::Vector2f(0.1f * static_cast<float>(v - 12), 0.25f);
  head.submeshes = {skin, lashes, cornea};

  HeadMaterial skinMaterial;
  skinMaterial.name = "skin";
  skinMaterial.diffuseTexture = texturePath;
  skinMaterial.diffuse = Eigen::Vector4f(0.9f, 0.8f, 0.7f, 1.0f);
  skinMaterial.specular = Eigen::Vector3f(0.2f, 0.2f, 0.25f);
  skinMaterial.shininess = 20.0f;
  HeadMaterial lashMaterial;
  lashMaterial.name = "lashes";
  lashMaterial.diffuse = Eigen::Vector4f(0.1f, 0.1f, 0.1f, 1.0f);
  lashMaterial.transparent = true;
  HeadMaterial clear;
  clear.name = "clear";
  clear.diffuse = Eigen::Vector4f(0.0f, 0.0f, 0.0f, 0.0f);
  clear.transparent = true;
  head.materials = {skinMaterial, lashMaterial, clear};
  head.computeNormals();
  return head;
}

// open_jaw moves skin and lash vertices (vertex 1 is listed twice: the two entries add up),
// the pupil pose moves the cornea, the brow pose two skin vertices; the eye and head turn.
PoseSet syntheticPoses() {
  PoseSet poses;
  poses.vertexCount = 19;
  VertexPose& jaw = poses.poses[channelIndex(kOpenJaw)];
  jaw.vertices = {0, 1, 2, 12, 13, 1};
  jaw.offsets.resize(3, 6);
  jaw.offsets << 0, 0, 0, 0, 0, 1e-5f,                 //
      -3e-4f, -2e-4f, -1e-4f, -5e-5f, -5e-5f, -1e-4f,  //
      1e-5f, 2e-5f, 0, 0, 0, 3e-5f;
  VertexPose& pupil = poses.poses[channelIndex(kDilateLeftPupil)];
  pupil.vertices = {16, 17};
  pupil.offsets.resize(3, 2);
  pupil.offsets << -2e-5f, 2e-5f, 0, 0, 0, 0;
  VertexPose& brow = poses.poses[channelIndex(kRaiseLeftInnerBrow)];
  brow.vertices = {9, 10};
  brow.offsets.resize(3, 2);
  brow.offsets << 0, 0, 2.5e-4f, 2e-4f, 0, 0;
  poses.eyeLeft.vertices = {16, 17, 18};
  poses.eyeLeft.centre = Eigen::Vector3f(0.55f, 0.95f, 0.2f);
  for (int v = 0; v < 19; ++v) poses.head.vertices.push_back(v);
  poses.head.centre = Eigen::Vector3f(0.3f, -0.5f, -0.2f);
  return poses;
}

const std::vector<int> kExportedFaps = {kOpenJaw, kDilateLeftPupil, kRaiseLeftInnerBrow};
const QStringList kExportedNames = {"fap03_open_jaw", "fap29_dilate_l_pupil",
                                    "fap31_raise_l_i_eyebrow"};

// What an exported pose must hold, computed independently of the exporter: entries per vertex
// summed, times 1024.
std::map<int, Eigen::Vector3f> expectedOffsets(const PoseSet& poses, int fap) {
  std::map<int, Eigen::Vector3f> sum;
  const VertexPose& pose = poses.poses[channelIndex(fap)];
  for (std::size_t k = 0; k < pose.vertices.size(); ++k) {
    auto [it, isNew] = sum.try_emplace(pose.vertices[k], Eigen::Vector3f::Zero());
    it->second += pose.offsets.col(static_cast<Eigen::Index>(k));
  }
  for (auto& [v, offset] : sum) offset *= 1024.0f;
  return sum;
}

void writeTexture(const QString& path) {
  QImage image(4, 4, QImage::Format_RGBA8888);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) image.setPixelColor(x, y, QColor(60 * x, 60 * y, 200, 255));
  image.setPixelColor(0, 0, QColor(255, 0, 0, 255));  // marks the upper left corner
  QVERIFY(image.save(path, "PNG"));
}

QStringList entries(const QString& dir) {
  return QDir(dir).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden, QDir::Name);
}

// The what() of the FileError that `action` throws; empty when it throws nothing.
template <typename Action>
QString fileErrorOf(Action action) {
  try {
    action();
  } catch (const FileError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

QByteArray readAll(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return file.readAll();
}

// Loads a .mesh from `dir` (registered as a resource location, so its .material is parsed too).
Ogre::MeshPtr loadMesh(const QString& dir, const std::string& name) {
  auto& groups = Ogre::ResourceGroupManager::getSingleton();
  groups.addResourceLocation(str(dir), "FileSystem", kGroup);
  groups.initialiseResourceGroup(kGroup);
  return Ogre::MeshManager::getSingleton().load(name, kGroup);
}

// `components` floats per vertex of the element with `semantic`, read from the vertex buffer.
std::vector<float> readElement(const Ogre::VertexData& data, Ogre::VertexElementSemantic semantic,
                               int components) {
  std::vector<float> values;
  const Ogre::VertexElement* element = data.vertexDeclaration->findElementBySemantic(semantic);
  if (!element) return values;
  const Ogre::HardwareVertexBufferSharedPtr& buffer =
      data.vertexBufferBinding->getBuffer(element->getSource());
  const auto* base =
      static_cast<const unsigned char*>(buffer->lock(Ogre::HardwareBuffer::HBL_READ_ONLY));
  for (std::size_t v = 0; v < data.vertexCount; ++v) {
    float value[4];
    std::memcpy(value, base + v * buffer->getVertexSize() + element->getOffset(),
                sizeof(float) * static_cast<std::size_t>(components));
    values.insert(values.end(), value, value + components);
  }
  buffer->unlock();
  return values;
}

std::size_t resourceCount(Ogre::ResourceManager& manager) {
  std::size_t count = 0;
  for (auto it = manager.getResourceIterator(); it.hasMoreElements(); it.moveNext()) ++count;
  return count;
}

std::vector<std::uint32_t> readIndices(const Ogre::IndexData& data) {
  std::vector<std::uint32_t> indices;
  if (data.indexCount == 0) return indices;
  const auto& buffer = data.indexBuffer;
  const void* base = buffer->lock(Ogre::HardwareBuffer::HBL_READ_ONLY);
  for (std::size_t i = 0; i < data.indexCount; ++i) {
    if (buffer->getType() == Ogre::HardwareIndexBuffer::IT_16BIT)
      indices.push_back(static_cast<const std::uint16_t*>(base)[i]);
    else
      indices.push_back(static_cast<const std::uint32_t*>(base)[i]);
  }
  buffer->unlock();
  return indices;
}

std::vector<std::uint32_t> flatten(const std::vector<Eigen::Vector3i>& triangles, int base = 0) {
  std::vector<std::uint32_t> indices;
  for (const Eigen::Vector3i& t : triangles)
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint32_t>(t[k] - base));
  return indices;
}

std::vector<float> columns(const Eigen::MatrixXf& m, int first, int count) {
  const Eigen::MatrixXf block = m.middleCols(first, count);
  return std::vector<float>(block.data(), block.data() + block.size());
}

// A parsed .glb: its JSON and BIN chunks, after the container layout has been checked.
struct Glb {
  QJsonObject json;
  QByteArray bin;

  QJsonObject at(const char* array, int index) const {
    return json[array].toArray()[index].toObject();
  }

  // The elements of accessor `index`, honouring the buffer view's stride.
  template <typename T>
  std::vector<T> read(int index) const {
    const QJsonObject accessor = at("accessors", index);
    const QJsonObject view = at("bufferViews", accessor["bufferView"].toInt());
    static const std::map<QString, int> kComponents = {
        {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}};
    const int components = kComponents.at(accessor["type"].toString());
    const int elementSize = components * static_cast<int>(sizeof(T));
    const int stride = view.contains("byteStride") ? view["byteStride"].toInt() : elementSize;
    const int start = view["byteOffset"].toInt() + accessor["byteOffset"].toInt();
    std::vector<T> values;
    for (int i = 0; i < accessor["count"].toInt(); ++i) {
      for (int c = 0; c < components; ++c) {
        T value;
        std::memcpy(&value, bin.constData() + start + i * stride + c * static_cast<int>(sizeof(T)),
                    sizeof(T));
        values.push_back(value);
      }
    }
    return values;
  }
};

std::uint32_t word(const QByteArray& bytes, int offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.constData() + offset, 4);
  return value;
}

// Checks the GLB container (header, two chunks, lengths, 4-byte padding) and the placement of
// every buffer view and accessor inside the BIN chunk; fills `glb` on success.
void parseGlb(const QByteArray& file, Glb& glb) {
  QVERIFY(file.size() >= 28);
  QCOMPARE(word(file, 0), 0x46546C67u);  // "glTF"
  QCOMPARE(word(file, 4), 2u);
  QCOMPARE(word(file, 8), static_cast<std::uint32_t>(file.size()));
  const std::uint32_t jsonLength = word(file, 12);
  QCOMPARE(word(file, 16), 0x4E4F534Au);  // "JSON"
  QCOMPARE(jsonLength % 4, 0u);
  const int binHeader = 20 + static_cast<int>(jsonLength);
  QVERIFY(file.size() >= binHeader + 8);
  const std::uint32_t binLength = word(file, binHeader);
  QCOMPARE(word(file, binHeader + 4), 0x004E4942u);  // "BIN\0"
  QCOMPARE(binLength % 4, 0u);
  QCOMPARE(static_cast<qsizetype>(binHeader + 8 + binLength), file.size());

  const QByteArray jsonText = file.mid(20, static_cast<qsizetype>(jsonLength));
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(jsonText, &error);
  QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
  glb.json = document.object();
  glb.bin = file.mid(binHeader + 8, static_cast<qsizetype>(binLength));

  QCOMPARE(glb.json["asset"].toObject()["version"].toString(), QString("2.0"));
  const QJsonArray buffers = glb.json["buffers"].toArray();
  QCOMPARE(buffers.size(), 1);
  QVERIFY(!buffers[0].toObject().contains("uri"));  // the GLB-stored buffer
  QVERIFY(buffers[0].toObject()["byteLength"].toInt() <= static_cast<int>(binLength));
  for (const QJsonValue& value : glb.json["bufferViews"].toArray()) {
    const QJsonObject view = value.toObject();
    QCOMPARE(view["byteOffset"].toInt() % 4, 0);
    QVERIFY(view["byteOffset"].toInt() + view["byteLength"].toInt() <=
            buffers[0].toObject()["byteLength"].toInt());
  }
  static const std::map<int, int> kComponentSize = {{5123, 2}, {5125, 4}, {5126, 4}};
  static const std::map<QString, int> kComponents = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}};
  for (const QJsonValue& value : glb.json["accessors"].toArray()) {
    const QJsonObject accessor = value.toObject();
    const QJsonObject view = glb.at("bufferViews", accessor["bufferView"].toInt());
    const int size = kComponentSize.at(accessor["componentType"].toInt());
    const int elementSize = size * kComponents.at(accessor["type"].toString());
    const int stride = view.contains("byteStride") ? view["byteStride"].toInt() : elementSize;
    QCOMPARE(accessor["byteOffset"].toInt() % size, 0);
    QVERIFY(accessor["count"].toInt() >= 1);
    QVERIFY(accessor["byteOffset"].toInt() + stride * (accessor["count"].toInt() - 1) +
                elementSize <=
            view["byteLength"].toInt());
  }
}

// Accessor min/max must be exactly the extremes of the data (the spec requires them on POSITION).
void checkMinMax(const Glb& glb, int index) {
  const QJsonObject accessor = glb.at("accessors", index);
  QVERIFY(accessor.contains("min") && accessor.contains("max"));
  const std::vector<float> values = glb.read<float>(index);
  const int components = static_cast<int>(accessor["min"].toArray().size());
  for (int c = 0; c < components; ++c) {
    float lo = values[static_cast<std::size_t>(c)], hi = lo;
    for (std::size_t i = static_cast<std::size_t>(c); i < values.size();
         i += static_cast<std::size_t>(components)) {
      lo = std::min(lo, values[i]);
      hi = std::max(hi, values[i]);
    }
    QCOMPARE(static_cast<float>(accessor["min"].toArray()[c].toDouble()), lo);
    QCOMPARE(static_cast<float>(accessor["max"].toArray()[c].toDouble()), hi);
  }
}

void compareFloats(const std::vector<float>& actual, const std::vector<float>& expected) {
  QCOMPARE(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    if (std::abs(actual[i] - expected[i]) > 1e-6f * std::max(1.0f, std::abs(expected[i])))
      QFAIL(qPrintable(QString("element %1: %2 != %3").arg(i).arg(actual[i]).arg(expected[i])));
  }
}

// Dense POSITION deltas of `fap`'s exported pose over sub-mesh `s` of `head`.
std::vector<float> expectedDeltas(const HeadMesh& head, const PoseSet& poses, int fap, int s) {
  const HeadSubmesh& sub = head.submeshes[static_cast<std::size_t>(s)];
  std::vector<float> deltas(3 * static_cast<std::size_t>(sub.vertexCount), 0.0f);
  for (const auto& [v, offset] : expectedOffsets(poses, fap)) {
    if (v < sub.firstVertex || v >= sub.firstVertex + sub.vertexCount) continue;
    for (int c = 0; c < 3; ++c)
      deltas[3 * static_cast<std::size_t>(v - sub.firstVertex) + static_cast<std::size_t>(c)] =
          offset[c];
  }
  return deltas;
}

// A head with 70,000 vertices: "small" (0-2) and "late" (69997-69999) have one triangle each,
// "big" (3-69996) a strip over all its vertices. OGRE's shared geometry needs 32-bit indices
// for "late" (global indices), glTF's per-primitive indices only for "big".
HeadMesh largeHead() {
  constexpr int n = 70000;
  HeadMesh head;
  head.positions.resize(3, n);
  for (int v = 0; v < n; ++v)
    head.positions.col(v) = Eigen::Vector3f(static_cast<float>(v % 100),
                                            static_cast<float>(v / 100), static_cast<float>(v % 7));
  head.normals = Eigen::Matrix3Xf::Zero(3, n);
  head.normals.row(2).setOnes();
  HeadSubmesh small{"small", -1, 0, 3, {{0, 1, 2}}};
  HeadSubmesh big{"big", -1, 3, n - 6, {}};
  for (int v = 3; v + 2 < n - 3; ++v) big.triangles.emplace_back(v, v + 1, v + 2);
  HeadSubmesh late{"late", -1, n - 3, 3, {{n - 3, n - 2, n - 1}}};
  head.submeshes = {small, big, late};
  return head;
}

}  // namespace

class RigExportTest : public QObject {
  Q_OBJECT

 private slots:
  void poseNames();
  void meshRoundTrip();
  void exportInsideRunningOgre();
  void glbRoundTrip();
  void indexWidths();
  void glbNormalsAreUnit();
  void zeroPoses();
  void missingFolderThrowsAndWritesNothing();
  void missingTextureThrowsAndWritesNothing();
  void badRigThrowsAndWritesNothing();
  void texturesAlreadyInPlaceAndNameClashes();
};

void RigExportTest::poseNames() {
  QCOMPARE(exporters::exportedPoseName(3), std::string("fap03_open_jaw"));
  QCOMPARE(exporters::exportedPoseName(31), std::string("fap31_raise_l_i_eyebrow"));
  QCOMPARE(exporters::exportedPoseName(68), "fap68_" + std::string(fapInfo(68).name));
}

void RigExportTest::meshRoundTrip() {
  QTemporaryDir source, target;
  const QString texture = source.filePath("skin.png");
  writeTexture(texture);
  const HeadMesh head = syntheticHead(str(texture));
  const PoseSet poses = syntheticPoses();
  exporters::exportOgreMesh(head, poses, str(target.filePath("head.mesh")));

  // Exactly the three files, no temporaries; the texture is a byte-for-byte copy.
  QCOMPARE(entries(target.path()), QStringList({"head.material", "head.mesh", "skin.png"}));
  QCOMPARE(readAll(target.filePath("skin.png")), readAll(texture));

  exporters::HeadlessOgre ogre;
  {
    const Ogre::MeshPtr mesh = loadMesh(target.path(), "head.mesh");
    QVERIFY(mesh);
    const Ogre::VertexData& shared = *mesh->sharedVertexData;
    QCOMPARE(shared.vertexCount, std::size_t{19});
    QCOMPARE(readElement(shared, Ogre::VES_POSITION, 3), columns(head.positions, 0, 19));
    QCOMPARE(readElement(shared, Ogre::VES_NORMAL, 3), columns(head.normals, 0, 19));
    QCOMPARE(readElement(shared, Ogre::VES_TEXTURE_COORDINATES, 2), columns(head.uvs, 0, 19));
    // Positions alone in their buffer: software pose blending rewrites only that one.
    const auto* position = shared.vertexDeclaration->findElementBySemantic(Ogre::VES_POSITION);
    QCOMPARE(shared.vertexBufferBinding->getBuffer(position->getSource())->getVertexSize(),
             std::size_t{12});

    QCOMPARE(mesh->getNumSubMeshes(), std::size_t{3});
    const char* materialNames[] = {"head/skin", "head/lashes", "head/clear"};
    for (unsigned short i = 0; i < 3; ++i) {
      const Ogre::SubMesh* sub = mesh->getSubMesh(i);
      QVERIFY(sub->useSharedVertices);
      QCOMPARE(sub->getMaterialName(), std::string(materialNames[i]));
      QCOMPARE(readIndices(*sub->indexData), flatten(head.submeshes[i].triangles));
      QCOMPARE(sub->indexData->indexBuffer->getType(), Ogre::HardwareIndexBuffer::IT_16BIT);
      QCOMPARE(mesh->_getSubMeshIndex(head.submeshes[i].name), i);
    }

    const Ogre::PoseList& loaded = mesh->getPoseList();
    QCOMPARE(loaded.size(), kExportedFaps.size());
    for (std::size_t p = 0; p < loaded.size(); ++p) {
      QCOMPARE(QString::fromStdString(loaded[p]->getName()), kExportedNames[static_cast<int>(p)]);
      QCOMPARE(loaded[p]->getTarget(), static_cast<unsigned short>(0));  // shared geometry
      const std::map<int, Eigen::Vector3f> expected = expectedOffsets(poses, kExportedFaps[p]);
      const Ogre::Pose::VertexOffsetMap& offsets = loaded[p]->getVertexOffsets();
      QCOMPARE(offsets.size(), expected.size());
      for (const auto& [v, offset] : expected) {
        QVERIFY(offsets.count(static_cast<std::size_t>(v)));
        const Ogre::Vector3& o = offsets.at(static_cast<std::size_t>(v));
        QCOMPARE(Eigen::Vector3f(o.x, o.y, o.z), offset);
      }
    }
    // Vertex 1 is listed twice in open_jaw: the exported offset is the sum.
    QCOMPARE(loaded[0]->getVertexOffsets().at(1).y, (-2e-4f + -1e-4f) * 1024.0f);

    QVERIFY(mesh->hasAnimation("fap"));
    Ogre::Animation* animation = mesh->getAnimation("fap");
    QCOMPARE(animation->getLength(), 0.0f);
    QVERIFY(animation->hasVertexTrack(0));
    Ogre::VertexAnimationTrack* track = animation->getVertexTrack(0);
    QCOMPARE(track->getAnimationType(), Ogre::VAT_POSE);
    QCOMPARE(track->getNumKeyFrames(), static_cast<unsigned short>(1));
    const auto& references = track->getVertexPoseKeyFrame(0)->getPoseReferences();
    QCOMPARE(references.size(), kExportedFaps.size());
    for (std::size_t i = 0; i < references.size(); ++i) {
      QCOMPARE(references[i].poseIndex, static_cast<unsigned short>(i));
      QCOMPARE(references[i].influence, 0.0f);
    }

    // Bounds hold the neutral head, open_jaw at its largest slider value, and the left
    // eye turned so its cornea points along +x.
    const Ogre::AxisAlignedBox& bounds = mesh->getBounds();
    auto contains = [&](const Eigen::Vector3f& p) {
      return bounds.contains(Ogre::Vector3(p.x(), p.y(), p.z()));
    };
    for (int v = 0; v < 19; ++v) QVERIFY(contains(head.positions.col(v)));
    const float jawMax = static_cast<float>(fapInfo(kOpenJaw).sliderMax);
    for (const auto& [v, offset] : expectedOffsets(poses, kOpenJaw))
      QVERIFY(contains(head.positions.col(v) + offset * (jawMax / 1024.0f)));
    const float eyeRadius = (head.positions.col(16) - poses.eyeLeft.centre).norm();
    QVERIFY(contains(poses.eyeLeft.centre + Eigen::Vector3f(eyeRadius, 0, 0)));
    QVERIFY(mesh->getBoundingSphereRadius() >= bounds.getMaximum().length());

    // The material script parsed, with what each material asks for.
    auto& materials = Ogre::MaterialManager::getSingleton();
    const Ogre::MaterialPtr skin = materials.getByName("head/skin", kGroup);
    QVERIFY(skin);
    const Ogre::Pass* skinPass = skin->getTechnique(0)->getPass(0);
    QCOMPARE(skinPass->getDiffuse(), Ogre::ColourValue(0.9f, 0.8f, 0.7f, 1.0f));
    QCOMPARE(skinPass->getSpecular(), Ogre::ColourValue(0.2f, 0.2f, 0.25f, 1.0f));
    QCOMPARE(skinPass->getShininess(), 20.0f);
    QVERIFY(skinPass->getDepthWriteEnabled());
    QCOMPARE(skinPass->getNumTextureUnitStates(), static_cast<unsigned short>(1));
    QCOMPARE(skinPass->getTextureUnitState(0)->getTextureName(), std::string("skin.png"));

    const Ogre::MaterialPtr lashes = materials.getByName("head/lashes", kGroup);
    QVERIFY(lashes);
    const Ogre::Pass* lashPass = lashes->getTechnique(0)->getPass(0);
    QCOMPARE(lashPass->getSourceBlendFactor(), Ogre::SBF_SOURCE_ALPHA);
    QCOMPARE(lashPass->getDestBlendFactor(), Ogre::SBF_ONE_MINUS_SOURCE_ALPHA);
    QVERIFY(!lashPass->getDepthWriteEnabled());

    const Ogre::MaterialPtr clear = materials.getByName("head/clear", kGroup);
    QVERIFY(clear);
    const Ogre::Pass* corneaPass = clear->getTechnique(0)->getPass(0);
    QCOMPARE(corneaPass->getSourceBlendFactor(), Ogre::SBF_ONE);  // additive
    QCOMPARE(corneaPass->getDestBlendFactor(), Ogre::SBF_ONE);
    QVERIFY(!corneaPass->getDepthWriteEnabled());
    QVERIFY(corneaPass->getSpecular().r >= 0.9f);
    QVERIFY(corneaPass->getShininess() >= 96.0f);
    QCOMPARE(corneaPass->getDiffuse(), Ogre::ColourValue(0, 0, 0, 1));
  }
}

void RigExportTest::exportInsideRunningOgre() {
  QTemporaryDir target;
  const HeadMesh head = syntheticHead("");
  exporters::HeadlessOgre ogre;
  QVERIFY(ogre.ownsRoot());
  // The application already has a material of that name: the export must neither replace
  // nor remove it, and must leave no meshes of its own behind.
  auto& materials = Ogre::MaterialManager::getSingleton();
  const Ogre::MaterialPtr existing = materials.create("head/skin", Ogre::RGN_DEFAULT);
  existing->createTechnique()->createPass()->setDiffuse(Ogre::ColourValue(0.1f, 0.2f, 0.3f));
  auto& meshes = Ogre::MeshManager::getSingleton();
  const std::size_t meshesBefore = resourceCount(meshes);
  const std::size_t materialsBefore = resourceCount(materials);
  {
    exporters::HeadlessOgre nested;
    QVERIFY(!nested.ownsRoot());
  }
  exporters::exportOgreMesh(head, syntheticPoses(), str(target.filePath("head.mesh")));
  QCOMPARE(resourceCount(meshes), meshesBefore);
  QCOMPARE(resourceCount(materials), materialsBefore);
  QCOMPARE(materials.getByName("head/skin")->getTechnique(0)->getPass(0)->getDiffuse(),
           Ogre::ColourValue(0.1f, 0.2f, 0.3f));
  {
    // Loaded into the application material's group: a .mesh looks its materials up there.
    Ogre::ResourceGroupManager::getSingleton().addResourceLocation(str(target.path()), "FileSystem",
                                                                   Ogre::RGN_DEFAULT);
    const Ogre::MeshPtr mesh = meshes.load("head.mesh", Ogre::RGN_DEFAULT);
    QCOMPARE(mesh->getPoseList().size(), kExportedFaps.size());
    QCOMPARE(mesh->getNumSubMeshes(), std::size_t{3});
    QCOMPARE(mesh->getSubMesh(0)->getMaterialName(), std::string("head/skin"));
  }
}

void RigExportTest::glbRoundTrip() {
  QTemporaryDir source, target;
  const QString texture = source.filePath("skin.png");
  writeTexture(texture);
  const HeadMesh head = syntheticHead(str(texture));
  const PoseSet poses = syntheticPoses();
  const QString path = target.filePath("head.glb");
  exporters::exportGlb(head, poses, str(path));
  QCOMPARE(entries(target.path()), QStringList({"head.glb"}));

  Glb glb;
  parseGlb(readAll(path), glb);
  if (QTest::currentTestFailed()) return;

  const QJsonArray meshes = glb.json["meshes"].toArray();
  QCOMPARE(meshes.size(), 1);
  const QJsonObject mesh = meshes[0].toObject();
  QJsonArray names;
  for (const QString& name : kExportedNames) names.append(name);
  QCOMPARE(mesh["extras"].toObject()["targetNames"].toArray(), names);
  QCOMPARE(mesh["weights"].toArray(), QJsonArray({0, 0, 0}));
  const QJsonArray primitives = mesh["primitives"].toArray();
  QCOMPARE(primitives.size(), 3);
  for (int s = 0; s < 3; ++s) {
    const HeadSubmesh& sub = head.submeshes[static_cast<std::size_t>(s)];
    const QJsonObject primitive = primitives[s].toObject();
    const QJsonObject attributes = primitive["attributes"].toObject();
    QCOMPARE(primitive["material"].toInt(), sub.material);
    QCOMPARE(primitive["mode"].toInt(), 4);
    checkMinMax(glb, attributes["POSITION"].toInt());
    QCOMPARE(glb.read<float>(attributes["POSITION"].toInt()),
             columns(head.positions, sub.firstVertex, sub.vertexCount));
    compareFloats(glb.read<float>(attributes["NORMAL"].toInt()),
                  columns(head.normals, sub.firstVertex, sub.vertexCount));
    // Not flipped: HeadMesh uvs already have glTF's upper-left origin.
    QCOMPARE(glb.read<float>(attributes["TEXCOORD_0"].toInt()),
             columns(head.uvs, sub.firstVertex, sub.vertexCount));
    QCOMPARE(glb.at("accessors", primitive["indices"].toInt())["componentType"].toInt(), 5123);
    QCOMPARE(glb.read<std::uint16_t>(primitive["indices"].toInt()).size(),
             sub.triangles.size() * 3);
    std::vector<std::uint32_t> indices;
    for (std::uint16_t i : glb.read<std::uint16_t>(primitive["indices"].toInt()))
      indices.push_back(i);
    QCOMPARE(indices, flatten(sub.triangles, sub.firstVertex));
    // Every primitive has every target; zeros where the pose does not reach.
    const QJsonArray targets = primitive["targets"].toArray();
    QCOMPARE(targets.size(), 3);
    for (int t = 0; t < 3; ++t) {
      const int accessor = targets[t].toObject()["POSITION"].toInt();
      checkMinMax(glb, accessor);
      compareFloats(glb.read<float>(accessor),
                    expectedDeltas(head, poses, kExportedFaps[static_cast<std::size_t>(t)], s));
    }
  }

  // Materials: colour, texture embedded as PNG (same pixels), blending where it matters.
  const QJsonObject skin = glb.at("materials", 0);
  QCOMPARE(skin["name"].toString(), QString("skin"));
  const QJsonObject pbr = skin["pbrMetallicRoughness"].toObject();
  QCOMPARE(static_cast<float>(pbr["baseColorFactor"].toArray()[0].toDouble()), 0.9f);
  QCOMPARE(pbr["metallicFactor"].toDouble(), 0.0);
  QVERIFY(!skin.contains("alphaMode"));
  const QJsonObject image = glb.at(
      "images",
      glb.at("textures", pbr["baseColorTexture"].toObject()["index"].toInt())["source"].toInt());
  QCOMPARE(image["mimeType"].toString(), QString("image/png"));
  const QJsonObject imageView = glb.at("bufferViews", image["bufferView"].toInt());
  const QImage embedded = QImage::fromData(
      glb.bin.mid(imageView["byteOffset"].toInt(), imageView["byteLength"].toInt()), "PNG");
  QCOMPARE(embedded.convertToFormat(QImage::Format_RGBA8888),
           QImage(texture).convertToFormat(QImage::Format_RGBA8888));
  QCOMPARE(glb.at("materials", 1)["alphaMode"].toString(), QString("BLEND"));
  const QJsonObject cornea = glb.at("materials", 2);
  QCOMPARE(cornea["alphaMode"].toString(), QString("BLEND"));
  QVERIFY(cornea["pbrMetallicRoughness"].toObject()["roughnessFactor"].toDouble() <= 0.05 + 1e-9);

  // assimp reads it as three meshes with three morph targets each.
  std::unique_ptr<const aiScene, decltype(&aiReleaseImport)> scene(
      aiImportFile(path.toUtf8().constData(), 0), &aiReleaseImport);
  QVERIFY2(scene, aiGetErrorString());
  QCOMPARE(scene->mNumMeshes, 3u);
  for (unsigned s = 0; s < 3; ++s) {
    const aiMesh* m = scene->mMeshes[s];
    const HeadSubmesh& sub = head.submeshes[s];
    QCOMPARE(m->mNumVertices, static_cast<unsigned>(sub.vertexCount));
    QCOMPARE(m->mNumFaces, static_cast<unsigned>(sub.triangles.size()));
    for (unsigned v = 0; v < m->mNumVertices; ++v) {
      const Eigen::Vector3f p = head.positions.col(sub.firstVertex + static_cast<int>(v));
      QCOMPARE(Eigen::Vector3f(m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z), p);
      // assimp's origin is the lower left corner: it flips glTF's v on import.
      QCOMPARE(m->mTextureCoords[0][v].y,
               1.0f - head.uvs(1, sub.firstVertex + static_cast<int>(v)));
    }
    QCOMPARE(m->mNumAnimMeshes, 3u);
    for (unsigned t = 0; t < 3; ++t) {
      const aiAnimMesh* target = m->mAnimMeshes[t];
      // assimp 5.2 names targets from mesh.extras.targetNames.
      QCOMPARE(QString(target->mName.C_Str()), kExportedNames[static_cast<int>(t)]);
      QCOMPARE(target->mNumVertices, m->mNumVertices);
      // assimp stores the morphed positions (base + delta).
      std::vector<float> deltas;
      for (unsigned v = 0; v < target->mNumVertices; ++v) {
        const aiVector3D d = target->mVertices[v] - m->mVertices[v];
        deltas.insert(deltas.end(), {d.x, d.y, d.z});
      }
      compareFloats(deltas, expectedDeltas(head, poses, kExportedFaps[t], static_cast<int>(s)));
    }
  }
}

void RigExportTest::indexWidths() {
  QTemporaryDir target;
  const HeadMesh head = largeHead();
  exporters::exportOgreMesh(head, PoseSet{}, str(target.filePath("large.mesh")));
  exporters::exportGlb(head, PoseSet{}, str(target.filePath("large.glb")));
  {
    exporters::HeadlessOgre ogre;
    // Sub-meshes without material name BaseWhite, which an OGRE with a render system always
    // defines; this headless one does not, so the test provides it.
    Ogre::ResourceGroupManager::getSingleton().createResourceGroup(kGroup);
    Ogre::MaterialManager::getSingleton().create("BaseWhite", kGroup);
    const Ogre::MeshPtr mesh = loadMesh(target.path(), "large.mesh");
    QCOMPARE(mesh->sharedVertexData->vertexCount, std::size_t{70000});
    const Ogre::HardwareIndexBuffer::IndexType expected[] = {Ogre::HardwareIndexBuffer::IT_16BIT,
                                                             Ogre::HardwareIndexBuffer::IT_32BIT,
                                                             Ogre::HardwareIndexBuffer::IT_32BIT};
    for (unsigned short s = 0; s < 3; ++s) {
      QCOMPARE(mesh->getSubMesh(s)->indexData->indexBuffer->getType(), expected[s]);
      QCOMPARE(readIndices(*mesh->getSubMesh(s)->indexData), flatten(head.submeshes[s].triangles));
      QCOMPARE(mesh->getSubMesh(s)->getMaterialName(), std::string("BaseWhite"));
    }
  }
  Glb glb;
  parseGlb(readAll(target.filePath("large.glb")), glb);
  if (QTest::currentTestFailed()) return;
  const QJsonArray primitives = glb.json["meshes"].toArray()[0].toObject()["primitives"].toArray();
  const int expectedType[] = {5123, 5125, 5123};
  for (int s = 0; s < 3; ++s) {
    const HeadSubmesh& sub = head.submeshes[static_cast<std::size_t>(s)];
    const int indices = primitives[s].toObject()["indices"].toInt();
    QCOMPARE(glb.at("accessors", indices)["componentType"].toInt(), expectedType[s]);
    std::vector<std::uint32_t> actual;
    if (expectedType[s] == 5125) {
      actual = glb.read<std::uint32_t>(indices);
    } else {
      for (std::uint16_t i : glb.read<std::uint16_t>(indices)) actual.push_back(i);
    }
    QCOMPARE(actual, flatten(sub.triangles, sub.firstVertex));
    QVERIFY(!primitives[s].toObject().contains("material"));
  }
}

void RigExportTest::glbNormalsAreUnit() {
  QTemporaryDir target;
  HeadMesh head = syntheticHead("");
  head.normals.col(0) *= 3.0f;    // glTF rejects non-unit normals...
  head.normals.col(1).setZero();  // ...and a degenerate one has no direction at all
  const Eigen::Vector3f expected0 = head.normals.col(0).normalized();
  exporters::exportGlb(head, syntheticPoses(), str(target.filePath("head.glb")));
  Glb glb;
  parseGlb(readAll(target.filePath("head.glb")), glb);
  if (QTest::currentTestFailed()) return;
  const QJsonObject attributes = glb.json["meshes"]
                                     .toArray()[0]
                                     .toObject()["primitives"]
                                     .toArray()[0]
                                     .toObject()["attributes"]
                                     .toObject();
  const std::vector<float> normals = glb.read<float>(attributes["NORMAL"].toInt());
  compareFloats({normals[0], normals[1], normals[2]},
                {expected0.x(), expected0.y(), expected0.z()});
  compareFloats({normals[3], normals[4], normals[5]}, {0.0f, 0.0f, 1.0f});
  for (std::size_t v = 0; v < normals.size() / 3; ++v)
    QVERIFY(
        std::abs(Eigen::Vector3f(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]).norm() -
                 1.0f) < 1e-6f);
}

void RigExportTest::zeroPoses() {
  QTemporaryDir target;
  const HeadMesh head = syntheticHead("");
  exporters::exportOgreMesh(head, PoseSet{}, str(target.filePath("still.mesh")));
  exporters::exportGlb(head, PoseSet{}, str(target.filePath("still.glb")));
  QCOMPARE(entries(target.path()), QStringList({"still.glb", "still.material", "still.mesh"}));
  {
    exporters::HeadlessOgre ogre;
    const Ogre::MeshPtr mesh = loadMesh(target.path(), "still.mesh");
    QCOMPARE(mesh->getPoseList().size(), std::size_t{0});
    QVERIFY(mesh->hasAnimation("fap"));
    QCOMPARE(mesh->getAnimation("fap")
                 ->getVertexTrack(0)
                 ->getVertexPoseKeyFrame(0)
                 ->getPoseReferences()
                 .size(),
             std::size_t{0});
    QCOMPARE(mesh->getNumSubMeshes(), std::size_t{3});
    QCOMPARE(mesh->getSubMesh(0)->getMaterialName(), std::string("still/skin"));
  }
  Glb glb;
  parseGlb(readAll(target.filePath("still.glb")), glb);
  if (QTest::currentTestFailed()) return;
  const QJsonObject mesh = glb.json["meshes"].toArray()[0].toObject();
  QVERIFY(!mesh.contains("weights"));
  QVERIFY(!mesh.contains("extras"));
  for (const QJsonValue& primitive : mesh["primitives"].toArray())
    QVERIFY(!primitive.toObject().contains("targets"));
  QVERIFY(!glb.json.contains("images"));  // the head has no texture
  std::unique_ptr<const aiScene, decltype(&aiReleaseImport)> scene(
      aiImportFile(str(target.filePath("still.glb")).c_str(), 0), &aiReleaseImport);
  QVERIFY2(scene, aiGetErrorString());
  QCOMPARE(scene->mNumMeshes, 3u);
  QCOMPARE(scene->mMeshes[0]->mNumAnimMeshes, 0u);
}

void RigExportTest::missingFolderThrowsAndWritesNothing() {
  QTemporaryDir source, target;
  const QString texture = source.filePath("skin.png");
  writeTexture(texture);
  const HeadMesh head = syntheticHead(str(texture));
  const QString meshPath = target.filePath("missing/head.mesh");
  const QString glbPath = target.filePath("missing/head.glb");
  const QString meshError =
      fileErrorOf([&] { exporters::exportOgreMesh(head, syntheticPoses(), str(meshPath)); });
  QVERIFY2(meshError.contains(meshPath), qPrintable(meshError));
  const QString glbError =
      fileErrorOf([&] { exporters::exportGlb(head, syntheticPoses(), str(glbPath)); });
  QVERIFY2(glbError.contains(glbPath), qPrintable(glbError));
  QCOMPARE(entries(target.path()), QStringList());
  QCOMPARE(entries(source.path()), QStringList({"skin.png"}));
}

void RigExportTest::missingTextureThrowsAndWritesNothing() {
  QTemporaryDir source, target;
  const QString texture = source.filePath("absent.png");
  const HeadMesh head = syntheticHead(str(texture));
  const QString meshError = fileErrorOf([&] {
    exporters::exportOgreMesh(head, syntheticPoses(), str(target.filePath("head.mesh")));
  });
  QVERIFY2(meshError.contains(texture) && meshError.contains("texture"), qPrintable(meshError));
  const QString glbError = fileErrorOf(
      [&] { exporters::exportGlb(head, syntheticPoses(), str(target.filePath("head.glb"))); });
  QVERIFY2(glbError.contains(texture), qPrintable(glbError));
  QCOMPARE(entries(target.path()), QStringList());
}

void RigExportTest::badRigThrowsAndWritesNothing() {
  QTemporaryDir target;
  const HeadMesh head = syntheticHead("");
  const QString meshPath = target.filePath("head.mesh");
  const QString glbPath = target.filePath("head.glb");
  auto expectRejected = [&](const PoseSet& poses, const QString& reason) {
    const QString meshError =
        fileErrorOf([&] { exporters::exportOgreMesh(head, poses, str(meshPath)); });
    QVERIFY2(meshError.startsWith(meshPath) && meshError.contains(reason), qPrintable(meshError));
    const QString glbError = fileErrorOf([&] { exporters::exportGlb(head, poses, str(glbPath)); });
    QVERIFY2(glbError.startsWith(glbPath) && glbError.contains(reason), qPrintable(glbError));
  };

  PoseSet outOfRange = syntheticPoses();
  outOfRange.poses[channelIndex(kOpenJaw)].vertices[2] = 19;
  expectRejected(outOfRange, "moves vertex 19, but the head has 19 vertices");

  PoseSet rotation = syntheticPoses();
  rotation.poses[channelIndex(48)] = rotation.poses[channelIndex(kOpenJaw)];
  expectRejected(rotation, "FAP 48 (head_pitch)");

  PoseSet otherHead = syntheticPoses();
  otherHead.vertexCount = 20;
  expectRejected(otherHead, "baked for 20 vertices");

  PoseSet ragged = syntheticPoses();
  ragged.poses[channelIndex(kRaiseLeftInnerBrow)].offsets.resize(3, 1);
  expectRejected(ragged, "1 offsets for 2 vertices");

  HeadMesh broken = head;
  broken.submeshes[1].triangles.emplace_back(12, 13, 3);  // vertex 3 belongs to the skin
  const QString error =
      fileErrorOf([&] { exporters::exportGlb(broken, syntheticPoses(), str(glbPath)); });
  QVERIFY2(error.contains("sub-mesh 'eyelashes' has a triangle outside its vertices 12..15"),
           qPrintable(error));

  QCOMPARE(entries(target.path()), QStringList());
}

void RigExportTest::texturesAlreadyInPlaceAndNameClashes() {
  QTemporaryDir a, b;
  writeTexture(a.filePath("skin.png"));
  QImage other(2, 2, QImage::Format_RGBA8888);
  other.fill(Qt::green);
  QVERIFY(other.save(b.filePath("skin.png")));
  HeadMesh head = syntheticHead(str(a.filePath("skin.png")));
  head.materials[1].diffuseTexture = str(b.filePath("skin.png"));  // another file, same name
  head.materials[2].diffuseTexture = str(a.filePath("skin.png"));  // the cornea ignores its texture

  // Exported into the folder that already holds a/skin.png: that file is used in place.
  const QByteArray before = readAll(a.filePath("skin.png"));
  exporters::exportOgreMesh(head, syntheticPoses(), str(a.filePath("head.mesh")));
  QCOMPARE(entries(a.path()),
           QStringList({"head.material", "head.mesh", "skin.png", "skin_2.png"}));
  QCOMPARE(readAll(a.filePath("skin.png")), before);
  QCOMPARE(readAll(a.filePath("skin_2.png")), readAll(b.filePath("skin.png")));
  const QByteArray script = readAll(a.filePath("head.material"));
  QVERIFY(script.contains("texture \"skin.png\""));
  QVERIFY(script.contains("texture \"skin_2.png\""));
  QCOMPARE(script.count("texture_unit"), 2);
}

QTEST_GUILESS_MAIN(RigExportTest)
#include "RigExportTest.moc"
