#include "TearPieces.h"

#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailBuilder.h>

namespace lacrima::exporting {

std::vector<TearPiece> tearPieces(const playback::FrameView& view) {
  std::vector<TearPiece> pieces;
  for (const tears::TearSurface* water : {view.surface, view.drops})
    if (water && !water->empty())
      pieces.push_back(
          {TearKind::Water, water->positions(), water->normals(), water->triangles(), {}});
  if (view.trails && !view.trails->empty())
    pieces.push_back({TearKind::Trail, view.trails->positions(), view.trails->normals(),
                      view.trails->triangles(), view.trails->alpha()});
  return pieces;
}

}  // namespace lacrima::exporting
