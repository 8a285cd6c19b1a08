// Runs a fuzz target's LLVMFuzzerTestOneInput over files and folders of inputs, once each, in
// sorted order: the sanitizer build's replay of the committed corpus and regression files.
//
// This stands in for libFuzzer's own driver there, so that the replay needs neither clang's
// fuzzer runtime nor coverage instrumentation; a finding is whatever the sanitizers or the
// target's abort() make of an input, and the input's path is printed before it runs so that the
// log names the culprit.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

// The committed seeds and regression files are a few KiB each; a file this large among them is
// a mistake, not an input, and is refused before it is read.
constexpr std::uintmax_t kMaxInputBytes = 1u << 20;

bool collectInputs(const fs::path& argument, std::vector<fs::path>& inputs) {
  std::error_code error;
  if (fs::is_directory(argument, error)) {
    for (const auto& entry : fs::directory_iterator(argument, error))
      if (entry.is_regular_file()) inputs.push_back(entry.path());
  } else if (fs::is_regular_file(argument, error)) {
    inputs.push_back(argument);
  } else {
    std::fprintf(stderr, "fuzz replay: %s: no such file or folder\n", argument.c_str());
    return false;
  }
  return !error;
}

bool replay(const fs::path& input) {
  std::error_code error;
  const std::uintmax_t size = fs::file_size(input, error);
  if (error || size > kMaxInputBytes) {
    std::fprintf(stderr, "fuzz replay: %s: unreadable, or larger than %ju bytes\n", input.c_str(),
                 kMaxInputBytes);
    return false;
  }
  std::ifstream in(input, std::ios::binary);
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>()};
  std::fprintf(stderr, "fuzz replay: %s\n", input.c_str());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...\n", argv[0]);
    return 2;
  }
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i)
    if (!collectInputs(argv[i], inputs)) return 2;
  std::sort(inputs.begin(), inputs.end());
  if (inputs.empty()) {
    std::fprintf(stderr, "fuzz replay: no inputs in the given folders\n");
    return 2;
  }
  for (const fs::path& input : inputs)
    if (!replay(input)) return 1;
  std::printf("fuzz replay: %zu inputs, no finding\n", inputs.size());
  return 0;
}
