#pragma once
// "Where does this point go?": a picture of a rigged head (the default head, or any head with
// its feature points) with one feature point highlighted, for the Head workspace's reference
// panel beside the head being marked up, together with the point's description
// (fdpDescription, lacrima/common/FdpTable.h).
//
// Software-rendered (HeadPreview.h: QPainter, no GPU, no OGRE), so it works on every platform
// the editor runs on, offscreen included. The picture is framed on the point's region
// (referenceView):
//   Eyes   eyelid, eye and eyebrow points (groups 3 and 4): both eyes close up, front on
//   Mouth  lip, tongue and teeth points (2.2-2.9, 8.x, 6.x, 9.8-9.11): the mouth close up
//   Side   the left ear, the back of the skull and the neck pivot (10.1/3/5/7/9, 11.6, 7.1):
//          the whole head from the face's left
//   Face   everything else: the whole head, front on
// Close-ups are sized from the head's own points (eye separation 3.5-3.6, mouth width 8.3-8.4)
// and fall back to a tenth of the head's size around the point when those are missing.
//
// The other feature points show as small grey dots; the highlighted one as a disc of the
// highlight colour in a white and a dark ring, with short cross hairs so it is found at a
// glance. A point hidden from the view (the tongue behind closed lips, the back of the ear) is
// drawn as a dashed ring only, and the picture says so (ReferencePicture::hidden).
#include <lacrima/common/HeadMesh.h>
#include <lacrima/exporters/HeadPreview.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <Eigen/Core>
#include <QColor>
#include <QImage>
#include <QPointF>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::exporters {

enum class ReferenceView { Face, Eyes, Mouth, Side };
ReferenceView referenceView(std::string_view fdpId);

// A head with its feature points, ready to draw.
struct ReferenceHead {
  HeadMesh mesh;
  std::map<std::string, Eigen::Vector3d, rigging::FdpIdLess> points;  // neutral positions
  std::vector<std::optional<QColor>> submeshColours;  // HeadPreview style; nullopt hides
};

// The default head (rigging/DefaultHead.h) with the points of media/default-head.fdp.json;
// transparent cards and corneas hidden. Throws FileError when the head is not fetched or the
// file is missing. Takes about 0.1 s: load it once and keep it.
ReferenceHead defaultReferenceHead();

// Any head with its (validated) feature-point file: each point at its surface position.
ReferenceHead referenceHead(HeadMesh mesh, const rigging::FeaturePointFile& points);

struct ReferenceStyle {
  int size = 360;  // square picture, pixels
  QColor highlight = QColor(255, 40, 190);
  QColor others = QColor(150, 150, 150);  // the other points' dots
  double highlightRadius = 6;             // pixels
};

struct ReferencePicture {
  QImage image;         // null when the head has no point `id`
  QPointF pixel;        // where the point is drawn
  bool hidden = false;  // the surface hides it from this view (drawn as a dashed ring)
  ReferenceView view = ReferenceView::Face;
  PreviewPanel panel;  // the view's centre and size (model units)
};

// The picture for feature point `id` of `head`. Needs a QGuiApplication (fonts; the offscreen
// platform is enough).
ReferencePicture renderFeaturePointReference(const ReferenceHead& head, std::string_view id,
                                             const ReferenceStyle& style = {});

}  // namespace lacrima::exporters
