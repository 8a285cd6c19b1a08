// lacrima-fap: inspect, dump, resample and convert FAP animations and Lacrima projects.
// The interface scripts rely on: exit 0 on success, 1 on bad input or a failed write,
// 2 on wrong usage; results on stdout, diagnostics on stderr as "file:line:col: message".
#include "CliFiles.h"
#include "GenerateCommand.h"

#include <lacrima/common/CommandLineNumbers.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/common/mood/MoodGenerator.h>

#include <QCommandLineParser>
#include <QCoreApplication>

#include <charconv>
#include <cstdio>
#include <functional>
#include <string>

using namespace lacrima;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

const char* const kCommandSummary =
    "Commands:\n"
    "  check FILE                         validate a .fap file or project; one summary line\n"
    "  dump FILE                          decoded frames as CSV (frame,fap1,...,fap70)\n"
    "  interpolate IN -o OUT [--fps 22] [--smooth]\n"
    "                                     IN's frames as keys, resampled densely at --fps\n"
    "  convert IN -o OUT [--strict]       .fap <-> .lacrima/.json; --strict: 68-FAP .fap\n"
    "  generate --mood sadness=0.8[,anger=0.2] | --script moods.json --seconds S\n"
    "           [--seed N] [--rate 22] [--strict] -o OUT\n"
    "                                     a take of the crying generator (docs/mood.md)\n";

// "3-26 39-42 63": compact list of the channels in a mask.
std::string channelRanges(const ChannelMask& mask) {
  std::string out;
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (!mask.test(channelIndex(fap))) continue;
    int last = fap;
    while (last < kChannelCount && mask.test(channelIndex(last + 1))) ++last;
    if (!out.empty()) out += ' ';
    out += std::to_string(fap);
    if (last > fap) out += '-' + std::to_string(last);
    fap = last;
  }
  return out.empty() ? "none" : out;
}

std::string formatNumber(double value) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(value);
}

int check(const std::string& path) {
  if (isProjectPath(path)) {
    const ProjectDocument doc = loadProject(path);
    ChannelMask channels;
    for (const Keyframe& key : doc.keys.keys()) channels |= key.channels;
    std::printf("%s: project \"%s\", %d keys over %s s, %s fps, channels %s\n", path.c_str(),
                doc.name.c_str(), static_cast<int>(doc.keys.keys().size()),
                formatNumber(doc.keys.endTime() - doc.keys.startTime()).c_str(),
                formatNumber(doc.fps).c_str(), channelRanges(channels).c_str());
    return kExitOk;
  }
  const FapReadResult read = readFap(path);
  const FapAnimation& anim = read.animation;
  std::printf("%s: FAP %s, %s fps, %d frames (%s s), %d channels masked (%s), %d warning%s\n",
              path.c_str(), anim.version.c_str(), formatNumber(anim.fps).c_str(), anim.frameCount(),
              formatNumber(anim.duration()).c_str(), static_cast<int>(anim.animated.count()),
              channelRanges(anim.animated).c_str(), static_cast<int>(read.warnings.size()),
              read.warnings.size() == 1 ? "" : "s");
  return kExitOk;
}

int dump(const std::string& path) {
  const FapAnimation anim = loadAnimation(path);
  std::string out = "frame";
  for (int fap = 1; fap <= kChannelCount; ++fap) out += ",fap" + std::to_string(fap);
  out += '\n';
  char buf[32];
  for (int i = 0; i < anim.frameCount(); ++i) {
    out += std::to_string(i);
    for (float v : anim.frames[static_cast<size_t>(i)]) {
      out += ',';
      out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
    }
    out += '\n';
    if (out.size() > (1 << 20)) {  // stream big animations instead of holding all text
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  return std::ferror(stdout) ? kExitBadInput : kExitOk;
}

int interpolate(const std::string& in, const std::string& out, double fps, bool smooth) {
  const Interpolation mode = smooth ? Interpolation::Smooth : Interpolation::Linear;
  KeyframeSequence keys;
  std::string name;
  if (isProjectPath(in)) {
    ProjectDocument doc = loadProject(in);
    name = doc.name;
    std::vector<Keyframe> k = doc.keys.keys();
    for (Keyframe& key : k) key.interpolation = mode;
    keys = KeyframeSequence(std::move(k));
  } else {
    const FapAnimation source = loadAnimation(in);
    name = source.name;
    keys = KeyframeSequence::fromAnimation(source, mode);
  }
  FapAnimation dense = keys.bake(fps);
  dense.name = name;
  saveAnimation(dense, out, /*strict=*/false);
  std::fprintf(stderr, "%s: %d frames at %s fps\n", out.c_str(), dense.frameCount(),
               formatNumber(fps).c_str());
  return kExitOk;
}

int convert(const std::string& in, const std::string& out, bool strict) {
  if (isProjectPath(in) && isProjectPath(out))
    saveProject(loadProject(in), out);  // keeps the keys rather than baking them
  else
    saveAnimation(loadAnimation(in), out, strict);
  return kExitOk;
}

// One parser per command, so each command's --help lists only what it takes.
struct Command {
  const char* name;
  const char* description;
  const char* positional;  // "FILE" or "IN"; nullptr: the command takes none
  bool takesOutput;
  std::function<int(QCommandLineParser&, const std::string&, const std::string&)> run;
  std::function<void(QCommandLineParser&)> addOptions = [](QCommandLineParser&) {};
};

int usageError(const QString& message) {
  std::fprintf(stderr, "lacrima-fap: %s\n\nusage: lacrima-fap COMMAND ...\n%s", qPrintable(message),
               kCommandSummary);
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("lacrima-fap");
  QCoreApplication::setApplicationVersion(LACRIMA_VERSION);

  const QCommandLineOption outputOption({"o", "output"}, "Write the result to <file>.", "file");
  const QCommandLineOption fpsOption("fps", "Output frame rate (default 22).", "rate", "22");
  const QCommandLineOption smoothOption("smooth", "Monotone cubic instead of linear.");
  const QCommandLineOption strictOption("strict", "Write the 68 standard FAPs only.");
  const QCommandLineOption moodOption(
      "mood", "Constant moods: sadness, anger, joy, shame, each 0..1 (sadness=0.8,anger=0.2).",
      "moods");
  const QCommandLineOption scriptOption(
      "script", "Moods over time: a JSON file of keys (docs/mood.md#mood-scripts).", "file");
  const QCommandLineOption secondsOption("seconds", "Length of the take (0 to 86400).", "s");
  const QCommandLineOption seedOption("seed", "The take's seed (default 1).", "n", "1");
  const QCommandLineOption rateOption("rate", "Frames per second (default 22).", "fps", "22");
  // generate's options read and checked; usage errors exit 2 before anything is generated.
  const auto runGenerate = [&](QCommandLineParser& p, const std::string& out) {
    GenerateRequest request;
    request.output = out;
    if (p.isSet(moodOption) == p.isSet(scriptOption))
      return usageError("generate takes either --mood or --script");
    if (p.isSet(moodOption)) {
      try {
        request.moods = parseMoodLevels(p.value(moodOption).toStdString());
      } catch (const std::invalid_argument& error) {
        return usageError(QString("--mood: ") + error.what());
      }
    } else {
      request.script = p.value(scriptOption).toStdString();
    }
    if (!p.isSet(secondsOption)) return usageError("generate needs --seconds S");
    std::string error;
    const auto seconds = readNumberOption(
        "--seconds", "seconds", p.value(secondsOption).toStdString(), 0, kMaxMoodSeconds, error);
    const auto rate = readNumberOption("--rate", "frames per second",
                                       p.value(rateOption).toStdString(), 0.001, 1000, error);
    if (!seconds || !rate) return usageError(QString::fromStdString(error));
    bool ok = false;
    request.seed = p.value(seedOption).toULongLong(&ok);
    if (!ok)
      return usageError("--seed: expected a whole number from 0 to 18446744073709551615, got '" +
                        p.value(seedOption) + "'");
    request.seconds = *seconds;
    request.fps = *rate;
    request.strict = p.isSet(strictOption);
    std::fprintf(stderr, "%s\n", generate(request).c_str());
    return kExitOk;
  };

  const Command commands[] = {
      {"check", "Validate FILE and print one summary line.", "FILE", false,
       [](QCommandLineParser&, const std::string& file, const std::string&) {
         return check(file);
       }},
      {"dump", "Print FILE's decoded frames as CSV.", "FILE", false,
       [](QCommandLineParser&, const std::string& file, const std::string&) { return dump(file); }},
      {"interpolate", "Treat IN's frames as keys and resample them at --fps into OUT.", "IN", true,
       [&](QCommandLineParser& p, const std::string& in, const std::string& out) {
         bool ok = false;
         const double fps = p.value(fpsOption).toDouble(&ok);
         if (!ok || !(fps > 0 && fps <= 1000))
           return usageError("--fps expects a frame rate in (0, 1000], got '" + p.value(fpsOption) +
                             "'");
         return interpolate(in, out, fps, p.isSet(smoothOption));
       },
       [&](QCommandLineParser& p) {
         p.addOptions({fpsOption, smoothOption});
       }},
      {"convert", "Convert between .fap and a project, .lacrima or .json (by OUT's extension).",
       "IN", true,
       [&](QCommandLineParser& p, const std::string& in, const std::string& out) {
         return convert(in, out, p.isSet(strictOption));
       },
       [&](QCommandLineParser& p) { p.addOption(strictOption); }},
      {"generate",
       "Write a take of the crying generator (docs/mood.md) to OUT: moods held constant "
       "(--mood) or following a script (--script), for --seconds, from --seed.",
       nullptr, true,
       [&](QCommandLineParser& p, const std::string&, const std::string& out) {
         return runGenerate(p, out);
       },
       [&](QCommandLineParser& p) {
         p.addOptions(
             {moodOption, scriptOption, secondsOption, seedOption, rateOption, strictOption});
       }},
  };

  const QStringList args = QCoreApplication::arguments();
  if (args.size() < 2) return usageError("no command given");
  const QString name = args.at(1);
  if (name == "--help" || name == "-h" || name == "help") {
    std::printf("usage: lacrima-fap COMMAND ...   (lacrima-fap COMMAND --help for details)\n\n%s",
                kCommandSummary);
    return kExitOk;
  }
  if (name == "--version" || name == "-v") {
    std::printf("lacrima-fap %s\n", LACRIMA_VERSION);
    return kExitOk;
  }

  for (const Command& command : commands) {
    if (name != command.name) continue;
    QCommandLineParser parser;
    parser.setApplicationDescription(command.description);
    parser.addHelpOption();
    if (command.positional)
      parser.addPositionalArgument(command.positional,
                                   "Input .fap file or project (.lacrima or .json).");
    if (command.takesOutput) parser.addOption(outputOption);
    command.addOptions(parser);
    QStringList commandArgs = args.mid(1);
    commandArgs[0] = QString("lacrima-fap ") + command.name;
    if (!parser.parse(commandArgs)) return usageError(parser.errorText());
    if (parser.isSet("help")) {
      std::printf("%s", qPrintable(parser.helpText()));
      return kExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (!command.positional && !positional.isEmpty())
      return usageError(
          QString("%1 takes no file but -o OUT, got '%2'").arg(command.name, positional.first()));
    if (command.positional && positional.size() != 1)
      return usageError(QString("%1 takes exactly one %2").arg(command.name, command.positional));
    if (command.takesOutput && !parser.isSet(outputOption))
      return usageError(QString("%1 needs -o OUT").arg(command.name));
    try {
      const std::string output =
          command.takesOutput ? parser.value(outputOption).toStdString() : std::string();
      return command.run(parser, positional.value(0).toStdString(), output);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s\n", error.what());
      return kExitBadInput;
    }
  }
  return usageError("unknown command '" + name + "'");
}
