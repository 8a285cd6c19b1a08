#include "Kernels.h"

#include <lacrima/tears/Parameters.h>
#include <lacrima/common/JsonSyntaxError.h>

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace lacrima::tears {
namespace {

// Physical anchors of the mapping described in Parameters.h.
constexpr double kRealHeadHeightMetres = 0.27;
constexpr double k2009UnitMetres = 0.0032;
constexpr double kDefaultPressure = 0.004;
constexpr double kSoundSpeedMetresPerSecond = 0.2;
constexpr double kDefaultTension = 0.2;
// Laplace pressure 2 sigma / R of a 100-particle drop (R = 2.88 rest spacings = 0.72 units of
// 2009 at the default kernel, proportional to the kernel) as a fraction of c^2: the compression
// tension causes, whatever the kernel.
constexpr double kTensionCompression = 0.1;
constexpr double kDrop100Radius2009 = 0.72;
// Akinci: cohesion + curvature at a drop's surface ~5% of the pressure response c^2 / h.
constexpr double kAkinciFraction = 0.05;
constexpr double kFrictionReferenceSpeed = 0.3;  // m/s

// Sum of poly6 over a simple cubic lattice of the given spacing around the origin (origin
// included): the density a particle of unit mass sees in a fluid at rest.
double latticeKernelSum(double h, double spacing) {
  const Poly6Kernel w(h);
  const int n = static_cast<int>(std::ceil(h / spacing));
  double sum = 0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        const double r2 = spacing * spacing * (i * i + j * j + k * k);
        sum += w.value(r2);
      }
  return sum;
}

}  // namespace

TearSettings::TearSettings() {
  for (const auto& info : tearParameterTable()) this->*info.field = info.defaultValue;
}

void TearSettings::set(std::string_view name, double value) {
  validateTearParameter(name, value);  // throws with the table's wording
  this->*findTearParameter(name)->field = value;
}

double TearSettings::get(std::string_view name) const {
  const TearParameterInfo* info = findTearParameter(name);
  if (!info) throw std::invalid_argument("unknown parameter '" + std::string(name) + "'");
  return this->*info->field;
}

TearSettings TearSettings::fromJson(std::string_view json) {
  QJsonParseError error{};
  const QJsonDocument document = QJsonDocument::fromJson(
      QByteArray(json.data(), static_cast<qsizetype>(json.size())), &error);
  if (error.error != QJsonParseError::NoError) {
    throw std::invalid_argument(
        jsonSyntaxErrorLocation(json, error, "tear parameters").toString() +
        ": invalid JSON: " + error.errorString().toStdString());
  }
  if (!document.isObject())
    throw std::invalid_argument("tear parameters: expected a JSON object of name: number");
  TearSettings result;  // filled completely before it is returned: no half-applied state
  const QJsonObject object = document.object();
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string name = it.key().toStdString();
    if (!it.value().isDouble()) {
      throw std::invalid_argument("tear parameters: " + name + ": expected a number");
    }
    try {
      result.set(name, it.value().toDouble());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("tear parameters: ") + e.what());
    }
  }
  return result;
}

UnitScale UnitScale::fromHeadHeight(double headHeight) {
  if (!(headHeight > 0) || !std::isfinite(headHeight))
    throw std::invalid_argument("head height must be positive and finite");
  UnitScale s;
  s.headUnitsPerMetre = headHeight / kRealHeadHeightMetres;
  s.lengthPer2009Unit = k2009UnitMetres * s.headUnitsPerMetre;
  return s;
}

ScaledParameters ScaledParameters::from(const TearSettings& in, const UnitScale& scale) {
  ScaledParameters p;
  const double L = scale.lengthPer2009Unit;
  const double U = scale.headUnitsPerMetre;
  p.headUnitsPerMetre = U;
  p.h = in.kernel * L;
  p.spacing = 0.5 * p.h;
  p.particleRadius = 0.5 * p.spacing;
  p.contactBand = 0.5 * p.particleRadius;
  p.restDensity = 1.0;
  p.particleMass = p.restDensity / latticeKernelSum(p.h, p.spacing);
  const double c0 = kSoundSpeedMetresPerSecond * U;
  p.stiffness = c0 * c0 * in.pressure / kDefaultPressure;
  p.soundSpeed = std::sqrt(p.stiffness);
  p.kinematicViscosity = in.viscosity * L * L;
  p.tensionSigma = in.tension / kDefaultTension * 0.5 * kTensionCompression * c0 * c0 * kDrop100Radius2009 * L * (in.kernel / 0.5);
  p.tensionGamma = in.tension / kDefaultTension * kAkinciFraction * c0 * c0 / p.h;
  p.adhesion = in.adhesion * U;
  p.friction = in.friction / (kFrictionReferenceSpeed * U);
  p.gravity = in.gravity * U;
  p.nodeSize = in.nodeSize * L;
  p.cubeSize = in.cubeSize * L;
  p.iso = in.iso;
  return p;
}

}  // namespace lacrima::tears
