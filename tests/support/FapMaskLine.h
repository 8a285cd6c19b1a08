#pragma once
// A .fap mask line written by hand for the reader's and the streams' suites: `tokens` tokens
// (68, or 70 with the tear channels), 1 for each FAP in `faps`, single spaces, no newline.
#include <lacrima/common/FapChannels.h>

#include <algorithm>
#include <initializer_list>
#include <string>

namespace lacrima::test {

inline std::string mask(std::initializer_list<int> faps, int tokens = kFapCount) {
  std::string line;
  for (int fap = 1; fap <= tokens; ++fap) {
    line += std::find(faps.begin(), faps.end(), fap) != faps.end() ? "1 " : "0 ";
  }
  line.pop_back();
  return line;
}

}  // namespace lacrima::test
