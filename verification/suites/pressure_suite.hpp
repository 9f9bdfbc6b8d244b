// verify --suite pressure: the fluid's pressure and the forces it puts on bodies, against answers
// that do not come from SPH (reports/pressure.md).
//   Turek & Hron CFD1-CFD3 (Re = 20, 100 steady; 200 periodic): drag, lift, Strouhal number on a
//     resolution ladder and at three sound speeds (the incompressible limit must not depend on c)
//   Schaefer & Turek 2D-1 and 2D-2 (the cylinder without the beam, Re = 20 steady, 100 periodic):
//     drag, lift, St and the pressure difference between the cylinder's front and rear points; 2D-1's
//     drag with the linear pressure reference against the outlet's datum
//   still water tank: pressure against rho g (H - y) after settling, and its noise
//   a cylinder under the surface of still water: its buoyancy against Archimedes, at four sound speeds
//   Taylor-Green vortex: velocity decay and the pressure field against the analytic solution
#pragma once

#include "run/runner.hpp"
#include "suites/suite.hpp"

#include <cmath>
#include <limits>

#include <string>
#include <vector>

namespace mrsph::verification {

SuiteSummary run_pressure_suite(const SuiteContext& ctx);

// One cylinder benchmark (Turek & Hron's CFD1-3, Schaefer & Turek's 2D-1 and 2D-2) and one run of it
// (pressure_suite.cpp).
struct BenchmarkCase {
  std::string name;
  double reynolds;
  double end_time;
  double window_start;  // the flow has settled (steady, or shedding at its own period)
  bool shedding;        // CFD3, 2D-2
  // The band of Strouhal numbers the shedding component of the lift is taken from (CFD3's: 0.1-0.35,
  // the reason beside add_shedding_component in pressure_suite.cpp).
  double shedding_band_low = 0.1, shedding_band_high = 0.35;
};

struct CylinderRun {
  const BenchmarkCase* benchmark;
  int resolution;          // D / dp
  int sound_speed_factor;  // c / U0
  SuiteRun record;
  std::string scene = "turek_hron_cfd.json";  // or turek_hron_cfd_open.json, the benchmark's channel;
                                               // schaefer_turek_cylinder.json for 2D-1 and 2D-2
  // A run beside the ladder: its name (empty on the ladder) and the scene overrides that make it.
  std::string variant = {};
  std::vector<std::string> overrides = {};
};

// Runs it and fills its record: drag and lift means over the window; for CFD3 and 2D-2 also St and
// the lift and drag amplitudes; where the scene observes the pressure at points "front" and "rear",
// their difference's mean.
void run_cylinder(const SuiteContext& ctx, CylinderRun& out);

// The runs of one part, looked up by benchmark, D/dp and c / U0 (NaN for a run or metric that is absent).
class CylinderResults {
 public:
  explicit CylinderResults(const std::vector<CylinderRun>& runs) : runs_(runs) {}
  const CylinderRun* find(const std::string& benchmark, int resolution, int factor, const std::string& variant = {}) const;
  double value(const std::string& benchmark, int resolution, int factor, const std::string& name,
               const std::string& variant = {}) const;

 private:
  const std::vector<CylinderRun>& runs_;
};

// The drag at c = factor U0 against c = against U0, relative difference at most `tolerance`.
void check_sound_speed_independence(SuiteSummary& summary, const CylinderResults& results, const std::string& benchmark,
                                    int resolution, int factor, int against, double tolerance, const std::string& source);
// Each metric of each case on the ladder at c = factor U0, with observed order, Richardson value
// and GCI where the ladder has three rungs.
Json convergence_table(const CylinderResults& results, const std::vector<BenchmarkCase>& cases, const std::vector<int>& ladder,
                       int factor);

// The parts, each adding its runs, checks and tables to the summary (pressure_fields.cpp holds
// the tank and the vortex).
void run_cylinder_benchmarks(const SuiteContext& ctx, SuiteSummary& summary);
void run_schaefer_turek(const SuiteContext& ctx, SuiteSummary& summary);  // pressure_schaefer_turek.cpp
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
