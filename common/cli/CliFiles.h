#pragma once
// File handling shared by lacrima-fap's commands: one place decides whether a path is a
// project or a .fap file, and every warning reaches stderr in the same form.
#include <lacrima/common/FapReader.h>
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/common/ProjectPath.h>

#include <string>

namespace lacrima {

// Projects are told from FAP files by isProjectPath (ProjectPath.h): .lacrima or .json.

FapReadResult readFap(const std::string& path);  // warnings printed to stderr
ProjectDocument loadProject(const std::string& path);
FapAnimation loadAnimation(const std::string& path);  // a .fap file, or a project baked at its fps

void saveAnimation(const FapAnimation& animation, const std::string& path, bool strict);
void saveProject(const ProjectDocument& project, const std::string& path);

}  // namespace lacrima
