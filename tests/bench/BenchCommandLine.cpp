#include "BenchCommandLine.h"

#include <lacrima/common/ImageSize.h>

#include <cstdio>

namespace lacrima::bench {

BenchCommandLine::BenchCommandLine(std::string subcommand, const QString& description)
    : subcommand_(std::move(subcommand)), help_(QStringList{"h", "help"}, "Shows this help.") {
  parser_.setApplicationDescription(description);
  // Not addHelpOption(): its --help-all lists Qt's own options, which a benchmark never reads.
  parser_.addOption(help_);
}

void BenchCommandLine::flag(const QString& name, const QString& help, bool& target) {
  parser_.addOption(QCommandLineOption(name, help));
  flags_.emplace_back(name, &target);
}

void BenchCommandLine::option(const QString& name, const QString& valueName, const QString& help,
                              Reader read) {
  parser_.addOption(QCommandLineOption(name, help, valueName));
  readers_.emplace_back(name, std::move(read));
}

void BenchCommandLine::wholeNumber(const QString& name, const QString& valueName,
                                   const QString& help, int low, int high, int& target) {
  option(name, valueName, help, [low, high, &target](const QString& text) {
    bool ok = false;
    const int value = text.toInt(&ok);
    if (!ok || value < low || value > high)
      return "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high) +
             ", not '" + text.toStdString() + "'";
    target = value;
    return std::string();
  });
}

void BenchCommandLine::number(const QString& name, const QString& valueName, const QString& help,
                              double low, double high, double& target, Low lowEnd) {
  option(name, valueName, help, [low, high, lowEnd, &target](const QString& text) {
    bool ok = false;
    const double value = text.toDouble(&ok);
    const bool aboveLow = lowEnd == Low::Included ? value >= low : value > low;
    if (!ok || !aboveLow || !(value <= high))
      return "expected a number in " + std::string(lowEnd == Low::Included ? "[" : "(") +
             QString::number(low).toStdString() + ", " + QString::number(high).toStdString() +
             "], not '" + text.toStdString() + "'";
    target = value;
    return std::string();
  });
}

void BenchCommandLine::text(const QString& name, const QString& valueName, const QString& help,
                            std::string& target) {
  option(name, valueName, help, [&target](const QString& text) {
    target = text.toStdString();
    return std::string();
  });
}

void BenchCommandLine::choiceOf(const QString& name, const QString& help, const QStringList& words,
                                std::function<void(qsizetype chosen)> take) {
  option(name, words.join('|'), help, [words, take = std::move(take)](const QString& text) {
    const qsizetype chosen = words.indexOf(text);
    if (chosen < 0)
      return "expected " + words.join(" or ").toStdString() + ", not '" + text.toStdString() + "'";
    take(chosen);
    return std::string();
  });
}

void BenchCommandLine::imageSize(const QString& name, const QString& help, int& width,
                                 int& height) {
  option(name, "WxH", help, [&width, &height](const QString& text) {
    const ParsedImageSize parsed = parseImageSize(text.toStdString());
    if (parsed.error.empty()) {
      width = parsed.size.width();
      height = parsed.size.height();
    }
    return parsed.error;
  });
}

std::optional<int> BenchCommandLine::parse(int argc, char** argv) {
  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  const auto usageError = [this](const std::string& message) {
    std::fprintf(stderr, "lacrima-bench %s: %s\n(see lacrima-bench %s --help)\n",
                 subcommand_.c_str(), message.c_str(), subcommand_.c_str());
    return 2;
  };
  if (!parser_.parse(arguments)) return usageError(parser_.errorText().toStdString());
  if (parser_.isSet(help_)) {
    // The sub-commands run before any QCoreApplication exists, so Qt cannot name the program.
    QString help = parser_.helpText();
    help.replace(0, help.indexOf('\n'),
                 "Usage: lacrima-bench " + QString::fromStdString(subcommand_) + " [options]");
    std::fputs(help.toLocal8Bit().constData(), stdout);
    return 0;
  }
  if (!parser_.positionalArguments().isEmpty())
    return usageError("unexpected argument '" +
                      parser_.positionalArguments().first().toStdString() + "'");
  for (const auto& [name, target] : flags_)
    if (parser_.isSet(name)) *target = true;
  for (const auto& [name, read] : readers_)
    for (const QString& value : parser_.values(name))
      if (const std::string problem = read(value); !problem.empty())
        return usageError("--" + name.toStdString() + ": " + problem);
  return std::nullopt;
}

}  // namespace lacrima::bench
