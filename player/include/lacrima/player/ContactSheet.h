#pragma once
// A contact sheet: a few frames of an animation side by side, each labelled with its frame
// number and time, under a title line. For a quick look at a batch render.
#include <QImage>
#include <QString>

#include <vector>

namespace lacrima::player {

// `count` frame indices spread evenly over [0, frames - 1], first and last included (fewer
// when the animation has fewer frames).
std::vector<int> evenlySpacedFrames(int frames, int count);

struct SheetFrame {
  QImage image;
  int frame = 0;
  double seconds = 0;
};

// Thumbnails `thumbWidth` wide (height from the aspect ratio), `columns` per row.
QImage contactSheet(const std::vector<SheetFrame>& frames, const QString& title, int columns = 4,
                    int thumbWidth = 400);

}  // namespace lacrima::player
