#pragma once
// One lacrima-bench sub-command's options, read with QCommandLineParser as the applications read
// theirs: `--help` for each sub-command, `--name value` or `--name=value`, and one line naming
// the option and what it expects for anything unusable (exit status 2). Each option writes into
// the sub-command's own Options, so the values those start with are the defaults.
#include <QCommandLineParser>
#include <QStringList>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lacrima::bench {

class BenchCommandLine {
 public:
  // `subcommand` names it in the usage line and in the errors ("lacrima-bench tears: ...").
  BenchCommandLine(std::string subcommand, const QString& description);

  void flag(const QString& name, const QString& help, bool& target);
  void wholeNumber(const QString& name, const QString& valueName, const QString& help, int low,
                   int high, int& target);
  // A number in [low, high], or in (low, high] for what must stay above `low` (a rate, a factor).
  enum class Low { Included, Excluded };
  void number(const QString& name, const QString& valueName, const QString& help, double low,
              double high, double& target, Low lowEnd = Low::Included);
  void text(const QString& name, const QString& valueName, const QString& help,
            std::string& target);
  void imageSize(const QString& name, const QString& help, int& width, int& height);

  // One of a few words, each standing for a value of `target`.
  template <typename T>
  void choice(const QString& name, const QString& help, std::vector<std::pair<QString, T>> choices,
              T& target) {
    QStringList words;
    for (const auto& choice : choices) words << choice.first;
    choiceOf(name, help, words, [choices = std::move(choices), &target](qsizetype chosen) {
      target = choices[static_cast<std::size_t>(chosen)].second;
    });
  }

  // Any other option taking a value: `read` gets each value given, in order (so a repeated
  // option sees them all), and returns what is wrong with it, empty when it took it.
  using Reader = std::function<std::string(const QString& value)>;
  void option(const QString& name, const QString& valueName, const QString& help, Reader read);

  // Reads the sub-command's arguments (argv[0] is the sub-command). Nothing when it should run;
  // otherwise the exit status to return at once, with what was asked for printed: 0 after
  // --help, 2 for wrong usage.
  std::optional<int> parse(int argc, char** argv);

 private:
  void choiceOf(const QString& name, const QString& help, const QStringList& words,
                std::function<void(qsizetype chosen)> take);

  std::string subcommand_;
  QCommandLineParser parser_;
  QCommandLineOption help_;
  std::vector<std::pair<QString, bool*>> flags_;
  std::vector<std::pair<QString, Reader>> readers_;
};

}  // namespace lacrima::bench
