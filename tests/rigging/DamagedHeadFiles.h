#pragma once
// Damaged head files, made in the test, that each make Debian 12's assimp 5.2.5 hang, abort,
// crash, run out of memory or refuse, for the suites that check what a user sees then: the
// importer process (test_import_process, lacrima-rig) and the editor's Head workspace.
#include "../support/GeneratedHead.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>

#include <cstring>
#include <vector>

namespace lacrima::rigtest {

enum class Outcome { Hang, Crash, OutOfMemory, Refusal };

struct DamagedFile {
  QString name;  // file name, its extension the format
  QByteArray bytes;
  Outcome outcome;  // what assimp 5.2.5 does with it
  QString signal;   // for a crash: "SIGSEGV" or "SIGABRT"
};

// The generated head exported by assimp as `format` (an assimp exporter id), or empty.
inline QByteArray exportedHead(const QDir& dir, const char* format, const char* extension) {
  const QString obj = dir.filePath(QStringLiteral("exported-source.obj"));
  if (!testsupport::writeObj(testsupport::generatedHead(), obj)) return {};
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(obj.toStdString(), aiProcess_Triangulate);
  if (!scene) return {};
  const QString out = dir.filePath(QStringLiteral("exported.") + extension);
  Assimp::Exporter exporter;
  if (exporter.Export(scene, format, out.toStdString()) != AI_SUCCESS) return {};
  QFile file(out);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

inline QByteArray asciiPly() {
  QByteArray text =
      "ply\nformat ascii 1.0\ncomment a head cut short\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_index\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  return text;
}

// A binary PLY triangle whose one face lists `corners` corners (0: none).
inline QByteArray binaryPly(unsigned char corners) {
  QByteArray bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_index\nend_header\n";
  const float vertices[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  bytes.append(reinterpret_cast<const char*>(vertices), sizeof vertices);
  bytes.append(static_cast<char>(corners));
  for (std::int32_t i = 0; i < corners; ++i)
    bytes.append(reinterpret_cast<const char*>(&i), sizeof i);
  return bytes;
}

// Every damaged file; those whose source could not be exported are left out.
inline std::vector<DamagedFile> damagedHeadFiles(const QDir& dir) {
  std::vector<DamagedFile> files;
  // The 64-byte PLY: its header cut off. assimp's PLY reader waits for "end_header"
  // forever.
  files.push_back({"cut-header.ply", asciiPly().left(64), Outcome::Hang, {}});
  // A NUL byte where the header's next line starts: SIGSEGV in the PLY reader.
  files.push_back({"nul-in-header.ply", QByteArray("ply\nformat ascii 1.0\n", 21) + '\0',
                   Outcome::Crash, "SIGSEGV"});
  // A face with no corners: the triangulation step's ai_assert (SIGABRT).
  files.push_back({"face-without-corners.ply", binaryPly(0), Outcome::Crash, "SIGABRT"});
  // 200 million vertices announced in 150 bytes: past the memory limit, not a crash.
  files.push_back({"announces-millions.ply",
                   "ply\nformat binary_little_endian 1.0\nelement vertex 200000000\n"
                   "property float x\nproperty float y\nproperty float z\nend_header\n" +
                       QByteArray(64, '\0'),
                   Outcome::OutOfMemory,
                   {}});
  // A 3MF package whose model part has another name: its package reader's ai_assert.
  if (QByteArray package = exportedHead(dir, "3mf", "3mf"); !package.isEmpty()) {
    package.replace("3D/3DModel.model", "3D/3DModel.modeX");
    files.push_back({"renamed-model.3mf", package, Outcome::Crash, "SIGABRT"});
  }
  // An assbin file whose last material announces a huge number of properties: SIGSEGV.
  if (QByteArray assbin = exportedHead(dir, "assbin", "assbin"); !assbin.isEmpty()) {
    const char materialChunk[4] = {0x3c, 0x12, 0, 0};
    const qsizetype at = assbin.lastIndexOf(QByteArray(materialChunk, 4));
    if (at >= 0 && at + 12 <= assbin.size()) {
      const std::uint32_t count = 0x00aa000d;  // 11 million: under the memory limit
      std::memcpy(assbin.data() + at + 8, &count, sizeof count);
      files.push_back({"huge-material.assbin", assbin, Outcome::Crash, "SIGSEGV"});
    }
  }
  // Refused cleanly: a glTF accessor far past its buffer, FBX and GLB cut in half.
  if (QByteArray gltf = exportedHead(dir, "gltf2", "gltf"); !gltf.isEmpty()) {
    const qsizetype at = gltf.indexOf("\"count\"");
    const qsizetype colon = gltf.indexOf(':', at);
    const qsizetype end = gltf.indexOf(',', colon);
    if (at >= 0 && colon > at && end > colon) {
      // Its buffer is the exporter's exported.bin beside it, as the JSON names it.
      gltf.replace(colon + 1, end - colon - 1, " 4000000000");
      files.push_back({"accessor-past-buffer.gltf", gltf, Outcome::Refusal, {}});
    }
  }
  if (const QByteArray fbx = exportedHead(dir, "fbx", "fbx"); !fbx.isEmpty())
    files.push_back({"cut.fbx", fbx.left(fbx.size() / 2), Outcome::Refusal, {}});
  if (const QByteArray glb = exportedHead(dir, "glb2", "glb"); !glb.isEmpty())
    files.push_back({"cut.glb", glb.left(glb.size() / 2), Outcome::Refusal, {}});
  return files;
}

// Writes `file` into `dir`; its path, or empty when it could not be written.
inline QString writeDamagedFile(const QDir& dir, const DamagedFile& file) {
  const QString path = dir.filePath(file.name);
  QFile out(path);
  if (!out.open(QIODevice::WriteOnly) || out.write(file.bytes) != file.bytes.size()) return {};
  return path;
}

}  // namespace lacrima::rigtest
