#pragma once
// Comma-separated number lists for lacrima-bench options (`--threads-axis 1,2`,
// `--angles 20,40,60`), read through BenchCommandLine::option.
#include <QString>

#include <string>
#include <vector>

namespace lacrima::bench {

// Reads "1,2,4" into `out` (replacing it): at least one number, each in [low, high], whole
// numbers only when `whole`. Returns what is wrong with the text, empty when it took it.
std::string readNumberList(const QString& text, double low, double high, bool whole,
                           std::vector<double>& out);

}  // namespace lacrima::bench
