#include "Kernels.h"

#include <lacrima/common/JsonInput.h>
#include <lacrima/tears/TearSettings.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace lacrima::tears {
namespace {

// Physical anchors of the mapping described in TearSettings.h.
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
// Pendant drops: the holding tension at the default adhesion, N/m, and water's density
// (docs/tears.md, "Drops that fall", has the calibration).
constexpr double kDefaultAdhesion = 20;
constexpr double kHoldingTension = 0.011;
constexpr double kWaterDensity = 1000;  // kg/m^3

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
  TearSettings result;  // filled completely before it is returned: no half-applied state
  try {
    const JsonInput input = JsonInput::parse(json, "tear parameters");
    for (const auto& [name, value] : readTearParameters(input.root())) result.set(name, value);
  } catch (const FileError& error) {
    throw std::invalid_argument(error.what());  // what the settings' callers catch
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
  p.tensionSigma = in.tension / kDefaultTension * 0.5 * kTensionCompression * c0 * c0 *
                   kDrop100Radius2009 * L * (in.kernel / 0.5);
  p.tensionGamma = in.tension / kDefaultTension * kAkinciFraction * c0 * c0 / p.h;
  p.adhesion = in.adhesion * U;
  p.holdingTension = in.adhesion / kDefaultAdhesion * kHoldingTension / kWaterDensity * U * U * U;
  p.friction = in.friction / (kFrictionReferenceSpeed * U);
  p.gravity = in.gravity * U;
  p.nodeSize = in.nodeSize * L;
  p.cubeSize = in.cubeSize * L;
  p.iso = in.iso;
  return p;
}

}  // namespace lacrima::tears
