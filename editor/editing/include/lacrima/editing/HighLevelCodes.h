#pragma once
// The codes of the high-level FAPs as the pickers list them: FAP 1 selects one of 15 visemes
// (0 = none), FAP 2 one of the six basic expressions (0 = neutral). Names and example sounds
// are the standard's (ISO/IEC 14496-2, visemes and expressions tables).
#include <span>
#include <string_view>

namespace lacrima::editing {

struct HighLevelCode {
  int code;
  std::string_view name;    // "PP", "joy"
  std::string_view detail;  // "p, b, m as in put, bed, mill"
};

std::span<const HighLevelCode> visemeCodes();      // 0..14
std::span<const HighLevelCode> expressionCodes();  // 0..6

}  // namespace lacrima::editing
