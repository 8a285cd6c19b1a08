// JsonWriter: field order kept, exact numbers, escaping, both layouts.
#include <lacrima/common/JsonWriter.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <cmath>
#include <cstdlib>
#include <limits>

using namespace lacrima;

class JsonWriterTest : public QObject {
  Q_OBJECT

 private slots:
  void compactKeepsOrder() {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("zeta", 1);
    json.field("alpha", "a\"b\\c\n");
    json.key("nested");
    json.beginObject();
    json.field("ok", true);
    json.endObject();
    json.key("row");
    const double row[] = {0.5, -2, 1e300};
    json.numberRow(row);
    json.key("empty");
    json.beginArray();
    json.endArray();
    json.endObject();
    QCOMPARE(QString::fromStdString(std::move(json).finish()),
             QString("{\"zeta\": 1, \"alpha\": \"a\\\"b\\\\c\\n\", \"nested\": {\"ok\": true}, "
                     "\"row\": [0.5, -2, 1e+300], \"empty\": []}\n"));
  }

  void indentedIsValidJson() {
    JsonWriter json;
    json.beginObject();
    json.field("name", "tab\there \x01");
    json.field("pi", 3.141592653589793);
    json.endObject();
    const std::string text = std::move(json).finish();
    QVERIFY(text.find("\n  \"pi\": 3.141592653589793") != std::string::npos);
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(doc.object().value("name").toString(), QString("tab\there \x01"));
    QCOMPARE(doc.object().value("pi").toDouble(), 3.141592653589793);
  }

  void numbersAreShortestAndExact() {
    QCOMPARE(formatJsonNumber(0.1), std::string("0.1"));
    QCOMPARE(formatJsonNumber(20000000), std::string("20000000"));
    QCOMPARE(formatJsonNumber(-0.004), std::string("-0.004"));
    for (double v : {1.0 / 3, 6.02214076e23, 5e-324, -1e-7})
      QCOMPARE(std::strtod(formatJsonNumber(v).c_str(), nullptr), v);
  }

  void nonFiniteBecomesNull() {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginArray();
    json.number(std::nan(""));
    json.number(std::numeric_limits<double>::infinity());
    json.endArray();
    QCOMPARE(std::move(json).finish(), std::string("[null, null]\n"));
  }
};

QTEST_GUILESS_MAIN(JsonWriterTest)
#include "JsonWriterTest.moc"
