#pragma once
// A drop sliding down an inclined plate, the physical observable of `lacrima-bench tears-slide`:
// a flat skin (the cheek sheet's generator with no curvature) tilted `angle` from the horizontal,
// one drop of fixed volume emitted near its top, and the steady speed of the drop's centroid
// down the slope. No solver is tuned to it: the published law for sliding drops (Podgorski,
// Flesselles & Limat 2001; Kim, Lee & Kang 2002) says Ca = mu U / gamma grows linearly with
// Bo sin(alpha) = rho g V^(2/3) sin(alpha) / gamma above a threshold angle.
#include <lacrima/tears/SimulationOptions.h>
#include <lacrima/tears/TearSettings.h>

#include <string>

namespace lacrima::bench {

struct SlideSetup {
  double angleDegrees = 45;  // of the plate from the horizontal, (0, 90]
  int particles = 100;       // the drop: 100 particles make a tear (TearSettings.h)
  int settleFrames = 22;     // let the drop form and reach its steady speed (1 s at 22 fps)
  int measureFrames = 44;    // then measure over this many frames
  double fps = 22;
  std::string solver = tears::SimulationOptions{}.pressureSolver.key;  // a registry key
  double lambdaScale = 1;  // the sub-step safety factors, scaled as tears-sweep scales them
  int threads = 0;
  // The model leaves water in a drop's trail (SimulationOptions::trailDecayMetres), and a lighter
  // drop clings harder and slows, so it never slides steadily; the law is for a drop of fixed
  // volume, so by default the loss is off.
  bool trailLoss = false;
};

struct SlideRun {
  // Along the slope, m/s: the centroid's mean speed over the measuring window, and over its
  // first and second halves (equal when the slide is steady).
  double speed = 0, earlySpeed = 0, lateSpeed = 0;
  double frontSpeed = 0;  // the lowest particle's, m/s: differs when the drop leaves a trail
  double massLeft = 1;    // the drop's mass at the end over its mass at emission
  double msPerFrame = 0;  // simulation alone, mean
  double substepsPerFrame = 0;
  int alive = 0;           // particles at the end
  long long recycled = 0;  // particles that left the simulation's box (fell off) and came back
  bool finite = true;      // every particle position finite
  bool onPlate = true;     // all of the drop stayed on the plate, clear of its lower edge
};

SlideRun runSlide(const SlideSetup& setup);

// What the simulation's parameters are physically, in SI units (rest density is water's).
struct SlidePhysics {
  double density = 1000;  // kg/m^3
  double viscosity = 0;   // dynamic, Pa s: rest density x the kinematic viscosity
  double tension = 0;     // N/m: the Müller sigma (TearSettings.h)
  double gravity = 0;     // m/s^2
  double volume = 0;      // m^3: particles x spacing^3
  double adhesion = 0;    // m/s^2 into the skin
  double dragRate = 0;    // friction: tangential drag rate per (normal load per mass), s/m
  double capillaryNumber(double speed) const { return viscosity * speed / tension; }
  double bondNumber() const;  // rho g V^(2/3) / gamma
  // The slide speed the skin friction alone allows a particle pressed by gravity and full
  // adhesion (SkinContact.h): g sin(a) = drag (g cos(a) + A) U. An estimate of what sets the
  // speed in this model, beside the measured one.
  double dragLimitedSpeed(double angleDegrees) const;
};

SlidePhysics slidePhysics(const tears::TearSettings& settings, int particles);

}  // namespace lacrima::bench
