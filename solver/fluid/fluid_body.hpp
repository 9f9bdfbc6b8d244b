// A weakly-compressible fluid body: its particles, resolution, material and numerical options.
#pragma once

#include "core/types.hpp"
#include "fluid/equation_of_state.hpp"
#include "fluid/reference_pressure.hpp"
#include "fluid/riemann_dissipation.hpp"
#include "kernel/lattice_moments.hpp"
#include "kernel/wendland_c2.hpp"
#include "neighbor/neighbor_list.hpp"
#include "particles/boundary_view.hpp"
#include "particles/fluid_particles.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace mrsph {

struct FluidMaterial {
  EquationOfState eos;
  Real viscosity = 0.0;  // dynamic viscosity mu (eta in the paper)
  Real rho0() const { return eos.rho0; }
  Real sound_speed() const { return eos.c0; }
};

enum class DensityReinitialisation {
  Internal,     // rho = rho_sum: confined flow (METHOD.md section 2)
  FreeSurface,  // rho = max(rho_sum, rho0): a truncated kernel near the surface must not lower rho
  Automatic,    // decided at initialisation (Simulation): FreeSurface under gravity, else Internal
  None,         // no summation: the density is what the continuity equation integrated
};

// The pressure the pair forces are measured from (reports/pressure.md):
//   Zero  p itself: a free surface, where p = 0 is the atmosphere
//   Mean  p minus the fluid's mean pressure: in a confined fluid the pressure level is set by the
//         particle count against the volume, not by the flow, and it grows as c^2; through the
//         zero-order error of the pressure gradient it would act as a spurious force
//   Linear p minus a least-squares linear fit of the fluid's pressure along its axes that are not
//         periodic, the fit's gradient applied exactly as a body force -V_i grad p_ref: a channel
//         between open boundaries, whose pressure level (the outlet's datum) and mean gradient
//         otherwise reach the flow through that same error, as a viscosity (reports/pressure.md
//         sections 29 and 30; fluid/reference_pressure.hpp)
enum class PressureReference { Zero, Mean, Linear, Automatic };

// How the viscous force's wall term continues the velocity into a boundary (wall_rules.hpp).
enum class ViscousWallVelocity { Linear, Mirrored, Quadratic };

// The paper's advection CFL number (Eq. 32), at which its transport-velocity shift is calibrated.
inline constexpr Real kPaperAdvectionCfl = 0.25;

struct FluidOptions {
  DensityReinitialisation density = DensityReinitialisation::Internal;
  PressureReference pressure_reference = PressureReference::Zero;
  // theta of the density re-initialisation once per advection step (Internal and FreeSurface),
  // rho <- rho + theta (rho_target - rho) (density_summation.hpp): 1, the paper's, replaces the
  // carried density by the summation; below 1 the summation pulls it towards itself by that
  // fraction, which filters the summation's response to the particles' arrangement
  // (reports/pressure.md section 11).
  Real density_relaxation = 1.0;
  Real transport_velocity_alpha = 0.0;  // 0: no transport-velocity correction
  // Initial particle relaxation (transport_velocity.hpp): this many shifts of the fluid particles
  // towards a uniform distribution before t = 0, walls and solids held still. 0: the lattice as cut.
  int relaxation_steps = 0;
  // Before the relaxation, each particle moved by a random offset of up to this fraction of dp in
  // x and y (seeded: runs stay reproducible): a perfect lattice is an equilibrium of the shift, so
  // relaxation alone leaves it a lattice, which a straining flow collapses (reports/pressure.md).
  Real relaxation_perturbation = 0.0;
  Real reference_velocity = 1.0;        // U_ref, a floor for the advection criterion
  // Divide the viscous operator by its lattice second moment (kernel/lattice_moments.hpp) so the
  // effective viscosity on a regular distribution is the physical one; off: the paper's code,
  // whose effective viscosity is 3.6 % low at h = 1.3 dp.
  bool viscous_lattice_correction = true;
  // Divide the pressure force by its lattice first moment M1 (kernel/lattice_moments.hpp), so a
  // linear pressure field on a regular distribution pushes with its gradient; off: the paper's
  // method, whose pressure force is 2.6 % weak at h = 1.3 dp (a flow driven by a pressure
  // difference runs 2.6 % slow; a still tank's pressure is 2.6 % high). Every pair force is scaled
  // alike, so momentum stays exact.
  bool pressure_lattice_correction = false;
  // With the correction above, divide by the mean first moment of the fluid's own arrangement
  // (particles with a full kernel support), measured at each density re-initialisation
  // (density_summation.hpp), instead of the square lattice's M1: a settled column is nearly
  // hexagonal (0.985-0.986), and the square lattice's 0.974 leaves its pressure 1.2 % low
  // (reports/pressure.md section 18). One number for the whole fluid: momentum stays exact.
  bool measured_pressure_moment = false;
  // The pressure pair force with each particle's kernel-gradient correction B = (sum_j V_j grad W_ij
  // (x) (r_j - r_i))^-1 (over the fluid and the boundaries, measured at each density
  // re-initialisation): -V_i V_j ((p_i - p_ref) B_i + (p_j - p_ref) B_j) grad W_ij, a boundary's
  // dummy with the fluid particle's B. Antisymmetric, so momentum stays exact. A linear pressure's
  // gradient is exact wherever the arrangement's zero-order residue vanishes (a lattice, stretched or
  // not), and a uniform pressure's stress is isotropic where B varies slowly, where the plain sum's
  // is the arrangement's moment tensor: on a sheared arrangement a shear stress in proportion to the
  // pressure's level (reports/pressure.md section 29). Replaces the lattice correction. Not the
  // summation energy's gradient: it does work no energy accounts for (an inviscid Taylor-Green vortex
  // gains 49 % kinetic energy over t = 3 L / U), so an option for diagnosis, off by default.
  bool pressure_gradient_correction = false;
  // delta of the delta-SPH density diffusion with Antuono's correction (density_diffusion.hpp),
  // in place of the Riemann pressure-difference term; 0: off (the paper's method).
  Real delta_sph = 0.0;
  // Evaluate the pressure pass's pair geometry (r, e, dW) at the positions of each acoustic step,
  // from the displacements since the list build; off: the paper's, cached at the build once per
  // advection step. Under a positive pressure the cached geometry feeds energy into the particle
  // motion at a rate that grows with p and with the advection step (reports/pressure.md section 9).
  bool refresh_pair_geometry = false;
  // The continuity pass's velocity divergence (and the Riemann momentum dissipation) at the positions of
  // each acoustic step too; off: cached, as the paper's. With the summation each advection step the
  // divergence's geometry does not enter (the density is replaced); with the continuity equation
  // carrying the density, the cached divergence is dissipative at first order in the advection step
  // and the cached pressure force anti-dissipative by about as much: the two on the same current
  // geometry give the Taylor-Green vortex 0.3-2.4 % of nu at every step (reports/pressure.md section 38).
  bool refresh_divergence_geometry = false;
  // The wall rule's pressure (wall_rules.hpp) continues the hydrostatic balance's rest state rho0 g
  // into the dummy particles whole and clips only the rest of the acceleration; off: the paper's
  // code, which clips the whole continuation, so that a dummy above a fluid particle (under a body,
  // beside a side wall) keeps the particle's pressure: a submerged cylinder's buoyancy 2.2-4.1 %
  // high at every c (reports/pressure.md section 19).
  bool rest_state_at_walls = false;
  // The viscous force's wall term (wall_rules.hpp): Linear (the default), the velocity continued
  // linearly through the wall, with which a channel's profile converges at second order instead of
  // 0.6 (reports/pressure.md section 20); Mirrored, the paper's 2 (v_i - vbar_a); Quadratic, continued
  // as a parabola whose curvature is the wall's momentum balance (reports/pressure.md section 34).
  ViscousWallVelocity viscous_wall_velocity = ViscousWallVelocity::Linear;
  // The continuity equation's wall term with the paper's mirrored velocity 2 (v_i - vbar_a); off:
  // v_i - vbar_a, the time derivative of the density summation's wall term (wall_rules.hpp), so that
  // the re-initialisation does not set the density back next to a moving body by a jump that grows
  // as c^2 (reports/pressure.md section 22). Left to the flow: on only where no summation
  // re-initialises the density (DensityReinitialisation::None).
  bool mirrored_wall_continuity = false;
  // The options above that the scene left to the flow (absent keys):
  // Simulation::resolve_automatic_fluid_options gives a fluid with a free surface the relaxed
  // summation, the corrected pressure force with its measured moment, the refreshed geometry and
  // the rest state continued into the walls, which together hold a still column's pressure to its
  // hydrostatic answer (reports/pressure.md sections 14 and 18); any other fluid keeps the values
  // above. Options built in code leave nothing to the flow.
  struct LeftToFlow {
    bool density_relaxation = false, pressure_lattice_correction = false, refresh_pair_geometry = false,
         rest_state_at_walls = false, measured_pressure_moment = false, mirrored_wall_continuity = false;
  } left_to_flow;
  Real advection_cfl = kPaperAdvectionCfl;  // paper Eq. 32
  // An upper bound on the advection step, for scenes whose observers must resolve what is faster
  // than the flow (an acoustic pulse: outputs are taken between advection steps, never by shortening
  // one). Infinite: the criterion alone.
  Real max_advection_step = std::numeric_limits<Real>::infinity();
  Real acoustic_cfl = 0.6;              // paper Eq. 33

  // Whether an acoustic pass evaluates pairs at the current positions, so that the positions at each
  // list build must be recorded.
  bool refreshes_pair_geometry() const { return refresh_pair_geometry || refresh_divergence_geometry; }

  // One advection step at this CFL as a fraction of the paper's step (CFL 0.25; the step is CFL h / U),
  // at most 1. The paper calibrated two once-per-step operations at its step: the transport-velocity
  // shift and the summation's reset of the density. Each is scaled by this fraction, so that below
  // CFL 0.25 its effect per unit time is the paper's, not 0.25 / CFL times it (reports/pressure.md
  // sections 35 and 41); at and above 0.25 the paper's per step is kept, bit for bit.
  Real paper_step_fraction() const { return std::min(1.0, advection_cfl / kPaperAdvectionCfl); }
};

struct FluidBody {
  std::string name;
  Real dp;
  WendlandC2 kernel;
  FluidMaterial material;
  FluidOptions options;
  RiemannDissipation riemann;
  FluidParticles particles;
  Real lattice_number_density;  // sigma0 for this dp and h
  Real lattice_laplacian;       // M2 for this dp and h, with the viscous regularisation 0.01 h
  Real lattice_gradient;        // M1 for this dp and h
  Real gradient_moment;         // what the pressure lattice correction divides by: M1, or measured
  ReferencePressure reference;  // p_ref(x), subtracted from p in the pair forces (PressureReference)
  Vec2 non_periodic_axes = Vec2::Ones();  // 1 along an axis that is not periodic (set by the simulation)
  Mat2Array gradient_correction;  // B_i of FluidOptions::pressure_gradient_correction
  Vec2Array density_gradient;     // <grad rho>^L of the delta-SPH diffusion, each acoustic step
  // With options.refresh_pair_geometry or refresh_divergence_geometry: positions at the list build,
  // and each particle's displacement since then (set before each pressure pass with
  // refresh_pair_geometry, and before each continuity pass with refresh_divergence_geometry).
  Vec2Array positions_at_list_build, moved_since_list_build;

  FluidBody(std::string body_name, Real spacing, Real h_over_dp)
      : name(std::move(body_name)), dp(spacing), kernel(h_over_dp * spacing),
        lattice_number_density(mrsph::lattice_number_density(kernel, spacing)),
        lattice_laplacian(lattice_laplacian_moment(kernel, spacing, viscous_regularisation())),
        lattice_gradient(lattice_gradient_moment(kernel, spacing)), gradient_moment(lattice_gradient) {}
  Real h() const { return kernel.h(); }
  Real viscous_regularisation() const { return 0.01 * kernel.h(); }  // paper Eq. 22
};

// The fluid's view of one boundary body (rigid wall or elastic solid): the pairs within the
// fluid's kernel support and, for each pair k, the force the boundary exerts on the fluid
// particle. The boundary feels -force of each of its pairs (Newton's third law, pair by pair).
struct FluidContact {
  std::string boundary_name;
  BoundaryView boundary;
  NeighborList pairs;                 // fluid particle i -> boundary particles a
  TransposedContacts pairs_of_boundary;
  Vec2Array pair_pressure_force;      // written every acoustic step (first half)
  Vec2Array pair_viscous_force;       // written once per advection step
  // Each fluid particle's distance above the boundary's surface, from its nearest boundary particle
  // (wall_rules.hpp), set with the viscous force; for the particles with pairs in this contact.
  RealArray fluid_distance;
  Vec2Array fluid_wall_normal;  // with it, that particle's normal (the wall's tangent for the quadratic rule)
  Vec2Array pair_dissipation_force;   // Riemann momentum dissipation, written in the second half
  // With the fluid's refresh_pair_geometry, for a moving boundary (boundary.pos set): its positions at
  // the list build, and its displacement since then (set before each pressure pass).
  Vec2Array boundary_positions_at_list_build, boundary_moved;
  // Force on each boundary particle from the dissipation of the previous second half. The fluid
  // applies that dissipation in the next acoustic step; so does the boundary. Indexed by boundary
  // particle, so it survives the rebuild of the pair list between advection steps.
  Vec2Array boundary_dissipation_reaction;
  // With PressureReference::Linear and a boundary immersed in the fluid (Simulation: an elastic solid,
  // or a wall within the bounding box of the fluid's particles), the fluid's grad p_ref: each boundary particle feels
  // -V_a grad p_ref beside its pairs, so that a closed body feels the linear field's exact
  // -V_body grad p_ref (reference_pressure.hpp). Else null: a wall that bounds the fluid has its
  // force measured from p_ref, as under the mean reference.
  const Vec2* reference_gradient = nullptr;
  // Momentum the fluid gave this boundary since the record was last cleared (by its reader: the
  // runner, after each observer record), its viscous part, and the time that covers: impulse /
  // duration is the force averaged over that time (the force observer's drag and lift), where the
  // pair forces above hold only the last acoustic step. Summing the pairs every acoustic step costs
  // a few percent of a step, so only contacts whose force is observed keep the record.
  bool records_impulse = false;
  Vec2 recorded_impulse = Vec2::Zero();
  Vec2 recorded_viscous_impulse = Vec2::Zero();
  Real recorded_duration = 0.0;
};

}  // namespace mrsph
