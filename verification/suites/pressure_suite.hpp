// verify --suite pressure: the fluid's pressure and the forces it puts on bodies, against answers
// that do not come from SPH (reports/pressure.md).
//   Turek & Hron CFD1-CFD3 (Re = 20, 100 steady; 200 periodic): drag, lift, Strouhal number on a
//     resolution ladder and at three sound speeds (the incompressible limit must not depend on c)
//   still water tank: pressure against rho g (H - y) after settling, and its noise
//   a cylinder under the surface of still water: its buoyancy against Archimedes, at four sound speeds
//   Taylor-Green vortex: velocity decay and the pressure field against the analytic solution
#pragma once

#include "run/runner.hpp"
#include "suites/suite.hpp"

#include <cmath>
#include <limits>

#include <string>

namespace mrsph::verification {

SuiteSummary run_pressure_suite(const SuiteContext& ctx);

// One Turek & Hron cylinder benchmark (CFD1-3) and one run of it (pressure_suite.cpp).
struct BenchmarkCase {
  std::string name;
  double reynolds;
  double end_time;
  double window_start;  // the flow has settled (steady, or shedding at its own period)
  bool shedding;        // CFD3
};

struct CylinderRun {
  const BenchmarkCase* benchmark;
  int resolution;          // D / dp
  int sound_speed_factor;  // c / U0
  SuiteRun record;
  std::string scene = "turek_hron_cfd.json";  // or turek_hron_cfd_open.json, the benchmark's channel
};

// Runs it and fills its record: drag and lift means over the window; for CFD3 also St and the
// lift and drag amplitudes.
void run_cylinder(const SuiteContext& ctx, CylinderRun& out);

// The parts, each adding its runs, checks and tables to the summary (pressure_fields.cpp holds
// the tank and the vortex).
void run_cylinder_benchmarks(const SuiteContext& ctx, SuiteSummary& summary);
void run_hydrostatic_tank(const SuiteContext& ctx, SuiteSummary& summary);
void run_submerged_cylinder(const SuiteContext& ctx, SuiteSummary& summary);  // pressure_buoyancy.cpp
void run_taylor_green(const SuiteContext& ctx, SuiteSummary& summary);

// Shared by the parts: the mean and standard deviation of one column of an observer's series over
// (start, end], each sample weighted by the time since the previous one (the observer samples every
// advection step; a step cut short to land on the end time weighs little);
struct WindowStats {
  double mean = NAN, std = NAN;
};
WindowStats window_stats(const ObserverSeries& s, std::size_t column, double start,
                         double end = std::numeric_limits<double>::infinity());
// a run's metric (NaN if the run diverged or did not measure it), and checks that record a missing
// value as a failed check.
double run_metric(const SuiteRun& run, const std::string& name);
void check_at_most_or_missing(SuiteSummary& summary, const std::string& name, double value, double limit,
                              const std::string& source);
// |value - reference| <= tolerance |reference|
void check_relative_or_missing(SuiteSummary& summary, const std::string& name, double value, double reference,
                               double tolerance, const std::string& source);

}  // namespace mrsph::verification
