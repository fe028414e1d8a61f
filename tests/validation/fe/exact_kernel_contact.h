// SPDX-License-Identifier: LGPL-2.1-or-later
// An independent reference for the FE contact model of a pin in a bushing: the same
// continuum problem (plane strain, small strain, frictionless unilateral contact, pin
// annulus bonded to a rigid core that translates under force control, bushing ring
// clamped on its outer edge, exact rigid gap of the two circles along the pin normal)
// solved with exact Fourier (Michell) kernels of the two rings instead of finite
// elements. No deal.II, no gmsh, no code from src/: only the standard library and Eigen.
// The method, its equations and its measured convergence are described at the top of
// exact_kernel_contact.cc; the checks are in exact_kernel_selftest.cc.
#pragma once

#include <array>
#include <vector>

namespace wearlink::validation
{
  /** The pin–bushing pair (SI units). */
  struct ExactKernelPair
  {
    double bore_radius  = 12e-3;   ///< R1, radius of the bore [m]
    double pin_radius   = 11.5e-3; ///< R2, radius of the pin [m]
    double core_radius  = 4.6e-3;  ///< r_c, radius of the pin's rigid core [m]
    double outer_radius = 24e-3;   ///< R_o, clamped outer radius of the bushing ring [m]
    double axial_length = 10e-3;   ///< L: a force F [N] is the load F / L per unit length [m]
    double E_bushing    = 207e9;   ///< [Pa]
    double nu_bushing   = 0.3;
    double E_pin        = 207e9; ///< [Pa]
    double nu_pin       = 0.3;
  };

  /**
   * Discretization parameters. The defaults give peak pressure and half-angle within
   * 0.1 % of the grid-converged values for 100 N … 100 kN on the steel pair (see the
   * convergence table in exact_kernel_contact.cc).
   */
  struct ExactKernelOptions
  {
    /** Pressure nodes on each side of the load direction (uniform in the pin angle ψ). */
    unsigned int nodes_per_half_window = 256;
    /** Half-width of the pressure window in ψ [rad]; 0: automatic (window_factor × a coarse estimate). */
    double window_half_angle = 0;
    /** Automatic window: this factor times the contact half-angle (ψ) of a coarse solve. */
    double window_factor = 1.25;
    /** Nodes per half window of that coarse solve. */
    unsigned int coarse_nodes = 40;
    /**
     * Pairing of the pin node with its bore point. false (the FE model's): along the ray
     * of the pin normal, which carries the gap and the contact force. true: the closest
     * bore point, with the bore normal (for the study of the modelling choice only).
     */
    bool closest_point_pairing = false;
    /** Gauss points per element for the regular part of the influence integrals. */
    unsigned int quadrature_points = 3;
    /** Re-linearize the gap until the pin moves by less than this times the approach. */
    double       relinearization_tolerance = 1e-6;
    unsigned int max_relinearizations      = 20;
    /** Keep finite-ring correction modes until they are this small relative to the ring's compliance. */
    double mode_tolerance = 1e-12;
    /** Upper bound on the finite-ring correction modes (a cap below the tolerance truncates them). */
    unsigned int max_correction_modes = 400;
  };

  /** The solution of one load state. Angles are global polar angles [rad]. */
  struct ExactKernelResult
  {
    double peak_pressure = 0; ///< [Pa] (force per unit contact arc and axial length)
    double half_angle    = 0; ///< half the contact arc seen from the bore centre [rad]
    double half_width    = 0; ///< half the contact arc length along the pin surface [m]
    /** |e| − c: pin-core position beyond the rigid contact position (overlap of the rigid circles) [m]. */
    double approach = 0;
    /** (e − e0)·d: core translation along the load from the rigid contact position e0 = c d [m]. */
    double elastic_approach = 0;
    /** Sum of the elastic normal displacements (bore − pin) at the contact centre node [m]. */
    double                      centre_compression = 0;
    std::array<double, 2>       resultant{};        ///< L ∫ p n ds over the pin surface (n outward) [N]
    std::array<double, 2>       pin_displacement{}; ///< pin centre − bore centre [m]
    std::vector<double>         pin_angle;          ///< node angles about the pin centre [rad]
    std::vector<double>         bore_angle;         ///< angle of each node's contact point about the bore centre [rad]
    std::vector<double>         pressure;           ///< nodal pressure [Pa]
    double                      window_half_angle = 0; ///< ψ window used [rad]
    unsigned int                iterations        = 0; ///< active-set iterations, summed over re-linearizations
    unsigned int                relinearizations  = 0; ///< gap linearizations (kinematic updates)
    std::array<unsigned int, 2> correction_modes{};    ///< finite-ring correction modes kept (pin, bushing)
    double                      solve_time = 0;        ///< wall time [s]
  };

  /**
   * Solve the frictionless contact of the pin pushed by @p force_N [N] along the global
   * direction @p load_direction_rad into the bore. Throws std::runtime_error if the
   * contact solver or the re-linearization does not converge.
   */
  ExactKernelResult
  solve_exact_kernel_contact(const ExactKernelPair    &pair,
                             double                    force_N,
                             double                    load_direction_rad,
                             const ExactKernelOptions &options = {});

  /** An elastic ring a ≤ r ≤ b loaded on one edge and held (u = 0) on the other. */
  struct ElasticRing
  {
    double inner_radius   = 0;
    double outer_radius   = 0;
    double E              = 0;
    double nu             = 0;
    bool   loaded_outside = true; ///< true: pin on its core; false: bushing loaded in the bore
  };

  /**
   * Surface compliance of Fourier mode n on the loaded edge R: the applied traction
   * (T_r, T_θ) = (cos nθ, 0) gives (u_r, u_θ) = (rr cos nθ, tr sin nθ), and
   * (0, sin nθ) gives (rt cos nθ, tt sin nθ). For n = 0, tr = rt = 0 and tt is the
   * torsional compliance (uniform T_θ). [m per Pa]
   */
  struct ModeCompliance
  {
    double rr = 0, rt = 0, tr = 0, tt = 0;
  };

  /** Amplitudes of mode n at one radius: u_r = u_r cos nθ, u_θ = u_t sin nθ, σ_rr, σ_rθ likewise. */
  struct ModeState
  {
    double u_r = 0, u_t = 0, s_rr = 0, s_rt = 0;
  };

  /** Exact (Michell) response of @p ring to the loaded-edge traction (T_r cos nθ, T_θ sin nθ), at radius @p r. */
  ModeState
  ring_mode_state(const ElasticRing &ring, unsigned int n, double traction_r, double traction_t, double r);

  /** ring_mode_state() on the loaded edge for unit radial and tangential tractions. */
  ModeCompliance
  ring_mode_compliance(const ElasticRing &ring, unsigned int n);

  /**
   * Displacement of the loaded edge at angle @p delta from a unit point force (per unit
   * length) applied at angle 0, from the closed-form kernel: {K_rr, K_θr, K_θθ} with
   * (u_r, u_θ) = (K_rr f_r − K_θr f_θ, K_θr f_r + K_θθ f_θ) [m per N/m].
   */
  std::array<double, 3>
  ring_point_force_response(const ElasticRing &ring, double delta, const ExactKernelOptions &options = {});
} // namespace wearlink::validation
