#include <lacrima/editor/EditorTheme.h>

#include <lacrima/viewport/DarkTheme.h>

namespace lacrima::editor::theme {

void apply(QApplication& app) { viewport::applyDarkTheme(app); }

QColor keyAccent() { return {0xf2, 0xb1, 0x3a}; }
QColor keyIdle() { return {0xc4, 0xc8, 0xcf}; }
QColor playhead() { return {0xe8, 0x5a, 0x4f}; }
QColor tearBlue() { return {0x5a, 0xb4, 0xf0}; }

QColor groupColour(FapGroup group) {
  switch (group) {
    case FapGroup::VisemeExpression:
      return {0xd0, 0xd3, 0xd8};
    case FapGroup::JawChinInnerLips:
      return {0xf0, 0x8c, 0x4b};
    case FapGroup::Eyes:
      return {0x4c, 0xc9, 0xb0};
    case FapGroup::Eyebrows:
      return {0xa5, 0x87, 0xf0};
    case FapGroup::Cheeks:
      return {0xf0, 0x7e, 0xb2};
    case FapGroup::Tongue:
      return {0xe0, 0x5d, 0x5d};
    case FapGroup::Head:
      return {0x8f, 0xa9, 0xc9};
    case FapGroup::OuterLips:
      return {0xf2, 0xa2, 0x7c};
    case FapGroup::Nose:
      return {0xe6, 0xcf, 0x5a};
    case FapGroup::Ears:
      return {0x8c, 0xc9, 0x6a};
    case FapGroup::Tears:
      return tearBlue();
  }
  return {0xc0, 0xc0, 0xc0};
}

}  // namespace lacrima::editor::theme
