#pragma once
// Finding Lacrima's own media (media/ in the source tree, share/lacrima/ once installed):
// the default head's feature-point file, the demo animation. The player, the editor's preview,
// lacrima-rig and the benchmarks all look here, so each finds what the others find.
//
// A file media/X is looked for at
//   1. <folder of the running executable>/../share/lacrima/X   (installed under any prefix)
//   2. <source tree>/media/X, only when the running executable is in this build's bin/
// so a build directory works without installing, and an installed copy, moved or not, reads
// only its own share/lacrima: never the sources it was built from, even when they are still
// there. No prefix is compiled in, so /usr, /usr/local and ~/opt/lacrima all work.
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

// The folder of the running executable (symbolic links resolved), from /proc/self/exe; empty
// when that cannot be read. Needs no QCoreApplication.
std::string executableDir();

// Every place media/`relative` is looked for by an executable in `executableDir`, in search
// order. Separate from the running process so the rule can be tested for any location.
std::vector<std::string> mediaCandidatesFor(const std::string& executableDir,
                                            std::string_view relative);

// mediaCandidatesFor(executableDir(), relative).
std::vector<std::string> mediaCandidates(std::string_view relative);

// The first candidate that exists. Throws FileError naming `relative` and every place looked.
std::string findMediaFile(std::string_view relative);

}  // namespace lacrima::inline common
