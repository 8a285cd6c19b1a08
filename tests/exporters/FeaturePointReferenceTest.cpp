// The reference picture of a feature point (FeaturePointReference.h) on the default head
// (skipped when it is not fetched): framed on the point's region, the point drawn in the
// highlight colour where it is, hidden points flagged, unknown ids give no picture, and every
// point the head has comes with a description.
#include "../support/MissingData.h"

#include <lacrima/common/FdpTable.h>
#include <lacrima/exporters/FeaturePointReference.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::exporters;

namespace {

bool near(QColor a, QColor b, int tolerance = 4) {
  return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
         std::abs(a.blue() - b.blue()) <= tolerance;
}

}  // namespace

class FeaturePointReferenceTest : public QObject {
  Q_OBJECT

  std::unique_ptr<ReferenceHead> head_;

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    head_ = std::make_unique<ReferenceHead>(defaultReferenceHead());
  }

  void everyPointOfTheHeadHasADescription() {
    QVERIFY(head_->points.size() > 40);
    for (const auto& [id, position] : head_->points) {
      QVERIFY2(!fdpDescription(id).empty(), id.c_str());
      QVERIFY(position.allFinite());
    }
  }

  void regionsPickTheirFraming() {
    QCOMPARE(referenceView("3.7"), ReferenceView::Eyes);
    QCOMPARE(referenceView("4.3"), ReferenceView::Eyes);
    QCOMPARE(referenceView("8.3"), ReferenceView::Mouth);
    QCOMPARE(referenceView("2.2"), ReferenceView::Mouth);
    QCOMPARE(referenceView("6.1"), ReferenceView::Mouth);
    QCOMPARE(referenceView("9.10"), ReferenceView::Mouth);
    QCOMPARE(referenceView("2.10"), ReferenceView::Face);
    QCOMPARE(referenceView("9.3"), ReferenceView::Face);
    QCOMPARE(referenceView("10.1"), ReferenceView::Side);
    QCOMPARE(referenceView("10.2"), ReferenceView::Face);  // the right ear: seen from the front
    QCOMPARE(referenceView("11.6"), ReferenceView::Side);
  }

  void theHighlightedPointShowsInItsColour_data() {
    QTest::addColumn<QString>("id");
    for (const char* id : {"9.3", "3.7", "3.12", "3.11", "8.3", "8.4", "2.10", "4.3", "10.1"})
      QTest::newRow(id) << QString(id);
  }
  void theHighlightedPointShowsInItsColour() {
    QFETCH(QString, id);
    ReferenceStyle style;
    QElapsedTimer timer;
    timer.start();
    const ReferencePicture picture = renderFeaturePointReference(*head_, id.toStdString(), style);
    qInfo("%s: %lld ms", qPrintable(id), timer.elapsed());
    QCOMPARE(picture.image.size(), QSize(style.size, style.size));
    QVERIFY2(!picture.hidden, "a point on the visible surface was taken for hidden");
    QVERIFY(QRectF(0, 0, style.size, style.size).contains(picture.pixel));
    const QPoint at = picture.pixel.toPoint();
    QVERIFY2(near(picture.image.pixelColor(at), style.highlight),
             qPrintable(picture.image.pixelColor(at).name()));
    // A picture of the head, not of the backdrop: most pixels differ from its colour.
    int head = 0;
    for (int y = 0; y < style.size; y += 6)
      for (int x = 0; x < style.size; x += 6)
        head += !near(picture.image.pixelColor(x, y), QColor(235, 240, 245), 2);
    QVERIFY(head > 0.2 * (style.size / 6) * (style.size / 6));
  }

  void closeUpsAreCloserAndMoveTheHighlight() {
    const ReferencePicture face = renderFeaturePointReference(*head_, "9.3");
    const ReferencePicture eye = renderFeaturePointReference(*head_, "3.7");
    const ReferencePicture mouth = renderFeaturePointReference(*head_, "8.3");
    QVERIFY(eye.panel.halfSize < 0.5 * face.panel.halfSize);
    QVERIFY(mouth.panel.halfSize < 0.5 * face.panel.halfSize);
    // The face's left (+x) on the image's right, the other eye corner on the other side.
    const ReferencePicture otherEye = renderFeaturePointReference(*head_, "3.12");
    QVERIFY(eye.pixel.x() > otherEye.pixel.x() + 50);
    QCOMPARE(otherEye.panel.centre, eye.panel.centre);
    // The same framing, a different highlight: the pictures differ at both points.
    QVERIFY(eye.image.pixelColor(otherEye.pixel.toPoint()) !=
            otherEye.image.pixelColor(otherEye.pixel.toPoint()));
  }

  void aHiddenPointIsFlagged() {
    // The tongue's tip is behind the closed lips of the neutral head.
    if (!head_->points.count("6.1")) QSKIP("the default head has no 6.1");
    const ReferencePicture tongue = renderFeaturePointReference(*head_, "6.1");
    QVERIFY(!tongue.image.isNull());
    QVERIFY(tongue.hidden);
    QVERIFY(!near(tongue.image.pixelColor(tongue.pixel.toPoint()), ReferenceStyle().highlight));
  }

  void unknownPointsGiveNoPicture() {
    QVERIFY(renderFeaturePointReference(*head_, "11.5").image.isNull());  // not on this head
    QVERIFY(renderFeaturePointReference(*head_, "nonsense").image.isNull());
    QVERIFY(renderFeaturePointReference(*head_, "").image.isNull());
    ReferenceStyle tiny;
    tiny.size = 0;
    QVERIFY(renderFeaturePointReference(*head_, "9.3", tiny).image.isNull());
  }
};

QTEST_MAIN(FeaturePointReferenceTest)
#include "FeaturePointReferenceTest.moc"
