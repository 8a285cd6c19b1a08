// A feature-point file (readFeaturePointFile), then checked against a small synthetic head with
// the default head's part names (validateFeaturePoints), as lacrima-rig does with a real one.
#include "FuzzInput.h"

#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>

namespace {

// A 6 x 6 vertex sheet per part, the parts side by side: enough vertices and triangles for
// indices, barycentrics and snapping to mean something.
lacrima::HeadMesh syntheticHead() {
  constexpr int kSide = 6;
  const char* parts[] = {"skin",        "eye_l",       "eye_r",  "cornea_l",  "cornea_r",
                         "teeth_upper", "teeth_lower", "tongue", "eyelashes", "eyebrows"};
  lacrima::HeadMesh head;
  const int partCount = static_cast<int>(std::size(parts));
  head.positions.resize(3, partCount * kSide * kSide);
  for (int p = 0; p < partCount; ++p) {
    lacrima::HeadSubmesh part;
    part.name = parts[p];
    part.firstVertex = p * kSide * kSide;
    part.vertexCount = kSide * kSide;
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x)
        head.positions.col(part.firstVertex + y * kSide + x) =
            Eigen::Vector3f(static_cast<float>(x + p * kSide), static_cast<float>(y), 0.1f * p);
    for (int y = 0; y + 1 < kSide; ++y)
      for (int x = 0; x + 1 < kSide; ++x) {
        const int v = part.firstVertex + y * kSide + x;
        part.triangles.emplace_back(v, v + 1, v + kSide + 1);
        part.triangles.emplace_back(v, v + kSide + 1, v + kSide);
      }
    head.submeshes.push_back(std::move(part));
  }
  head.computeNormals();
  return head;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const lacrima::HeadMesh head = syntheticHead();
  const lacrima::fuzz::InputFile file(data, size, ".fdp.json");
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    lacrima::Warnings warnings;
    const auto points = lacrima::rigging::readFeaturePointFile(file.path(), &warnings);
    (void)lacrima::rigging::validateFeaturePoints(points, head, &warnings,
                                                  lacrima::rigging::FeaturePointSet::Partial);
  });
  return 0;
}
