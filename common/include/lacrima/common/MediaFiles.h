#pragma once
// Finding Lacrima's own media (media/ in the source tree, share/lacrima/ once installed):
// the default head's feature-point file, the demo animation. The player, the editor's preview,
// lacrima-rig and the benchmarks all look here, so each finds what the others find.
//
// A file media/X is looked for, in this order, at
//   1. <folder of the running executable>/../share/lacrima/X   (an installed or relocated tree)
//   2. <CMAKE_INSTALL_PREFIX>/share/lacrima/X                  (installed, executable moved away)
//   3. <source tree>/media/X                                     (run from a build directory)
// so a build directory works without installing and an installed copy works without the
// sources. The first needs a QCoreApplication; without one it is skipped.
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

// Every place media/`relative` is looked for, in search order.
std::vector<std::string> mediaCandidates(std::string_view relative);

// The first candidate that exists. Throws FileError naming `relative` and every place looked.
std::string findMediaFile(std::string_view relative);

}  // namespace lacrima::inline common
