// lacrima-bench tears-slide: a physical observable no solver is tuned to. A drop of fixed volume
// slides down a flat plate (SlideScene.h) at several angles; per solver and sub-step factor the
// steady speed U of its centroid is fitted to the law of sliding drops,
//   U = k (sin(alpha) - sin(alpha_c)),
// the dimensional form of Ca = c (Bo sin(alpha) - Bo sin(alpha_c)) with Ca = mu U / gamma and
// Bo = rho g V^(2/3) / gamma (Podgorski, Flesselles & Limat 2001, PRL 87 036102; Kim, Lee & Kang
// 2002, J. Colloid Interface Sci. 247 372). Reported beside ms per frame: the fit's R^2 (how
// linear the simulated speeds are in sin(alpha)), k, alpha_c and the dimensionless slope
// c = dCa / d(Bo sin alpha) = nu k / (g V^(2/3)), in which gamma cancels. The law's prefactor
// depends on the contact angle and a contact-line cut-off, so what is compared is the form
// (linear above a threshold), not a number.
#include "BenchCommandLine.h"
#include "NumberList.h"
#include "SlideScene.h"
#include "SweepPlot.h"
#include "SweepSolvers.h"

#include <lacrima/common/JsonWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

using namespace lacrima::tears;

struct Options {
  std::vector<double> angles = {10, 20, 30, 45, 60, 75};
  std::vector<double> substeps = {0.25, 1, 2};
  int particles = 100;
  int settleFrames = 22, measureFrames = 44;
  int threads = 0;
  bool json = false;
  bool trailLoss = false;
  std::string png;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "tears-slide",
      "A drop sliding down a flat plate at several angles: its steady speed per solver and\n"
      "sub-step factor, fitted to the law of sliding drops U = k (sin a - sin a_c)\n"
      "(Ca linear in Bo sin a above a threshold), with the fit's R^2 beside ms per frame.");
  line.option("angles", "A1,A2,...",
              "Plate angles from the horizontal, degrees (default "
              "10,20,30,45,60,75).",
              [&o](const QString& text) { return readNumberList(text, 1, 90, false, o.angles); });
  line.option(
      "substeps", "F1,F2,...", "Sub-step safety factors (default 0.25,1,2).",
      [&o](const QString& text) { return readNumberList(text, 0.05, 4, false, o.substeps); });
  line.wholeNumber("particles", "N", "Particles in the drop (default 100, a tear).", 8, 5000,
                   o.particles);
  line.wholeNumber("settle", "F", "Frames before measuring (default 22: 1 s).", 1, 10000,
                   o.settleFrames);
  line.wholeNumber("measure", "F", "Frames measured (default 44: 2 s).", 2, 10000, o.measureFrames);
  line.wholeNumber("threads", "T", "Threads each simulation shares (default 0: all).", 0, 256,
                   o.threads);
  line.flag("trail-loss",
            "Keep the model's trail mass loss (the drop drains and slows; default: a drop of "
            "fixed volume).",
            o.trailLoss);
  line.flag("json", "One JSON object instead of the table.", o.json);
  line.text("png", "FILE", "Also draw speed against sin(angle) with the fitted lines as a PNG.",
            o.png);
  return line.parse(argc, argv);
}

// Least squares U = a + b sin(alpha) over the runs that slide (U > 0) and stayed on the plate.
struct LineFit {
  double slope = std::numeric_limits<double>::quiet_NaN();  // k, m/s
  double intercept = std::numeric_limits<double>::quiet_NaN();
  double rSquared = std::numeric_limits<double>::quiet_NaN();  // needs 3 points or more
  int points = 0;
  double thresholdSin() const { return -intercept / slope; }
};

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  f.points = int(x.size());
  if (f.points < 2) return f;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= f.points, my /= f.points;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx <= 0) return f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  // R^2 = 1 - SS_res / SS_tot; for a least-squares line SS_res = syy - slope sxy.
  if (f.points >= 3 && syy > 0) f.rSquared = 1 - (syy - f.slope * sxy) / syy;
  return f;
}

struct Setting {
  const SolverEntry* solver = nullptr;
  double lambdaScale = 1;
  std::vector<SlideRun> runs;  // one per angle
  LineFit fit;
  double msPerFrame = 0;  // mean over the angles
  // The largest |second-half speed - first-half speed| / speed of the fitted runs: 0 when every
  // slide is steady over the measuring window.
  double unsteadiness = 0;
  std::string name() const {
    return solver->name + " sub-step x" + QString::number(lambdaScale).toStdString();
  }
};

double sinDegrees(double degrees) { return std::sin(degrees * std::numbers::pi / 180.0); }

void fit(Setting& s, const Options& o) {
  std::vector<double> x, y;
  s.msPerFrame = 0;
  for (std::size_t i = 0; i < s.runs.size(); ++i) {
    s.msPerFrame += s.runs[i].msPerFrame / double(s.runs.size());
    if (s.runs[i].onPlate && s.runs[i].finite && s.runs[i].speed > 0) {
      x.push_back(sinDegrees(o.angles[i]));
      y.push_back(s.runs[i].speed);
      const SlideRun& r = s.runs[i];
      s.unsteadiness = std::max(s.unsteadiness, std::abs(r.lateSpeed - r.earlySpeed) / r.speed);
    }
  }
  s.fit = fitLine(x, y);
}

// Why a run is left out of the fit, if it is.
std::string note(const SlideRun& r) {
  if (!r.finite) return "  (non-finite: not fitted)";
  if (r.recycled > 0)
    return "  (" + std::to_string(r.recycled) + " particles fell off the plate: not fitted)";
  if (!r.onPlate) return "  (reached the lower edge: not fitted)";
  return {};
}

void printTable(const std::vector<Setting>& settings, const SlidePhysics& phys, const Options& o) {
  std::printf(
      "  drop: %d particles = %.1f uL; rho %.0f kg/m^3, mu %.3g Pa s, gamma %.3g N/m (the Müller "
      "sigma), g %.2f m/s^2: Bo = %.3g\n",
      o.particles, phys.volume * 1e9, phys.density, phys.viscosity, phys.tension, phys.gravity,
      phys.bondNumber());
  std::printf("  %-22s %6s %10s %10s %10s %10s %10s %10s %9s %6s %6s\n", "setting", "angle",
              "U mm/s", "1st half", "2nd half", "front", "Ca", "Bo sin a", "drag est", "mass",
              "ms/fr");
  for (const Setting& s : settings) {
    for (std::size_t i = 0; i < s.runs.size(); ++i) {
      const SlideRun& r = s.runs[i];
      std::printf("  %-22s %6.1f %10.3f %10.3f %10.3f %10.3f %10.3g %10.3g %9.3f %5.0f%% %6.2f%s\n",
                  s.name().c_str(), o.angles[i], 1e3 * r.speed, 1e3 * r.earlySpeed,
                  1e3 * r.lateSpeed, 1e3 * r.frontSpeed, phys.capillaryNumber(r.speed),
                  phys.bondNumber() * sinDegrees(o.angles[i]),
                  1e3 * phys.dragLimitedSpeed(o.angles[i]), 100 * r.massLeft, r.msPerFrame,
                  note(r).c_str());
    }
  }
  std::printf("  fit U = k (sin a - sin a_c) over the sliding runs:\n");
  std::printf("  %-22s %10s %10s %8s %14s %8s %9s %10s\n", "setting", "k mm/s", "a_c deg", "R^2",
              "dCa/d(Bo sin)", "points", "unsteady", "ms/frame");
  for (const Setting& s : settings) {
    const double sinC = s.fit.thresholdSin();
    const double angleC = std::abs(sinC) <= 1 ? std::asin(sinC) * 180 / std::numbers::pi
                                              : std::numeric_limits<double>::quiet_NaN();
    std::printf("  %-22s %10.3f %10.1f %8.4f %14.4g %8d %8.0f%% %10.3f\n", s.name().c_str(),
                1e3 * s.fit.slope, angleC, s.fit.rSquared,
                phys.capillaryNumber(s.fit.slope) / phys.bondNumber(), s.fit.points,
                100 * s.unsteadiness, s.msPerFrame);
  }
}

void printJson(const std::vector<Setting>& settings, const SlidePhysics& phys, const Options& o) {
  JsonWriter json(JsonWriter::Layout::Compact);
  json.beginObject();
  json.field("benchmark", "tears-slide");
  json.field("particles", o.particles);
  json.field("trail_loss", o.trailLoss);
  json.field("volume_m3", phys.volume);
  json.field("density_kg_m3", phys.density);
  json.field("viscosity_pa_s", phys.viscosity);
  json.field("tension_n_m", phys.tension);
  json.field("gravity_m_s2", phys.gravity);
  json.field("bond_number", phys.bondNumber());
  json.key("settings");
  json.beginArray();
  for (const Setting& s : settings) {
    json.beginObject();
    json.field("solver", s.solver->key);
    json.field("lambda_scale", s.lambdaScale);
    json.field("ms_per_frame", s.msPerFrame);
    json.field("fit_slope_m_s", s.fit.slope);
    json.field("fit_threshold_sin", s.fit.thresholdSin());
    json.field("fit_r_squared", s.fit.rSquared);
    json.field("fit_points", s.fit.points);
    json.field("fit_ca_per_bo_sin", phys.capillaryNumber(s.fit.slope) / phys.bondNumber());
    json.field("unsteadiness", s.unsteadiness);
    json.key("runs");
    json.beginArray();
    for (std::size_t i = 0; i < s.runs.size(); ++i) {
      const SlideRun& r = s.runs[i];
      json.beginObject();
      json.field("angle_degrees", o.angles[i]);
      json.field("speed_m_s", r.speed);
      json.field("speed_first_half_m_s", r.earlySpeed);
      json.field("speed_second_half_m_s", r.lateSpeed);
      json.field("front_speed_m_s", r.frontSpeed);
      json.field("capillary_number", phys.capillaryNumber(r.speed));
      json.field("bond_sin", phys.bondNumber() * sinDegrees(o.angles[i]));
      json.field("drag_limited_speed_m_s", phys.dragLimitedSpeed(o.angles[i]));
      json.field("mass_left", r.massLeft);
      json.field("ms_per_frame", r.msPerFrame);
      json.field("substeps_per_frame", r.substepsPerFrame);
      json.field("particles_alive", r.alive);
      json.field("on_plate", r.onPlate);
      json.field("recycled_particles", r.recycled);
      json.field("finite", r.finite);
      json.endObject();
    }
    json.endArray();
    json.endObject();
  }
  json.endArray();
  json.endObject();
  std::fputs(std::move(json).finish().c_str(), stdout);
}

// Measured speeds (markers) and each setting's fitted line (dashed) in the setting's colour.
// In black, what the skin friction alone allows (SlidePhysics::dragLimitedSpeed).
bool drawPlot(const std::vector<Setting>& settings, const SlidePhysics& phys, const Options& o) {
  std::vector<PlotSeries> series;
  PlotSeries drag{"skin friction alone (estimate)", {}, 8, true, false};
  for (int a = 5; a <= 90; a += 5)
    drag.points.push_back({sinDegrees(a), 1e3 * phys.dragLimitedSpeed(a), ""});
  for (std::size_t k = 0; k < settings.size(); ++k) {
    const Setting& s = settings[k];
    PlotSeries measured{s.name(), {}, int(k), false, true};
    for (std::size_t i = 0; i < s.runs.size(); ++i)
      if (s.runs[i].onPlate && s.runs[i].finite)
        measured.points.push_back({sinDegrees(o.angles[i]), 1e3 * s.runs[i].speed, ""});
    series.push_back(std::move(measured));
    if (!std::isfinite(s.fit.slope)) continue;
    char name[96];
    std::snprintf(name, sizeof name, "  fit: k %.1f mm/s, R^2 %.3f", 1e3 * s.fit.slope,
                  s.fit.rSquared);
    const double x0 = std::max(0.0, s.fit.thresholdSin());
    series.push_back({name,
                      {{x0, 1e3 * (s.fit.intercept + s.fit.slope * x0), ""},
                       {1, 1e3 * (s.fit.intercept + s.fit.slope), ""}},
                      int(k),
                      true,
                      false});
  }
  series.push_back(std::move(drag));
  char title[128];
  std::snprintf(title, sizeof title,
                "A %.0f uL drop (%d particles) sliding down a plate: fits U = k (sin a - sin a_c)",
                phys.volume * 1e9, o.particles);
  const PlotAxes axes{title, "sin(plate angle from the horizontal)",
                      "steady speed of the centroid (mm/s)", false, false};
  std::string why;
  if (!writePlot(o.png, axes, series, why)) {
    std::fprintf(stderr, "tears-slide: %s\n", why.c_str());
    return false;
  }
  return true;
}

}  // namespace

int runTearsSlide(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  const SlidePhysics phys = slidePhysics(TearSettings{}, o.particles);
  if (!o.json) {
    std::printf(
        "tears-slide: a %d-particle drop on a flat plate, %zu angles, settle %d + measure "
        "%d frames at 22 fps ...\n",
        o.particles, o.angles.size(), o.settleFrames, o.measureFrames);
    std::fflush(stdout);
  }
  std::vector<Setting> settings;
  const std::vector<SolverEntry> solvers = sweepSolvers();  // outlives the settings' pointers
  for (const SolverEntry& solver : solvers)
    for (double lambda : o.substeps) {
      Setting s;
      s.solver = &solver;
      s.lambdaScale = lambda;
      for (double angle : o.angles) {
        SlideSetup setup;
        setup.angleDegrees = angle;
        setup.particles = o.particles;
        setup.settleFrames = o.settleFrames;
        setup.measureFrames = o.measureFrames;
        setup.solver = solver.key;
        setup.lambdaScale = lambda;
        setup.threads = o.threads;
        setup.trailLoss = o.trailLoss;
        s.runs.push_back(runSlide(setup));
      }
      fit(s, o);
      settings.push_back(std::move(s));
    }
  if (o.json)
    printJson(settings, phys, o);
  else
    printTable(settings, phys, o);
  if (!o.png.empty()) {
    if (!drawPlot(settings, phys, o)) return 1;
    if (!o.json) std::printf("  wrote %s\n", o.png.c_str());
  }
  return 0;
}

}  // namespace lacrima::bench
