#pragma once
// A starting radius for a feature point's influence, from the face's own FAPUs.
//
// Choice: r = the typical spacing between the point and its neighbours on the same facial
// contour in the MPEG-4 feature-point layout. With the falloff w(s) + w(1 - s) = 1 (see
// InfluenceFalloff.h), neighbours one radius apart then share the surface between them and
// a FAP that moves both equally moves that strip rigidly, with no dip or bulge. By FDP group:
//   2.1, 2.10 - 2.14 (jaw, chin)          MW0       the chin and jaw move as one block
//   2 other, 8 (inner and outer lips)      MW0 / 4   corner, half-way point, middle: MW0/4 apart
//   3 (eyelids, eyes)                      ES0 / 4   eye width ~ ES0/2, lid middle to corners
//   4 (eyebrows)                           ES0 / 3   inner, middle, outer over ~2/3 ES0
//   5 (cheeks)                             ES0 / 2
//   6 (tongue)                             MW0 / 4
//   9 (nose)                               ENS0 / 4  nostrils, tip and bridge
//   10 (ears)                              ES0 / 4
//   7, 11 (head, hair line)                ES0 / 2
// Surface distance keeps these radii from crossing the mouth slit or the eye opening. They are
// defaults only: the rig tunes each point.
#include <lacrima/common/Fapu.h>

#include <string_view>

namespace lacrima::rigging {

// `featurePoint` is an FDP id "group.index", e.g. "8.3". Throws std::invalid_argument for a
// malformed id, a group outside 2-11, or a needed FAPU distance that is not positive.
double defaultInfluenceRadius(const FapuSet& fapu, std::string_view featurePoint);

}  // namespace lacrima::rigging
