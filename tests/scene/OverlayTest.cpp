// The engine-free parts of the scene on the real default head (skipped when it is not fetched):
// where the overlays apply (masks painted in uv space), the overlay layers made from the head's
// textures, the skin's relief and the tangent frames it is shaded in, the skin's horizons (its
// shadows), the static occlusion, the
// orbit camera's framing and mouse mapping, and the named cameras of --render --view.
#include "../support/MissingData.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/scene/CameraPreset.h>
#include <lacrima/scene/HeadOcclusion.h>
#include <lacrima/scene/HeadTangents.h>
#include <lacrima/scene/OrbitView.h>
#include <lacrima/scene/OverlayMasks.h>
#include <lacrima/scene/OverlayTextures.h>
#include <lacrima/scene/SkinDetail.h>
#include <lacrima/scene/SkinHorizons.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

using namespace lacrima;
using namespace lacrima::scene;

class OverlayTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadMesh> head_;
  EyeSphere left_, right_;

  // The skin vertex nearest to `point`.
  int skinVertexNear(const Eigen::Vector3f& point) const {
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    int best = -1;
    float bestDistance = 1e30f;
    for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v) {
      const float d = (head_->positions.col(v) - point).squaredNorm();
      if (d < bestDistance) {
        bestDistance = d;
        best = v;
      }
    }
    return best;
  }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
    const auto l = eyeSphere(*head_, "eye_l"), r = eyeSphere(*head_, "eye_r");
    QVERIFY(l && r);
    left_ = *l;
    right_ = *r;
    QVERIFY(left_.centre.x() > 0 && right_.centre.x() < 0);
    QVERIFY(left_.radius > 0.1f && left_.radius < 0.2f);  // an eyeball is about 12 mm across
  }

  void periocularWeightsSurroundTheEyesOnly() {
    const OverlayVertexWeights w = overlayVertexWeights(*head_);
    QCOMPARE(w.periocular.size(), std::size_t(head_->vertexCount()));
    for (const EyeSphere& eye : {left_, right_}) {
      const float r = eye.radius;
      // Lower lid and outer corner: full weight.
      QCOMPARE(
          w.periocular[std::size_t(skinVertexNear(eye.centre + Eigen::Vector3f(0, -1.2f * r, r)))],
          1.0f);
      // Top of the head, chin, back of the head: none.
      QCOMPARE(w.periocular[std::size_t(skinVertexNear(eye.centre + Eigen::Vector3f(0, 7 * r, 0)))],
               0.0f);
      QCOMPARE(
          w.periocular[std::size_t(skinVertexNear(eye.centre + Eigen::Vector3f(0, -8 * r, 0)))],
          0.0f);
      QCOMPARE(
          w.periocular[std::size_t(skinVertexNear(eye.centre + Eigen::Vector3f(0, 0, -8 * r)))],
          0.0f);
    }
    // Only skin carries weights.
    const HeadSubmesh* eye = head_->findSubmesh("eye_l");
    for (int v = eye->firstVertex; v < eye->firstVertex + eye->vertexCount; ++v)
      QCOMPARE(w.periocular[std::size_t(v)], 0.0f);
    for (float x : w.periocular) QVERIFY(x >= 0 && x <= 1);
  }

  void cheekWeightsSitBelowTheEyes() {
    const OverlayVertexWeights w = overlayVertexWeights(*head_);
    for (const EyeSphere& eye : {left_, right_}) {
      const float outwards = eye.centre.x() > 0 ? 1.0f : -1.0f;
      const int cheek =
          skinVertexNear(eye.centre + Eigen::Vector3f(0.3f * eye.radius * outwards,
                                                      -2.4f * eye.radius, eye.radius));
      QVERIFY2(w.cheek[std::size_t(cheek)] > 0.8f, "no blush on the cheekbone");
      QCOMPARE(w.cheek[std::size_t(
                   skinVertexNear(eye.centre + Eigen::Vector3f(0, 5 * eye.radius, eye.radius)))],
               0.0f);
    }
  }

  void maskIsPaintedInUvSpace() {
    const OverlayVertexWeights w = overlayVertexWeights(*head_);
    const QImage mask = paintOverlayMask(*head_, w, 256);
    QCOMPARE(mask.size(), QSize(256, 256));
    QCOMPARE(mask.format(), QImage::Format_RGBA8888);
    // At the uv of a vertex the mask holds (about) that vertex's weight.
    auto at = [&](int v) {
      const Eigen::Vector2f uv = head_->uvs.col(v) * 256.0f;
      return QColor(mask.pixel(std::clamp(int(uv.x()), 0, 255), std::clamp(int(uv.y()), 0, 255)));
    };
    const int lid =
        skinVertexNear(left_.centre + Eigen::Vector3f(0, -1.2f * left_.radius, left_.radius));
    const int top = skinVertexNear(left_.centre + Eigen::Vector3f(0, 7 * left_.radius, 0));
    QVERIFY2(at(lid).red() > 200, "the lower lid is not in the redness mask");
    QCOMPARE(at(top).red(), 0);
    // Some texels of each kind, most texels untouched (the body's uv area, the scalp).
    int red = 0, green = 0;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x) {
        const QColor c = mask.pixelColor(x, y);
        red += c.red() > 128;
        green += c.green() > 128;
      }
    QVERIFY(red > 50 && red < 256 * 256 / 10);
    QVERIFY(green > 20 && green < 256 * 256 / 10);
  }

  void headsWithoutEyesGetNoMask() {
    HeadMesh bare = *head_;
    bare.submeshes.erase(
        std::remove_if(bare.submeshes.begin(), bare.submeshes.end(),
                       [](const HeadSubmesh& s) { return s.name.rfind("eye_", 0) == 0; }),
        bare.submeshes.end());
    const OverlayVertexWeights w = overlayVertexWeights(bare);
    for (float x : w.periocular) QCOMPARE(x, 0.0f);
    const QImage mask = paintOverlayMask(bare, w, 64);
    QCOMPARE(mask.pixelColor(32, 32), QColor(0, 0, 0));
  }

  void overlayLayersAreRedderAndWetter() {
    QImage skin(64, 64, QImage::Format_RGBA8888);
    skin.fill(QColor(220, 180, 160));
    const QImage irritated = makeIrritatedSkin(skin);
    QCOMPARE(irritated.size(), skin.size());
    for (int y = 0; y < 64; y += 7)
      for (int x = 0; x < 64; x += 7) {
        const QColor c = irritated.pixelColor(x, y);
        QVERIFY(c.red() < 220 && c.green() < 180);                    // darker
        QVERIFY(double(c.red()) / c.green() > 220.0 / 180.0 * 1.15);  // redder
      }
    QImage eye(64, 64, QImage::Format_RGBA8888);
    eye.fill(QColor(235, 232, 228));  // sclera
    const QImage wet = makeWetEye(eye);
    double redShift = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const QColor c = wet.pixelColor(x, y);
        redShift += c.red() - c.green();
      }
    QVERIFY2(redShift / (64 * 64) > 15, "the sclera did not turn pink");
    QCOMPARE(makeIrritatedSkin(QImage()).size(), QSize(1, 1));  // a head without a texture
  }

  // The bloodshot layer at full redness, blended as eye.frag does (mix by its alpha), on the
  // default head's own eye texture: texels of the iris (eyeball vertices within 20 degrees of
  // the gaze, the cornea's direction; the iris reaches about 29) are unchanged bit for bit,
  // texels of the sclera (45 to 75 degrees off the gaze) turn pink.
  void bloodshotLayerReddensScleraNotIris() {
    const HeadSubmesh* eye = head_->findSubmesh("eye_l");
    const HeadSubmesh* cornea = head_->findSubmesh("cornea_l");
    QVERIFY(eye && cornea && eye->material >= 0);
    const QImage diffuse =
        QImage(QString::fromStdString(head_->materials[std::size_t(eye->material)].diffuseTexture))
            .convertToFormat(QImage::Format_RGBA8888);
    QVERIFY(!diffuse.isNull());
    const QImage layer = makeWetEye(diffuse);
    QCOMPARE(layer.size(), diffuse.size());
    const Eigen::Vector3f gaze =
        (head_->positions.middleCols(cornea->firstVertex, cornea->vertexCount).rowwise().mean() -
         left_.centre)
            .normalized();
    int iris = 0, sclera = 0, pinker = 0;
    for (int v = eye->firstVertex; v < eye->firstVertex + eye->vertexCount; ++v) {
      const float degrees =
          std::acos(std::clamp((head_->positions.col(v) - left_.centre).normalized().dot(gaze),
                               -1.0f, 1.0f)) *
          180 / std::numbers::pi_v<float>;
      const int x =
          std::clamp(int(head_->uvs(0, v) * float(diffuse.width())), 0, diffuse.width() - 1);
      const int y =
          std::clamp(int(head_->uvs(1, v) * float(diffuse.height())), 0, diffuse.height() - 1);
      const QColor before = diffuse.pixelColor(x, y), over = layer.pixelColor(x, y);
      const double a = over.alphaF();
      const double red = before.redF() * (1 - a) + over.redF() * a;
      const double green = before.greenF() * (1 - a) + over.greenF() * a;
      if (degrees < 20) {
        ++iris;
        QCOMPARE(over.alpha(), 0);
        QCOMPARE(over.rgb(), before.rgb());
      } else if (degrees > 45 && degrees < 75) {
        ++sclera;
        pinker += red - green > before.redF() - before.greenF() + 0.05;
      }
    }
    QVERIFY(iris > 30 && sclera > 30);
    QVERIFY2(pinker > sclera * 3 / 4, "the sclera did not turn pink");
  }

  // The skin's relief: a normal map that tiles (the step across the wrap is no bigger than
  // steps inside), averages to a flat normal (it neither darkens nor tilts the light overall),
  // and has fine structure; one tile spans about 1.5 cm of the default head's skin; it shows
  // only close up.
  void skinReliefTilesAveragesFlatAndIsFine() {
    const QImage relief = makeSkinDetailNormals(128);
    QCOMPARE(relief.size(), QSize(128, 128));
    QCOMPARE(relief.format(), QImage::Format_RGBA8888);
    auto normal = [&](int x, int y) {
      const QColor c = relief.pixelColor(x, y);
      return Eigen::Vector3d(c.redF() * 2 - 1, c.greenF() * 2 - 1, c.blueF() * 2 - 1);
    };
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double tilted = 0, insideStep = 0, wrapStep = 0;
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x) {
        const Eigen::Vector3d n = normal(x, y);
        QVERIFY(std::abs(n.norm() - 1) < 0.02);
        mean += n;
        tilted += n.z() < 0.985;  // more than 10 degrees
        if (x < 127) insideStep = std::max(insideStep, (normal(x + 1, y) - n).norm());
      }
    for (int y = 0; y < 128; ++y)
      wrapStep = std::max(wrapStep, (normal(0, y) - normal(127, y)).norm());
    for (int x = 0; x < 128; ++x)
      wrapStep = std::max(wrapStep, (normal(x, 0) - normal(x, 127)).norm());
    mean /= 128.0 * 128.0;
    QVERIFY2(std::abs(mean.x()) < 0.01 && std::abs(mean.y()) < 0.01, "the relief tilts the light");
    QVERIFY2(tilted > 128 * 128 / 20, "no pores or lines");
    QVERIFY2(wrapStep <= insideStep, "the relief does not tile");

    const float tiling = skinDetailTiling(*head_);
    QVERIFY2(tiling > 45 && tiling < 90, qPrintable(QString::number(tiling)));
    QCOMPARE(skinDetailTiling(HeadMesh{}), 64.0f);
    // Only close up: full from half the framing distance in, none from three quarters out.
    QCOMPARE(skinDetailStrength(0.3, 1.0), 1.0f);
    QCOMPARE(skinDetailStrength(0.5, 1.0), 1.0f);
    const float between = skinDetailStrength(0.6, 1.0);
    QVERIFY(between > 0 && between < 1);
    QCOMPARE(skinDetailStrength(0.75, 1.0), 0.0f);
    QCOMPARE(skinDetailStrength(1.0, 1.0), 0.0f);
    QCOMPARE(skinDetailStrength(0.3, 0.0), 0.0f);
  }

  // Tangent frames follow the uv layout: unit, orthogonal to the normal, along +u on the skin's
  // triangles and with +v on the side their handedness says.
  void tangentsFollowTheUvLayout() {
    const std::vector<Eigen::Vector4f> tangents = headTangents(*head_);
    QCOMPARE(tangents.size(), std::size_t(head_->vertexCount()));
    for (int v = 0; v < head_->vertexCount(); ++v) {
      const Eigen::Vector3f t = tangents[std::size_t(v)].head<3>();
      QVERIFY(std::abs(t.norm() - 1) < 1e-4f);
      QVERIFY(std::abs(t.dot(head_->normals.col(v))) < 1e-4f);
      QVERIFY(std::abs(std::abs(tangents[std::size_t(v)].w()) - 1) < 1e-6f);
    }
    int along = 0, total = 0;
    for (const Eigen::Vector3i& tri : head_->findSubmesh("skin")->triangles) {
      const Eigen::Vector3f e1 = head_->positions.col(tri[1]) - head_->positions.col(tri[0]);
      const Eigen::Vector3f e2 = head_->positions.col(tri[2]) - head_->positions.col(tri[0]);
      const Eigen::Vector2f d1 = head_->uvs.col(tri[1]) - head_->uvs.col(tri[0]);
      const Eigen::Vector2f d2 = head_->uvs.col(tri[2]) - head_->uvs.col(tri[0]);
      const float det = d1.x() * d2.y() - d2.x() * d1.y();
      if (std::abs(det) < 1e-12f) continue;
      const Eigen::Vector3f du = (e1 * d2.y() - e2 * d1.y()) / det;
      const Eigen::Vector3f dv = (e2 * d1.x() - e1 * d2.x()) / det;
      const Eigen::Vector4f& t = tangents[std::size_t(tri[0])];
      const Eigen::Vector3f bitangent = t.w() * head_->normals.col(tri[0]).cross(t.head<3>());
      along += t.head<3>().dot(du) > 0 && bitangent.dot(dv) > 0;
      ++total;
    }
    QVERIFY2(along > total * 95 / 100, qPrintable(QString("%1 of %2").arg(along).arg(total)));
    // Without uvs: still unit and orthogonal.
    HeadMesh plain = *head_;
    plain.uvs.resize(2, 0);
    const std::vector<Eigen::Vector4f> fallback = headTangents(plain);
    QVERIFY(std::abs(fallback[0].head<3>().dot(plain.normals.col(0))) < 1e-4f);
    QVERIFY(std::abs(fallback[0].head<3>().norm() - 1) < 1e-4f);
  }

  // Horizons on the default head: the crown sees open sky all round, the neck under the jaw has
  // the jaw above it (its most upward sector is high), the chin's underside faces the neck;
  // nothing but skin has horizons, and nothing within a tiny reach.
  void horizonsSeeTheJawOverTheNeck() {
    const std::vector<Eigen::Vector4f> tangents = headTangents(*head_);
    const std::vector<Horizons> horizons = skinHorizons(*head_, tangents);
    QCOMPARE(horizons.size(), std::size_t(head_->vertexCount()));
    auto upward = [&](int v) {  // the horizon of the sector pointing most upwards
      const Eigen::Vector3f n = head_->normals.col(v), t = tangents[std::size_t(v)].head<3>();
      const Eigen::Vector3f b = tangents[std::size_t(v)].w() * n.cross(t);
      int best = 0;
      for (int k = 1; k < 8; ++k) {
        const float a = float(k) * std::numbers::pi_v<float> / 4,
                    a0 = float(best) * std::numbers::pi_v<float> / 4;
        if ((std::cos(a) * t + std::sin(a) * b).y() > (std::cos(a0) * t + std::sin(a0) * b).y())
          best = k;
      }
      return horizons[std::size_t(v)][std::size_t(best)];
    };
    const int crown = skinVertexNear(Eigen::Vector3f(0, head_->boundsMax().y(), 0.4f));
    for (float h : horizons[std::size_t(crown)]) QVERIFY(h < 0.05f);
    const int neck = skinVertexNear(Eigen::Vector3f(0.45f, 6.3f, 0.6f));
    QVERIFY2(upward(neck) > 0.3f, qPrintable(QString::number(upward(neck))));
    const int chin = skinVertexNear(Eigen::Vector3f(0, 6.17f, 1.03f));
    QVERIFY(*std::max_element(horizons[std::size_t(chin)].begin(),
                              horizons[std::size_t(chin)].end()) > 0.5f);
    const HeadSubmesh* eye = head_->findSubmesh("eye_l");
    for (int v = eye->firstVertex; v < eye->firstVertex + eye->vertexCount; ++v)
      for (float h : horizons[std::size_t(v)]) QCOMPARE(h, 0.0f);
    for (const Horizons& h : skinHorizons(*head_, tangents, 1e-4f))
      for (float x : h) QCOMPARE(x, 0.0f);
    QVERIFY(skinHorizons(*head_, {}).size() == std::size_t(head_->vertexCount()));
  }

  void islandPaddingReplacesBordersAndFillsAround() {
    // One square uv island over [4, 12) texels of a 16 x 16 texture: green inside with a red
    // painted border ring, blue outside.
    HeadMesh quad;
    quad.positions = Eigen::Matrix3Xf::Zero(3, 4);
    quad.normals = Eigen::Matrix3Xf::Zero(3, 4);
    quad.uvs.resize(2, 4);
    quad.uvs << 0.25f, 0.75f, 0.75f, 0.25f, 0.25f, 0.25f, 0.75f, 0.75f;
    HeadSubmesh sub;
    sub.name = "skin";
    sub.vertexCount = 4;
    sub.triangles = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 3)};
    QImage texture(16, 16, QImage::Format_RGBA8888);
    texture.fill(QColor(0, 0, 255));
    for (int y = 4; y < 12; ++y)
      for (int x = 4; x < 12; ++x) {
        const bool border = x == 4 || x == 11 || y == 4 || y == 11;
        texture.setPixelColor(x, y, border ? QColor(255, 0, 0) : QColor(0, 200, 0));
      }
    const QImage padded = padUvIslands(texture, quad, sub, 2);
    QCOMPARE(padded.size(), texture.size());
    QCOMPARE(padded.pixelColor(8, 8), QColor(0, 200, 0));  // inside: untouched
    QCOMPARE(padded.pixelColor(4, 8), QColor(0, 200, 0));  // the painted border: replaced
    QCOMPARE(padded.pixelColor(11, 11), QColor(0, 200, 0));
    QCOMPARE(padded.pixelColor(2, 8), QColor(0, 200, 0));  // grown outwards
    QCOMPARE(padded.pixelColor(0, 0), QColor(0, 0, 255));  // far outside: kept
    // The real head: the skin texture keeps its colours inside the islands.
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    const QImage original(
        QString::fromStdString(head_->materials[std::size_t(skin->material)].diffuseTexture));
    QVERIFY(!original.isNull());
    const QImage skinPadded = padUvIslands(original, *head_, *skin);
    const QImage reference = original.convertToFormat(QImage::Format_RGBA8888);
    int same = 0, total = 0;
    for (const Eigen::Vector3i& t : skin->triangles) {
      const Eigen::Vector2f uv =
          (head_->uvs.col(t[0]) + head_->uvs.col(t[1]) + head_->uvs.col(t[2])) / 3.0f;
      const int x = std::clamp(int(uv.x() * reference.width()), 0, reference.width() - 1);
      const int y = std::clamp(int(uv.y() * reference.height()), 0, reference.height() - 1);
      same += skinPadded.pixelColor(x, y) == reference.pixelColor(x, y);
      ++total;
    }
    QVERIFY2(same > total * 9 / 10, "padding changed the inside of the islands");
  }

  void occlusionDarkensCavitiesNotTheFace() {
    const std::vector<float> ao = headOcclusion(*head_);
    QCOMPARE(ao.size(), std::size_t(head_->vertexCount()));
    for (float a : ao) QVERIFY(a >= 0.25f && a <= 1.0f);
    // Creases (nostrils, lips, ears) are darker; the face looking at the camera stays open.
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    int dark = 0, facing = 0;
    double facingSum = 0;
    for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v) {
      dark += ao[std::size_t(v)] < 0.8f;
      if (head_->normals(2, v) > 0.8f &&
          head_->positions(2, v) > left_.centre.z()) {  // the front of the face
        facingSum += ao[std::size_t(v)];
        ++facing;
      }
    }
    QVERIFY(dark > 20);
    QVERIFY(facingSum / facing > 0.93);
    // The forehead is open: not occluded.
    QVERIFY(
        ao[std::size_t(skinVertexNear(
            left_.centre + Eigen::Vector3f(-left_.centre.x(), 5 * left_.radius, left_.radius)))] >
        0.95f);
    // The back of the mouth is darker than the front teeth.
    const HeadSubmesh* teeth = head_->findSubmesh("teeth_upper");
    float front = 0, back = 1;
    for (int v = teeth->firstVertex; v < teeth->firstVertex + teeth->vertexCount; ++v) {
      front = std::max(front, ao[std::size_t(v)]);
      back = std::min(back, ao[std::size_t(v)]);
    }
    QVERIFY(front > back + 0.3f);
  }

  void framingLooksAtTheFace() {
    const OrbitView view = OrbitView::framing(*head_);
    const Eigen::Vector3f mid = 0.5f * (left_.centre + right_.centre);
    // The target is on the mid line a little below the eyes; the camera is in front of the face.
    QVERIFY(std::abs(view.target.x() - mid.x()) < 1e-3);
    QVERIFY(view.target.y() < mid.y() && view.target.y() > mid.y() - 0.5);
    QVERIFY(view.eye().z() > head_->boundsMax().z());
    // Looking at the target: the camera's -z axis points from the eye to the target.
    const Eigen::Vector3d forward = -(view.orientation() * Eigen::Vector3d::UnitZ());
    QVERIFY((forward - (view.target - view.eye()).normalized()).norm() < 1e-9);
  }

  // The angle between where `view` looks and the direction to `point`, in degrees.
  static double offAxisDegrees(const OrbitView& view, const Eigen::Vector3d& point) {
    const Eigen::Vector3d forward = (view.target - view.eye()).normalized();
    return std::acos(std::clamp(forward.dot((point - view.eye()).normalized()), -1.0, 1.0)) *
           180.0 / std::numbers::pi;
  }

  void cameraPresetsAimWhereTheyAreNamed() {
    for (const CameraPreset preset :
         {CameraPreset::Framing, CameraPreset::Front, CameraPreset::ThreeQuarter,
          CameraPreset::Profile, CameraPreset::CloseLeft, CameraPreset::CloseRight}) {
      QCOMPARE(parseCameraPreset(toString(preset)), std::optional(preset));
      QVERIFY(cameraPresetNames().find(toString(preset)) != std::string_view::npos);
    }
    QVERIFY(!parseCameraPreset("sideways"));
    QVERIFY(!parseCameraPreset(""));

    const OrbitView framing = OrbitView::framing(*head_);
    QVERIFY(presetView(*head_, CameraPreset::Framing) == framing);
    const OrbitView front = presetView(*head_, CameraPreset::Front);
    QVERIFY(std::abs(front.eye().x() - front.target.x()) < 1e-9);
    QVERIFY(front.eye().z() > head_->boundsMax().z());
    // Profile: the camera stands on the face's left (+x), level with the target.
    const OrbitView profile = presetView(*head_, CameraPreset::Profile);
    QVERIFY(std::abs(profile.eye().x() - profile.target.x() - profile.distance) < 1e-9);

    // Close-ups: aimed at the cheek below their own eye, from that side, far closer than the
    // framing, with that eye still in view (the tear's start) and the other eye off centre.
    const double halfFov = 0.5 * framing.fovYDegrees;
    for (const bool left : {true, false}) {
      const OrbitView close =
          presetView(*head_, left ? CameraPreset::CloseLeft : CameraPreset::CloseRight);
      const Eigen::Vector3d own = (left ? left_ : right_).centre.cast<double>();
      const Eigen::Vector3d other = (left ? right_ : left_).centre.cast<double>();
      QVERIFY(std::abs(close.target.x() - own.x()) < 0.05);  // the eye mesh's middle
      QVERIFY(close.target.y() < own.y());
      QVERIFY(left ? close.eye().x() > close.target.x() : close.eye().x() < close.target.x());
      QVERIFY(close.distance < 0.3 * framing.distance);
      QVERIFY(offAxisDegrees(close, own) < halfFov);
      QVERIFY(offAxisDegrees(close, other) > offAxisDegrees(close, own));
    }
  }

  void orbitZoomAndPanStayInRange() {
    OrbitView view = OrbitView::framing(*head_);
    const OrbitView start = view;
    view.orbit(0, 500);
    QCOMPARE(view.pitchDegrees, 85.0);
    view.orbit(720 + 10, -1000);
    QCOMPARE(view.pitchDegrees, -85.0);
    QVERIFY(std::abs(view.yawDegrees - std::remainder(start.yawDegrees + 10, 360.0)) < 1e-9);
    view.zoom(1e-9);
    QCOMPARE(view.distance, view.minDistance);
    view.zoom(1e9);
    QCOMPARE(view.distance, view.maxDistance);
    view.zoom(-1);
    view.zoom(std::nan(""));
    QCOMPARE(view.distance, view.maxDistance);
    // Panning moves the target across the view, by the view's height per unit.
    view = start;
    view.pan(0.5, 0);
    const Eigen::Vector3d right = view.orientation() * Eigen::Vector3d::UnitX();
    const double viewHeight = 2 * start.distance * std::tan(start.fovYDegrees * M_PI / 360);
    QVERIFY(((view.target - start.target) - 0.5 * viewHeight * right).norm() < 1e-9);
    QVERIFY(std::abs((view.eye() - view.target).norm() - start.distance) < 1e-9);
  }
};

QTEST_GUILESS_MAIN(OverlayTest)
#include "OverlayTest.moc"
