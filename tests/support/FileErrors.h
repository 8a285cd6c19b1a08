#pragma once
// Tests that bad input is refused with the right message: the text of the FileError a call
// throws.
#include <lacrima/common/Diagnostics.h>

#include <string>

namespace lacrima::testsupport {

// The message of the FileError `f` throws, or "" when it throws none (any other exception
// escapes, so the test fails on it).
template <class F>
std::string fileErrorOf(F&& f) {
  try {
    f();
  } catch (const FileError& e) {
    return e.what();
  }
  return {};
}

}  // namespace lacrima::testsupport
