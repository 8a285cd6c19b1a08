#pragma once
// SPH smoothing kernels of Müller, Charypar & Gross 2003 ("Particle-based fluid simulation for
// interactive applications") and the cohesion spline of Akinci, Akinci & Teschner 2013 ("Versatile
// surface tension and adhesion for SPH fluids"). Every kernel has support radius h and is zero
// beyond it. Coefficients are computed once per h so the inner loops only multiply.
#include <Eigen/Core>

#include <numbers>

namespace lacrima::tears {

// W_poly6(r, h) = 315 / (64 pi h^9) (h^2 - r^2)^3. Used for density and the colour field because
// it depends on r^2 only (no square root). Its gradient vanishes at r = 0, which is why pressure
// uses the spiky kernel instead.
class Poly6Kernel {
 public:
  explicit Poly6Kernel(double h)
      : h2_(h * h),
        w_(315.0 / (64.0 * std::numbers::pi * pow9(h))),
        grad_(-945.0 / (32.0 * std::numbers::pi * pow9(h))) {}

  double value(double r2) const {
    if (r2 >= h2_) return 0.0;
    const double d = h2_ - r2;
    return w_ * d * d * d;
  }
  double valueAtZero() const { return w_ * h2_ * h2_ * h2_; }
  // Coefficients for fused loops: W = valueCoefficient() (h^2 - r^2)^3,
  // grad W = gradientCoefficient() (h^2 - r^2)^2 r_vec.
  double valueCoefficient() const { return w_; }
  double gradientCoefficient() const { return grad_; }

  // grad W = -945 / (32 pi h^9) (h^2 - r^2)^2 r_vec
  Eigen::Vector3d gradient(const Eigen::Vector3d& r, double r2) const {
    if (r2 >= h2_) return Eigen::Vector3d::Zero();
    const double d = h2_ - r2;
    return (grad_ * d * d) * r;
  }
  // lap W = -945 / (32 pi h^9) (h^2 - r^2)(3 h^2 - 7 r^2)
  double laplacian(double r2) const {
    if (r2 >= h2_) return 0.0;
    return grad_ * (h2_ - r2) * (3.0 * h2_ - 7.0 * r2);
  }

 private:
  static double pow9(double h) {
    const double h3 = h * h * h;
    return h3 * h3 * h3;
  }
  double h2_, w_, grad_;
};

// Spiky kernel W = 15 / (pi h^6) (h - r)^3; only its gradient is used:
// grad W = -45 / (pi h^6) (h - r)^2 r_hat. Its gradient does not vanish near r = 0, so close
// particles keep repelling instead of clustering.
class SpikyKernel {
 public:
  explicit SpikyKernel(double h) : h_(h), grad_(-45.0 / (std::numbers::pi * pow6(h))) {}

  // Magnitude factor g with grad W = g * r_vec (r > 0); 0 outside the support.
  double gradientFactor(double r) const {
    if (r >= h_ || r <= 0.0) return 0.0;
    const double d = h_ - r;
    return grad_ * d * d / r;
  }
  // grad W = gradientCoefficient() (h - r)^2 / r * r_vec, for fused loops.
  double gradientCoefficient() const { return grad_; }
  double radius() const { return h_; }
  // |grad W| at distance 0 (the limit), used for coincident particles.
  double gradientMagnitudeAtZero() const { return -grad_ * h_ * h_; }
  double value(double r) const {
    if (r >= h_) return 0.0;
    const double d = h_ - r;
    return -grad_ / 3.0 * d * d * d;
  }

 private:
  static double pow6(double h) {
    const double h3 = h * h * h;
    return h3 * h3;
  }
  double h_, grad_;
};

// Müller's viscosity kernel, used for its Laplacian only: lap W = 45 / (pi h^6) (h - r), which is
// positive everywhere in the support, so viscosity always damps relative velocity.
class ViscosityKernel {
 public:
  explicit ViscosityKernel(double h)
      : h_(h), lap_(45.0 / (std::numbers::pi * h * h * h * h * h * h)) {}
  double laplacian(double r) const { return r >= h_ ? 0.0 : lap_ * (h_ - r); }
  // lap W = laplacianCoefficient() (h - r), for fused loops.
  double laplacianCoefficient() const { return lap_; }
  double radius() const { return h_; }
  // W itself, for the normalisation test: 15/(2 pi h^3) (-r^3/(2h^3) + r^2/h^2 + h/(2r) - 1).
  double value(double r) const {
    if (r >= h_ || r <= 0.0) return 0.0;
    const double q = r / h_;
    return 15.0 / (2.0 * std::numbers::pi * h_ * h_ * h_) *
           (-0.5 * q * q * q + q * q + 0.5 / q - 1.0);
  }

 private:
  double h_, lap_;
};

// Akinci 2013 cohesion spline: C(r) = 32/(pi h^9) * { (h-r)^3 r^3            if 2r > h
//                                                   { 2(h-r)^3 r^3 - h^6/64  if 0 < 2r <= h
// Repulsive (negative) at short range, attractive beyond h/2, so cohesion does not clump.
class CohesionKernel {
 public:
  explicit CohesionKernel(double h)
      : h_(h),
        h6_over_64_(h * h * h * h * h * h / 64.0),
        c_(32.0 / (std::numbers::pi * h * h * h * h * h * h * h * h * h)) {}
  double value(double r) const {
    if (r >= h_ || r <= 0.0) return 0.0;
    const double a = (h_ - r) * (h_ - r) * (h_ - r) * r * r * r;
    return 2.0 * r > h_ ? c_ * a : c_ * (2.0 * a - h6_over_64_);
  }

 private:
  double h_, h6_over_64_, c_;
};

}  // namespace lacrima::tears
