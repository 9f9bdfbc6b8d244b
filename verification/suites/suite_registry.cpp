#include "suites/suite.hpp"
#include "suites/antoci_suite.hpp"
#include "suites/convergence_suite.hpp"
#include "suites/fish_suite.hpp"
#include "suites/speed_accuracy_suite.hpp"
#include "suites/momentum_suite.hpp"
#include "suites/open_boundary_suite.hpp"
#include "suites/oscillating_plate_suite.hpp"
#include "suites/pressure_suite.hpp"
#include "suites/stability_suite.hpp"
#include "suites/turek_hron_suite.hpp"
#include "suites/valve_suite.hpp"
#include "suites/womersley_suite.hpp"

namespace mrsph::verification {

const std::vector<SuiteEntry>& registered_suites() {
  static const std::vector<SuiteEntry> suites{
      {"womersley", "periodic channel driven by an oscillating pressure gradient vs the analytic Womersley profile",
       run_womersley_suite},
      {"oscillating-plate", "cantilever plate in its first bending mode vs Euler-Bernoulli; convergence, energy, nu = 0.49",
       run_oscillating_plate_suite},
      {"momentum", "closed FSI box: total momentum for position- and velocity-based Verlet, multi- and single-step",
       run_momentum_suite},
      {"turek-hron", "FSI2 beam behind a cylinder (Re 100): cases I-IV (+V) vs Turek-Hron and the paper's Table 2",
       run_turek_hron_suite},
      {"antoci", "dam break through an elastic gate vs the Antoci experiment, cases I-IV; dry-bed dam break",
       run_antoci_suite},
      {"stability", "where each variant fails: kinematics, damping, schedules, time-step factors, Poisson ratio, ratios",
       run_stability_suite},
      {"convergence", "resolution ladders (plate, gate, FSI2): observed order, Richardson value, GCI; the paper's Table 3",
       run_convergence_suite},
      {"speed-accuracy", "wall time against error per configuration, the Pareto front, and the cheapest configuration per target",
       run_speed_accuracy_suite},
      {"valve", "venous valve leaflets in pulsatile Womersley flow, Wo = 1, 5, 10: period and amplitude of the leaflets",
       run_valve_suite},
      {"fish", "passively flapping tethered fish-like body: flapping frequency, amplitudes, Lissajous ratio, travelling wave",
       run_fish_suite},
      {"pressure", "pressure and forces: Turek-Hron CFD1-3 drag, lift, St at three resolutions and sound speeds; Schaefer-Turek 2D-1, 2D-2 (the cylinder alone): drag, front-to-rear pressure difference, lift, St, and 2D-1 against the outlet datum with the linear pressure reference; still water tank; a submerged cylinder's buoyancy; Taylor-Green vortex",
       run_pressure_suite},
      {"open-boundaries", "inlets and outlets: Poiseuille by a pressure difference, buffer mass balance, pulse reflection, open-channel start-up",
       run_open_boundary_suite},
  };
  return suites;
}

}  // namespace mrsph::verification
