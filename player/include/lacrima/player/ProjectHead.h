#pragma once
// Which head the player animates a file on: a project's own head (its "head" entry), else the
// default head; --mesh/--fdp override both. Projects name their head relative to their folder
// (ProjectDocument.h); a head file that is missing is an error naming the project, the JSON
// path and the file, raised before any rigging starts.
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/playback/HeadRig.h>

#include <memory>
#include <optional>
#include <string>

namespace lacrima::player {

// The head `path` names: nullopt for a FAP file or a project without a "head" entry. Paths
// are absolute. Throws FileError for a project that cannot be read.
std::optional<HeadFiles> headOfFile(const std::string& path);

// The rig for `head` (the default head for nullopt). `namedBy` is the project that names the
// head, for the message when one of its files is missing (FileError "project: head.mesh: no
// file at ...").
std::unique_ptr<playback::HeadRig> loadHeadFor(const std::optional<HeadFiles>& head,
                                               const std::string& namedBy);

}  // namespace lacrima::player
