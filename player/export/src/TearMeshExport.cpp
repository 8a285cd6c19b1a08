#include <lacrima/export/TearMeshExport.h>

#include "TearPieces.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>

#include <QDir>
#include <QElapsedTimer>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace lacrima::exporting {
namespace {

template <typename T>
void append(std::string& bytes, T value) {
  static_assert(std::endian::native == std::endian::little, "PLY here is binary_little_endian");
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// One frame's pieces as a binary PLY (see TearMeshExport.h), positions scaled by `metres`.
std::string plyBytes(const std::vector<TearPiece>& pieces, double metres) {
  long long vertices = 0, faces = 0;
  for (const TearPiece& p : pieces) {
    vertices += p.positions.cols();
    faces += p.triangles.cols();
  }
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\ncomment Lacrima tears: water and wet trails, metres, "
      "Y up\nelement vertex " +
      std::to_string(vertices) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty "
      "float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\nproperty uchar "
      "blue\nproperty uchar alpha\nelement face " +
      std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
  bytes.reserve(bytes.size() + static_cast<std::size_t>(vertices) * 28 +
                static_cast<std::size_t>(faces) * 13);
  for (const TearPiece& p : pieces) {
    const bool water = p.kind == TearKind::Water;
    for (Eigen::Index v = 0; v < p.positions.cols(); ++v) {
      for (int c = 0; c < 3; ++c) append(bytes, static_cast<float>(p.positions(c, v) * metres));
      for (int c = 0; c < 3; ++c) append(bytes, static_cast<float>(p.normals(c, v)));
      const double wetness = water ? 1.0 : std::clamp(p.alpha(v), 0.0, 1.0);
      const std::array<std::uint8_t, 4> colour = {
          water ? std::uint8_t{0} : std::uint8_t{255}, 128,
          water ? std::uint8_t{255} : std::uint8_t{0},
          static_cast<std::uint8_t>(std::lround(255 * wetness))};
      bytes.append(reinterpret_cast<const char*>(colour.data()), colour.size());
    }
  }
  std::int32_t first = 0;
  for (const TearPiece& p : pieces) {
    for (Eigen::Index t = 0; t < p.triangles.cols(); ++t) {
      append(bytes, std::uint8_t{3});
      for (int c = 0; c < 3; ++c) append(bytes, first + p.triangles(c, t));
    }
    first += static_cast<std::int32_t>(p.positions.cols());
  }
  return bytes;
}

}  // namespace

TearMeshExportResult exportTearMeshes(const playback::HeadRig& rig, const ExportOptions& options) {
  QElapsedTimer wall;
  wall.start();
  playback::Playback playback(rig);
  const FrameSpan span = openForExport(playback, options);
  const QString folder = QString::fromStdString(options.output);
  if (!QDir().mkpath(folder))
    throw FileError({options.output, 0, 0}, "cannot create the output folder");
  const QDir out(folder);
  const double metres = metresPerUnit(rig);
  TearMeshExportResult result;
  for (int f = span.first; f <= span.last; ++f) {
    // A file without tear channels is never simulated: its frames are all empty.
    const std::vector<TearPiece> pieces = playback.hasTears()
                                              ? tearPieces(playback.seek(f / playback.frameRate()))
                                              : std::vector<TearPiece>{};
    char name[32];
    std::snprintf(name, sizeof name, "tears_%04d.ply", f);
    const std::string bytes = plyBytes(pieces, metres);
    saveAtomically(out.filePath(QString::fromLatin1(name)).toStdString(), bytes);
    result.bytes += bytes.size();
    result.framesWithTears += pieces.empty() ? 0 : 1;
    ++result.frames;
    reportProgress(options, playback, f - span.first + 1, span.count());
  }
  result.seconds = static_cast<double>(wall.elapsed()) / 1000.0;
  return result;
}

}  // namespace lacrima::exporting
