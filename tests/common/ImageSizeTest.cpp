// parseImageSize: the one reader of "WxH" behind every --size option.
#include <lacrima/common/ImageSize.h>

#include <QtTest>

using namespace lacrima;

class ImageSizeTest : public QObject {
  Q_OBJECT
 private slots:
  void readsWidthAndHeight() {
    const ParsedImageSize parsed = parseImageSize("1280x720");
    QVERIFY(parsed.error.empty());
    QCOMPARE(parsed.size, QSize(1280, 720));
    QCOMPARE(parseImageSize("640X480").size, QSize(640, 480));
  }

  void acceptsTheBoundsThemselves() {
    QCOMPARE(parseImageSize("16x8192").size, QSize(kMinImageSide, kMaxImageSide));
  }

  void rejectsWhatIsNotASize_data() {
    QTest::addColumn<QString>("text");
    for (const char* text :
         {"", "big", "1280", "1280x", "x720", "1280x720x2", " 1280x720", "1280 x 720", "12.5x720",
          "-1280x720", "15x720", "1280x8193", "99999999999x720"})
      QTest::newRow(text) << QString::fromLatin1(text);
  }
  void rejectsWhatIsNotASize() {
    QFETCH(QString, text);
    const ParsedImageSize parsed = parseImageSize(text.toStdString());
    QVERIFY(!parsed.size.isValid());
    // The message says what was expected and echoes what was given.
    QVERIFY(QString::fromStdString(parsed.error).contains("WIDTHxHEIGHT"));
    QVERIFY(QString::fromStdString(parsed.error).contains("16 to 8192"));
    QVERIFY(QString::fromStdString(parsed.error).contains("'" + text + "'"));
  }

  void boundsTheRenderTargetToo() {
    QVERIFY(isImageSizeInBounds(QSize(kMinImageSide, kMaxImageSide)));
    QVERIFY(!isImageSizeInBounds(QSize(0, 10)));
    QVERIFY(!isImageSizeInBounds(QSize(kMaxImageSide + 1, 100)));
  }
};

QTEST_GUILESS_MAIN(ImageSizeTest)
#include "ImageSizeTest.moc"
