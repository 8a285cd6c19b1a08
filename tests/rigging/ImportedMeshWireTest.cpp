// The importer process's answer (ImportedMeshWire.h): a head goes through writer and reader
// unchanged, a refusal keeps its words, and every malformed answer is refused with a FileError
// naming the file, before anything it announces is allocated: every truncation of a real
// answer, a wrong magic, version or kind, a size that disagrees with the bytes, counts far over
// their bounds in a few bytes, parts outside the vertices, triangle corners outside their part,
// unknown materials, non-finite positions, bytes after the end.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/rigging/ImportedMeshWire.h>

#include <QtTest>

#include <cstring>
#include <limits>

using namespace lacrima;
namespace wire = lacrima::rigging::wire;

namespace {

const std::string kFile = "head.ply";

// Two parts, one textured material, uvs: every field of the format.
HeadMesh sampleHead() {
  HeadMesh head;
  head.positions.resize(3, 7);
  head.positions << 0, 1, 1, 0, 0.5f, 2, 3,  //
      0, 0, 1, 1, 0.5f, 0, 0,                //
      0, 0, 0, 0, 1, 0, 1;
  head.uvs.resize(2, 7);
  for (int v = 0; v < 7; ++v) head.uvs.col(v) << 0.1f * v, 1.0f - 0.1f * v;
  HeadMaterial skin;
  skin.name = "skin";
  skin.diffuseTexture = "/tmp/skin.png";
  skin.diffuse << 0.9f, 0.7f, 0.6f, 1.0f;
  skin.specular << 0.2f, 0.2f, 0.2f;
  skin.shininess = 30.0f;
  HeadMaterial lash;
  lash.name = "lash";
  lash.transparent = true;
  head.materials = {skin, lash};
  HeadSubmesh face{"face", 0, 0, 5, {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}};
  HeadSubmesh eye{"eye_l", -1, 5, 2, {{5, 6, 5}}};
  head.submeshes = {face, eye};
  head.computeNormals();
  return head;
}

template <class T>
void poke(std::string& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

// The offset of the first part's name in sampleHead()'s answer.
std::size_t firstPartOffset(const HeadMesh& head) {
  std::size_t at = wire::kHeaderBytes + 16 + 7 * 8 * sizeof(float);
  for (const HeadMaterial& m : head.materials)
    at += 8 + m.name.size() + m.diffuseTexture.size() + 8 * sizeof(float) + 4;
  return at;
}

// The reader's refusal of `bytes`, or "" when it accepted them.
std::string refusalOf(std::string_view bytes) {
  try {
    (void)wire::readImportAnswer(bytes, kFile);
  } catch (const FileError& e) {
    return e.what();
  }
  return {};
}

// A header for `kind` announcing `payload` bytes, then `payload` itself.
std::string answerWith(std::uint32_t kind, const std::string& payload) {
  std::string bytes(wire::kMagic, sizeof wire::kMagic);
  bytes.resize(wire::kHeaderBytes);
  poke(bytes, 8, wire::kVersion);
  poke(bytes, 12, kind);
  poke(bytes, 16, static_cast<std::uint64_t>(payload.size()));
  return bytes + payload;
}

}  // namespace

class ImportedMeshWireTest : public QObject {
  Q_OBJECT

 private slots:
  void aHeadComesBackUnchanged() {
    const HeadMesh head = sampleHead();
    const auto answer = wire::readImportAnswer(wire::writeImportedMesh(head), kFile);
    const HeadMesh* back = std::get_if<HeadMesh>(&answer);
    QVERIFY(back);
    QCOMPARE(back->positions, head.positions);
    QCOMPARE(back->normals, head.normals);
    QCOMPARE(back->uvs, head.uvs);
    QCOMPARE(back->materials.size(), head.materials.size());
    for (std::size_t i = 0; i < head.materials.size(); ++i) {
      const HeadMaterial &a = back->materials[i], &b = head.materials[i];
      QCOMPARE(a.name, b.name);
      QCOMPARE(a.diffuseTexture, b.diffuseTexture);
      QCOMPARE(a.diffuse, b.diffuse);
      QCOMPARE(a.specular, b.specular);
      QCOMPARE(a.shininess, b.shininess);
      QCOMPARE(a.transparent, b.transparent);
    }
    QCOMPARE(back->submeshes.size(), head.submeshes.size());
    for (std::size_t i = 0; i < head.submeshes.size(); ++i) {
      const HeadSubmesh &a = back->submeshes[i], &b = head.submeshes[i];
      QCOMPARE(a.name, b.name);
      QCOMPARE(a.material, b.material);
      QCOMPARE(a.firstVertex, b.firstVertex);
      QCOMPARE(a.vertexCount, b.vertexCount);
      QVERIFY(a.triangles == b.triangles);
    }
  }

  void aHeadWithoutUvsHasNone() {
    HeadMesh head = sampleHead();
    head.uvs.resize(2, 0);
    const auto answer = wire::readImportAnswer(wire::writeImportedMesh(head), kFile);
    QCOMPARE(std::get<HeadMesh>(answer).uvs.cols(), Eigen::Index{0});
  }

  void aRefusalKeepsItsWords() {
    const std::string message = "no faces in it (3 vertices and no face); expected a mesh";
    const auto answer = wire::readImportAnswer(wire::writeImportRefusal(message), kFile);
    QCOMPARE(std::get<wire::Refusal>(answer).message, message);
    // A message beyond the bound is cut where a character begins.
    const std::string longer = std::string(wire::kMaxMessageBytes - 1, 'a') + "\xc3\xa9tude";
    const auto cut = wire::readImportAnswer(wire::writeImportRefusal(longer), kFile);
    QCOMPARE(std::get<wire::Refusal>(cut).message, std::string(wire::kMaxMessageBytes - 1, 'a'));
  }

  void everyTruncationIsRefused() {
    const std::string bytes = wire::writeImportedMesh(sampleHead());
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      const std::string why = refusalOf(std::string_view(bytes).substr(0, n));
      QVERIFY2(why.starts_with(kFile + ": the importer's answer is malformed"),
               qPrintable(QString("%1 bytes: '%2'").arg(n).arg(QString::fromStdString(why))));
    }
  }

  void aWrongHeaderIsRefused() {
    std::string bytes = wire::writeImportedMesh(sampleHead());
    std::string magic = bytes;
    magic[0] = 'X';
    QVERIFY(refusalOf(magic).find("magic") != std::string::npos);
    std::string version = bytes;
    poke(version, 8, std::uint32_t{2});
    QVERIFY(refusalOf(version).find("version 2, expected 1") != std::string::npos);
    std::string kind = bytes;
    poke(kind, 12, std::uint32_t{7});
    QVERIFY(refusalOf(kind).find("kind 7") != std::string::npos);
    std::string size = bytes;
    poke(size, 16, std::uint64_t{1} << 40);
    QVERIFY(refusalOf(size).find("announces") != std::string::npos);
    QVERIFY(refusalOf(bytes + "x").find("announces") != std::string::npos);
  }

  // Counts far beyond the bytes that came, or beyond the bounds, are refused before anything
  // is allocated for them (the sanitizer build would report an allocation of gigabytes).
  void countsAreBoundedBeforeAllocation() {
    const auto header = [](std::uint32_t vertices, std::uint32_t uvs, std::uint32_t materials,
                           std::uint32_t parts) {
      std::string payload(16, '\0');
      poke(payload, 0, vertices);
      poke(payload, 4, uvs);
      poke(payload, 8, materials);
      poke(payload, 12, parts);
      return answerWith(1, payload);
    };
    QVERIFY(refusalOf(header(wire::kMaxVertices + 1, 0, 0, 0)).find("more than") !=
            std::string::npos);
    QVERIFY(refusalOf(header(wire::kMaxVertices, 1, 0, 0)).find("vertex arrays") !=
            std::string::npos);
    QVERIFY(refusalOf(header(0, 2, 0, 0)).find("expected 0 or 1") != std::string::npos);
    QVERIFY(refusalOf(header(0, 0, wire::kMaxMaterials, 0)).find("materials and parts") !=
            std::string::npos);
    QVERIFY(
        refusalOf(header(0, 0, 0, std::numeric_limits<std::uint32_t>::max())).find("more than") !=
        std::string::npos);
    // A string announcing 4 GiB.
    std::string refusal(4, '\xff');
    QVERIFY(refusalOf(answerWith(2, refusal)).find("more than") != std::string::npos);
    // A part announcing the most triangles there may be, in a few bytes.
    const HeadMesh head = sampleHead();
    std::string bytes = wire::writeImportedMesh(head);
    const std::size_t part = firstPartOffset(head);
    poke(bytes, part + 4 + 4 + 4 + 4 + 4, wire::kMaxTriangles);
    QVERIFY(refusalOf(bytes).find("a part's triangles needs") != std::string::npos);
  }

  void indicesAreChecked() {
    const HeadMesh head = sampleHead();
    const std::string good = wire::writeImportedMesh(head);
    const std::size_t part = firstPartOffset(head) + 4 + 4;  // after "face"'s name
    std::string material = good;
    poke(material, part, std::int32_t{2});
    QVERIFY(refusalOf(material).find("names material 2 of 2") != std::string::npos);
    std::string below = good;
    poke(below, part, std::int32_t{-2});
    QVERIFY(refusalOf(below).find("names material -2") != std::string::npos);
    std::string range = good;
    poke(range, part + 8, std::uint32_t{8});  // 5 vertices from 0 -> 8
    QVERIFY(refusalOf(range).find("has vertices 0 to 8 of 7") != std::string::npos);
    std::string wrapping = good;
    poke(wrapping, part + 4, std::uint32_t{0xffffffff});
    QVERIFY(refusalOf(wrapping).find("has vertices") != std::string::npos);
    std::string corner = good;
    poke(corner, part + 16, std::uint32_t{5});  // the first triangle's first corner: eye_l's
    QVERIFY(refusalOf(corner).find("uses vertex 5, outside the part's vertices 0 to 5") !=
            std::string::npos);
    QVERIFY(refusalOf(good + "junk").find("announces") != std::string::npos);
  }

  void nonFiniteNumbersAreRefused() {
    HeadMesh head = sampleHead();
    std::string bytes = wire::writeImportedMesh(head);
    poke(bytes, wire::kHeaderBytes + 16 + 4 * sizeof(float),
         std::numeric_limits<float>::quiet_NaN());  // vertex 2's y
    QVERIFY(refusalOf(bytes).find("vertex 2 has a coordinate that is not finite") !=
            std::string::npos);
    head.materials[0].shininess = std::numeric_limits<float>::infinity();
    QVERIFY(refusalOf(wire::writeImportedMesh(head)).find("not a finite number") !=
            std::string::npos);
  }

  void aMeshWithoutTrianglesIsRefused() {
    HeadMesh head = sampleHead();
    for (HeadSubmesh& s : head.submeshes) s.triangles.clear();
    QVERIFY(refusalOf(wire::writeImportedMesh(head)).find("without triangles") !=
            std::string::npos);
  }

  void theWriterRefusesWhatTheReaderWould() {
    HeadMesh head = sampleHead();
    head.submeshes[0].name = std::string(wire::kMaxNameBytes + 1, 'n');
    QVERIFY_THROWS_EXCEPTION(std::length_error, (void)wire::writeImportedMesh(head));
    // A texture path too long to send cannot be opened either: it is left out.
    head = sampleHead();
    head.materials[0].diffuseTexture = "/" + std::string(wire::kMaxNameBytes, 't');
    const auto answer = wire::readImportAnswer(wire::writeImportedMesh(head), kFile);
    QVERIFY(std::get<HeadMesh>(answer).materials[0].diffuseTexture.empty());
  }
};

QTEST_GUILESS_MAIN(ImportedMeshWireTest)
#include "ImportedMeshWireTest.moc"
