#pragma once
// The panels and colours lacrima-rig uses for --fdp-image and --pose-image: the whole head from
// the front and the side, plus close-ups of the eyes and the mouth from the front, where
// feature points crowd and where the lips and lids must not pull each other.
#include <lacrima/exporters/HeadPreview.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <map>
#include <string>
#include <vector>

namespace lacrima {

// Positions of the points a preview shows: feature points by id, plus "eyeL"/"eyeR" centres,
// "7.1" pivot and "tearL"/"tearR" when known.
using PreviewPoints = std::map<std::string, Eigen::Vector3d, rigging::FdpIdLess>;

std::vector<exporters::PreviewPanel> previewPanels(const HeadMesh& mesh,
                                                   const PreviewPoints& points);
std::vector<exporters::PreviewMarker> previewMarkers(const PreviewPoints& points);
exporters::PreviewStyle previewStyle(const HeadMesh& mesh, const rigging::FeaturePointFile& fdp,
                                     int panelSize);

}  // namespace lacrima
