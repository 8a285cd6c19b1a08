// The JSON reading toolkit: every getter's error names the file, line, column and JSON path of
// the value; syntax errors, size bounds and file limits; the path locator.
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonPathLocator.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>
#include <string>

using namespace lacrima;

namespace {

// Line 3 holds a value of every kind; "deep" is an array whose third element is wrong.
const std::string kDocument =
    "{\n"
    "  \"kinds\": {\n"
    "    \"text\": \"wide\", \"number\": 2.5, \"flag\": true, \"none\": null, \"list\": [1, 2, 3]\n"
    "  },\n"
    "  \"deep\": [\n"
    "    {\"keys\": [0, 1]},\n"
    "    {\"keys\": [2,\n"
    "              \"three\"]}\n"
    "  ]\n"
    "}\n";

// The what() of the FileError `read` throws on kDocument (named "t.json"), or "" if none.
std::string errorOf(const std::function<void(const JsonValue&)>& read) {
  try {
    read(JsonInput::parse(kDocument, "t.json").root());
  } catch (const FileError& error) {
    return error.what();
  }
  return {};
}

std::string parseErrorOf(const std::string& text) {
  try {
    JsonInput::parse(text, "t.json").root();
  } catch (const FileError& error) {
    return error.what();
  }
  return {};
}

std::string loadErrorOf(const QString& path, qint64 maxBytes) {
  try {
    JsonInput::load(path.toStdString(), {"test file", maxBytes});
  } catch (const FileError& error) {
    return error.what();
  }
  return {};
}

}  // namespace

class JsonInputTest : public QObject {
  Q_OBJECT

 private slots:
  void gettersReadWhatTheyExpect() {
    const JsonValue root = JsonInput::parse(kDocument, "t.json").root();
    const JsonValue kinds = root["kinds"];
    QCOMPARE(kinds["text"].string(), std::string("wide"));
    QCOMPARE(kinds["number"].number(), 2.5);
    QCOMPARE(kinds["number"].number(0.0, 2.5), 2.5);
    QCOMPARE(kinds["list"].integers(1, 3, 3), (std::vector<int>{1, 2, 3}));
    QCOMPARE(kinds["list"].numbers(3), (std::vector<double>{1, 2, 3}));
    QCOMPARE(kinds["list"].element(1).integer(0, 9), 2);
    QVERIFY(kinds["flag"].boolean());
    QVERIFY(kinds["none"].isNull());
    QCOMPARE(kinds["text"].oneOf({"narrow", "wide"}), std::size_t{1});
    QVERIFY(kinds.has("text") && !kinds.has("colour") && !kinds["text"].has("text"));
    QVERIFY(kinds["colour"].missing());
    QCOMPARE(kinds.size(), std::size_t{5});
    std::vector<std::string> names;
    for (const JsonValue& member : kinds.members()) names.push_back(member.name());
    QCOMPARE(names, (std::vector<std::string>{"flag", "list", "none", "number", "text"}));
    QCOMPARE(root["deep"].array(2)[1]["keys"].path().toString(), std::string("deep[1].keys"));
  }

  void everyGetterNamesFileLineColumnAndPath() {
    // Each located at the member's key on line 3, or, for a missing member, at its object.
    const std::vector<std::pair<std::function<void(const JsonValue&)>, std::string>> cases{
        {[](const JsonValue& r) { r["kinds"]["text"].number(); },
         "t.json:3:5: kinds.text: expected a finite number, got \"wide\""},
        {[](const JsonValue& r) { r["kinds"]["number"].number(0, 1); },
         "t.json:3:21: kinds.number: expected a number in [0, 1], got 2.5"},
        {[](const JsonValue& r) { r["kinds"]["number"].integer(0, 10); },
         "t.json:3:21: kinds.number: expected a whole number in [0, 10], got 2.5"},
        {[](const JsonValue& r) { r["kinds"]["flag"].string(); },
         "t.json:3:36: kinds.flag: expected a string, got true"},
        {[](const JsonValue& r) { r["kinds"]["none"].boolean(); },
         "t.json:3:50: kinds.none: expected true or false, got null"},
        {[](const JsonValue& r) { r["kinds"]["list"].object(); },
         "t.json:3:64: kinds.list: expected an object, got an array of 3 values"},
        {[](const JsonValue& r) { r["kinds"]["text"]["x"]; },
         "t.json:3:5: kinds.text: expected an object, got \"wide\""},
        {[](const JsonValue& r) { r["kinds"].array(9); },
         "t.json:2:3: kinds: expected an array, got an object"},
        {[](const JsonValue& r) { r["kinds"]["list"].array(2); },
         "t.json:3:64: kinds.list: expected an array of at most 2 values, got an array of 3 "
         "values"},
        {[](const JsonValue& r) {
           r["kinds"]["text"].oneOf({"linear", "smooth", "step"});
         },
         "t.json:3:5: kinds.text: expected \"linear\", \"smooth\" or \"step\", got \"wide\""},
        {[](const JsonValue& r) { r["kinds"]["colour"].number(); },
         "t.json:2:3: kinds: missing field \"colour\""},
        {[](const JsonValue& r) { r["kinds"].required("colour"); },
         "t.json:2:3: kinds: missing field \"colour\""},
        {[](const JsonValue& r) { r.rejectUnknownMembers({"kinds"}); },
         "t.json:5:3: deep: unknown field; expected one of kinds"},
        {[](const JsonValue& r) { r["kinds"]["colour"].fail("is needed for the skin"); },
         "t.json:2:3: kinds.colour: is needed for the skin"},
    };
    for (const auto& [read, expected] : cases) QCOMPARE(errorOf(read), expected);
  }

  void aBadValueDeepInAnArrayIsLocated() {
    const auto numbers = [](const JsonValue& r) {
      for (const JsonValue& entry : r["deep"].array(9)) entry["keys"].numbers(9);
    };
    QCOMPARE(errorOf(numbers),
             std::string("t.json:8:15: deep[1].keys[1]: expected a finite number, got \"three\""));
    const auto integers = [](const JsonValue& r) {
      for (const JsonValue& entry : r["deep"].array(9)) entry["keys"].integers(1, 9, 9);
    };
    QCOMPARE(errorOf(integers),
             std::string("t.json:6:15: deep[0].keys[0]: expected a whole number in [1, 9], got 0"));
  }

  void syntaxErrorsAndTheTopLevelAreLocated() {
    const std::string trailingComma = parseErrorOf("{\n  \"a\": 1,\n}");
    QVERIFY2(trailingComma.starts_with("t.json:3:1: invalid JSON: "), trailingComma.c_str());
    QCOMPARE(parseErrorOf("  [1]"),
             std::string(
                 "t.json:1:3: expected a JSON object at the top level, got an array of 1 value"));
    // Qt refuses numbers a double cannot hold, so every number a reader sees is finite.
    const std::string huge = parseErrorOf("{\"a\": 1e999}");
    QVERIFY2(huge.starts_with("t.json:1:") && huge.find("invalid JSON") != std::string::npos,
             huge.c_str());
  }

  void longTextIsShortenedInMessages() {
    const std::string text(100, 'x');
    const JsonValue value = JsonInput::parse("{\"a\": \"" + text + "\"}", "t.json").root()["a"];
    QCOMPARE(value.describe(), '"' + text.substr(0, 60) + "...\"");
  }

  void loadNamesTheProblemWithTheFile() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString absent = folder.filePath("absent.json");
    QVERIFY(loadErrorOf(absent, 1 << 20).starts_with(absent.toStdString() + ": cannot open: "));
    QCOMPARE(loadErrorOf(folder.path(), 1 << 20),
             folder.path().toStdString() + ": is a folder, not a test file");

    const QString large = folder.filePath("large.json");
    QFile file(large);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QVERIFY(file.resize((qint64{1} << 20) + 1));  // sparse: costs no disk
    file.close();
    QCOMPARE(loadErrorOf(large, 1 << 20),
             large.toStdString() + ": is 1 MiB or more; test files are limited to 1 MiB");
    // Under a limit below 1 MiB the sizes are in bytes (they printed as "0 MiB").
    QCOMPARE(loadErrorOf(large, 1000),
             large.toStdString() + ": is 1 MiB or more; test files are limited to 1000 bytes");
    QFile small(folder.filePath("small.json"));
    QVERIFY(small.open(QIODevice::WriteOnly));
    QVERIFY(small.resize(2000));
    small.close();
    QCOMPARE(loadErrorOf(small.fileName(), 1000),
             small.fileName().toStdString() +
                 ": is 2000 bytes or more; test files are limited to 1000 bytes");

    const QString broken = folder.filePath("broken.json");
    QFile brokenFile(broken);
    QVERIFY(brokenFile.open(QIODevice::WriteOnly));
    brokenFile.write("{\"a\": [1,\n 2,,]}");
    brokenFile.close();
    const std::string syntax = loadErrorOf(broken, 1 << 20);
    QVERIFY2(syntax.starts_with(broken.toStdString() + ":2:4: invalid JSON: "), syntax.c_str());
  }

  // Memory follows the file, not the limit: a small file loads under a limit of a tebibyte
  // (reading "up to the limit" in one call once allocated the whole limit first).
  void loadAllocatesForTheFileNotTheLimit() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString small = folder.filePath("small.json");
    QFile file(small);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"a\": 1}");
    file.close();
    const JsonInput input = JsonInput::load(small.toStdString(), {"test file", qint64{1} << 40});
    QCOMPARE(input.root()["a"].number(), 1.0);
  }

  void jsonPathLocatorFindsMembersAndElements() {
    const std::string json =
        "{\n \"a\": [1, {\"b\": 2},\n  {\"c\": {\"d\\\"x\": 3}}],\n \"e\": 4, \"a\": []\n}";
    const JsonPath a = JsonPath() / "a";
    QCOMPARE(locateJsonPath(json, JsonPath() / "e", "f").toString(), std::string("f:4:2"));
    // Duplicate keys resolve to the last one, as QJsonDocument does.
    QCOMPARE(locateJsonPath(json, a, "f").toString(), std::string("f:4:10"));
    QCOMPARE(locateJsonPath(json, JsonPath() / "zz", "f").toString(), std::string("f"));
    QCOMPARE((a / 2 / "c" / "d\"x").toString(), std::string("a[2].c.\"d\"x\""));
  }

  void jsonPathLocatorDecodesEscapedKeys() {
    const std::string json = "{\"x\": 0,\n \"caf\\u00e9\": {\"\\ud83d\\ude00\\n\": [0, 1]}}";
    const JsonPath path = JsonPath() / "caf\xc3\xa9" / "\xf0\x9f\x98\x80\n" / 1;
    QCOMPARE(locateJsonPath(json, path, "f").toString(), std::string("f:2:38"));
    // The key as QJsonDocument decodes it is the one a reader's path holds.
    const JsonValue root = JsonInput::parse(json, "f").root();
    QCOMPARE(root.members()[0].name(), std::string("caf\xc3\xa9"));
  }

  void pathsShareTheirParents() {
    const JsonPath keys = JsonPath() / "keys";
    const JsonPath time = keys / 3 / "time";
    QCOMPARE(time.toString(), std::string("keys[3].time"));
    QCOMPARE(time.parent().toString(), std::string("keys[3]"));
    QCOMPARE(keys.toString(), std::string("keys"));  // extending a path leaves it as it was
    QVERIFY(JsonPath().parent().empty());
    QCOMPARE(time.steps().size(), std::size_t{3});
    QCOMPARE(std::get<std::string>(time.last()), std::string("time"));
  }
};

QTEST_GUILESS_MAIN(JsonInputTest)
#include "JsonInputTest.moc"
