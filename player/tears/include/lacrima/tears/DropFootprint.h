#pragma once
// The wetted width of a drop resting on skin, from its volume.
//
// A small drop on a surface is close to a spherical cap (its size is below the capillary length,
// about 2.7 mm for water, so gravity flattens it little). A cap of sphere radius R meeting the
// skin at contact angle theta has
//     V = (pi R^3 / 3) (2 - 3 cos(theta) + cos^3(theta)),     contact radius  a = R sin(theta),
//     height  H = R (1 - cos(theta)),
// so a = sin(theta) (3 V / (pi (2 - 3 cos(theta) + cos^3(theta))))^(1/3).
//
// Water on human skin meets it at roughly 70-90 degrees (lower for tear fluid, whose proteins
// and lipids wet better); the default 70 degrees gives a one-particle drop of the default tear
// parameters (0.51 uL) a track 1.5 mm wide and ten particles 3.2 mm, the 1-3 mm of real tear
// tracks. The particles alone cannot show this width: at rest spacing s each is a parcel s wide.
#include <cmath>
#include <numbers>

namespace lacrima::tears {

struct CapShape {
  double contactRadius = 0;  // a
  double height = 0;         // H
};

// The water one particle stands for: a cube of the rest spacing, twice the particle radius.
// (Masses are not used: they are in the solver's units, and a drop's shape on the skin is
// drawn from the water it holds at rest.)
inline double parcelVolume(double particleRadius) {
  const double s = 2 * particleRadius;
  return s * s * s;
}

// Contact radius and height of a spherical cap of `volume` meeting the surface at
// `contactAngleRadians` (0 < theta <= pi). Units follow the volume's (length^3 -> length).
inline CapShape sphericalCap(double volume, double contactAngleRadians) {
  if (!(volume > 0) || !(contactAngleRadians > 0)) return {};
  const double c = std::cos(contactAngleRadians);
  const double shape = 2 - 3 * c + c * c * c;  // > 0 for theta in (0, pi]
  const double R = std::cbrt(3 * volume / (std::numbers::pi * shape));
  return {R * std::sin(contactAngleRadians), R * (1 - c)};
}

}  // namespace lacrima::tears
