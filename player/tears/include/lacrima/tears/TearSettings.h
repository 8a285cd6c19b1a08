#pragma once
// Tear parameters: the values of the 2009 system (common/TearParameters.h: names, defaults,
// ranges, the field each is kept in), loaded from JSON, and their translation into the head's
// units.
//
// Unit scaling (documented once, used everywhere):
//  * The head is in its own length unit (the default head: decimetres, ~2.7 tall). Its height
//    fixes `headUnitsPerMetre` assuming a real head of 0.27 m, so a head modelled in metres or
//    centimetres gets the same physical tears.
//  * The 2009 lengths (kernel, node_size, cube_size) are in "2009 units". We set one 2009 unit to
//    3.2 mm: the default kernel 0.5 becomes h = 1.6 mm, rest spacing h/2 = 0.8 mm, so ~100
//    particles make a ~4.6 mm drop (a tear), as the thesis's 100-particle tears looked.
//  * gravity and adhesion are accelerations in m/s^2 (the table says 9.81 is Earth's gravity):
//    multiplied by headUnitsPerMetre. Adhesion 20 therefore pulls a particle into the skin at ~2 g.
//  * The 2009 force constants had no consistent physical units (the thesis tuned them by trial),
//    so each is mapped so that its DEFAULT lands on a physically motivated value:
//      pressure 0.004  -> speed of sound c = 0.2 m/s, stiffness k = c^2 * pressure / 0.004.
//                         ~10x the speed of a tear on skin (weakly compressible), and the most a
//                         real-time budget allows: the CFL step h / c is then ~3 ms. A real
//                         c (1500 m/s) would need 10^5 sub-steps per frame.
//      viscosity       -> kinematic viscosity nu = viscosity * (2009 unit)^2 / s
//                         (0.9 -> 9.2e-6 m^2/s, ~9x water: needed at 0.8 mm resolution)
//      tension 0.2     -> Müller sigma such that the Laplace pressure 2 sigma / R of a 100-particle
//                         drop (radius proportional to the kernel) is 10% of c^2, so tension
//                         compresses a drop by ~10% at any kernel size. Water's
//                         real sigma would crush a c = 0.2 m/s fluid to several times its density.
//                         Akinci model: gamma = tension / 0.2 * 0.05 c^2 / h (cohesion
//                         and curvature forces ~5% of the pressure response c^2 / h)
//      friction        -> drag rate = friction * (normal load per mass) / 0.3 m/s: a default
//                         tear on a 45 degree cheek slides at ~2 cm/s (see SkinContact.h)
//      adhesion 20     -> also the holding tension of pendant drops (Tate's law,
//                         DropDetachment_Tate1864.h): gamma = adhesion / 20 * 0.011 N/m, so a
//                         drop under the chin lets go at the 20-30 uL water drops on skin hold;
//                         adhesion 0 holds nothing, 1000 fifty times more
//  * Time is in seconds, density is normalised (rest density rho0 = 1).
#include <lacrima/common/TearParameters.h>

#include <string>
#include <string_view>

namespace lacrima::tears {

// The table's parameters (common/TearParameters.h), in the 2009 units: one field each, named
// and ranged by the table alone. Defaults from the table.
struct TearSettings : TearParameterSet {
  TearSettings();  // the table's defaults

  // Sets one value by its table name; throws std::invalid_argument (unknown name / out of range).
  void set(std::string_view name, double value);
  double get(std::string_view name) const;

  // Parses a flat JSON object {"pressure": 0.004, ...}; missing names keep their defaults.
  // Throws std::invalid_argument with a message naming the offending key (syntax errors,
  // non-numbers, unknown names and out-of-range values all fail; nothing is half-applied).
  static TearSettings fromJson(std::string_view json);
};

// Length and acceleration conversion between physical/2009 units and the head's units.
struct UnitScale {
  double headUnitsPerMetre = 10.0;   // decimetre head
  double lengthPer2009Unit = 0.032;  // head units per 2009 unit (3.2 mm)

  // From the head's height in its own units (default head: 2.7 dm).
  static UnitScale fromHeadHeight(double headHeight);
};

// Everything the solver uses, in head units, seconds and normalised density.
struct ScaledParameters {
  double h = 0;               // kernel support radius
  double spacing = 0;         // rest particle spacing, h / 2
  double particleRadius = 0;  // collision radius, spacing / 2
  double contactBand = 0;     // a particle within radius + band of the skin is touching it
  double restDensity = 1.0;
  double particleMass = 0;  // set so a rest lattice at `spacing` has density restDensity
  double stiffness = 0;     // k in p = k (rho - rho0); speed of sound c = sqrt(k)
  double soundSpeed = 0;
  double kinematicViscosity = 0;
  double tensionSigma = 0;    // Müller: sigma / rho0
  double tensionGamma = 0;    // Akinci: gamma
  double adhesion = 0;        // acceleration into the skin at rest density and full mass
  double holdingTension = 0;  // gamma / rho0 of pendant drops' contact line, head units^3/s^2
  double friction = 0;        // drag rate per (normal load per mass)
  double gravity = 0;         // magnitude, along -y of the head frame
  double nodeSize = 0, cubeSize = 0, iso = 0;
  double headUnitsPerMetre = 0;

  static ScaledParameters from(const TearSettings& settings, const UnitScale& scale);
};

}  // namespace lacrima::tears
