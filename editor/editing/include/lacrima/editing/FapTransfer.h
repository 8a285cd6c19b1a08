#pragma once
// FAP files in and out of the editor.
//
// Import: the tolerant FapReader decodes the file; each frame i becomes a linear key at
// i / fps holding the file's animated channels, optionally thinned by reduceKeyFrames (see
// KeyReduction.h for the maths and its guarantee). Export: the document is baked at a frame
// rate (22 fps unless asked otherwise) and written by FapWriter, either extended (the tear
// channels 69-70 as a 70-token mask when a tear channel moves) or strict (the 68 standard FAPs,
// for other players). Both report the reader's/writer's warnings instead of dropping them.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/ProjectDocument.h>

#include <optional>
#include <string>

namespace lacrima::editing {

struct FapImportOptions {
  // nullopt: every frame becomes a key. Otherwise the reduction tolerance (>= 0).
  std::optional<double> reductionTolerance;
};

struct FapImportResult {
  ProjectDocument document;
  int frames = 0;       // frames in the file
  int keys = 0;         // keys made from them
  double maxError = 0;  // largest reproduction error of a dropped frame (channel units)
  Warnings warnings;
};

// Throws FileError (file:line:column: what was expected) for input the reader rejects.
FapImportResult importFap(const std::string& path, const FapImportOptions& options = {});
// Same, from a decoded animation (tests, benchmarks).
FapImportResult importAnimation(const FapAnimation& animation,
                                const FapImportOptions& options = {});

struct FapExportOptions {
  double fps = 22.0;
  bool strict = false;  // 68 standard FAPs only
};

struct FapExportResult {
  int frames = 0;
  bool wroteTears = false;
  Warnings warnings;
};

// Atomic: a failed export leaves an existing file untouched. Throws FileError.
FapExportResult exportFap(const ProjectDocument& document, const std::string& path,
                          const FapExportOptions& options = {});

}  // namespace lacrima::editing
