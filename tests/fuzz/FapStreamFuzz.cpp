// FAP text as a live input receives it: the bytes as one datagram (decodeFapDatagram: a frame or
// a FileError), and as a TCP stream cut in two at a place the input chooses (FapTextStream: it
// never throws, counts what it refuses, and holds at most one line).
#include "FuzzInput.h"

#include <lacrima/common/FapTextStream.h>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = lacrima::fuzz::text(data, size);
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    const lacrima::FapDatagram datagram = lacrima::decodeFapDatagram(bytes, "fuzz.udp");
    (void)datagram.frame.number;
  });
  lacrima::FapTextStream stream("fuzz.tcp");
  const std::size_t cut = size > 0 ? data[0] % (size + 1) : 0;
  long long frames = 0;
  const auto count = [&](const lacrima::FapTextFrame&) { ++frames; };
  stream.feed(bytes.substr(0, cut), count);
  if (stream.bufferedBytes() > lacrima::FapTextParser::kMaxLineLength) std::abort();
  stream.feed(bytes.substr(cut), count);
  stream.finish();
  if (frames != stream.counters().frames) std::abort();
  return 0;
}
