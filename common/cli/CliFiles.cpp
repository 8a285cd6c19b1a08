#include "CliFiles.h"

#include <lacrima/common/FapWriter.h>

#include <cstdio>

namespace lacrima {

static void printWarnings(const Warnings& warnings) {
  for (const Diagnostic& w : warnings) std::fprintf(stderr, "%s (warning)\n", w.toString().c_str());
}

FapReadResult readFap(const std::string& path) {
  FapReadResult result = FapReader::readFile(path);
  printWarnings(result.warnings);
  return result;
}

ProjectDocument loadProject(const std::string& path) { return ProjectDocument::load(path); }

FapAnimation loadAnimation(const std::string& path) {
  if (!isProjectPath(path)) return readFap(path).animation;
  return ProjectDocument::load(path, ProjectDocument::Use::Bake).bake();
}

void saveAnimation(const FapAnimation& animation, const std::string& path, bool strict) {
  if (isProjectPath(path)) {
    saveProject(ProjectDocument::fromAnimation(animation), path);
    return;
  }
  Warnings warnings;
  FapWriter::save(animation, path, FapWriteOptions{.strict = strict}, &warnings);
  printWarnings(warnings);
}

void saveProject(const ProjectDocument& project, const std::string& path) { project.save(path); }

}  // namespace lacrima
