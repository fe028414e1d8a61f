// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/pin_bushing_model.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "fe/boundary_compliance.h"
#include "fe/contact_solver.h"
#include "fe/elasticity_problem.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace wearlink::fe
{
  using namespace dealii;

  namespace
  {
    using wearlink::numbers::pi;

    using Clock = std::chrono::steady_clock;
    double
    seconds_since(Clock::time_point start)
    {
      return std::chrono::duration<double>(Clock::now() - start).count();
    }


    Tensor<1, 2>
    tensor(const std::array<double, 2> &a)
    {
      Tensor<1, 2> t;
      t[0] = a[0];
      t[1] = a[1];
      return t;
    }

    /** Wrap an angle to (−π, π]. */
    double
    wrap(double a)
    {
      return a - 2 * pi * std::ceil((a - pi) / (2 * pi));
    }

    /**
     * One edge of the contact zone along the coordinate @p x (ordered candidates):
     * the pressure of a frictionless contact of smooth profiles vanishes like
     * √(distance to the edge), so p² is linear there and is extrapolated to zero from
     * the two outermost active candidates, clamped between the last active and the
     * first inactive candidate.
     */
    double
    contact_edge(double x_last, double p_last, double x_inner, double p_inner, double x_outside)
    {
      const double p2_last = p_last * p_last, p2_inner = p_inner * p_inner;
      double       edge = 0.5 * (x_last + x_outside);
      if (p2_inner > p2_last)
        edge = x_last + p2_last * (x_last - x_inner) / (p2_inner - p2_last);
      const double lo = std::min(x_last, x_outside), hi = std::max(x_last, x_outside);
      return std::clamp(edge, lo, hi);
    }
  } // namespace


  class PinBushingModel::Impl
  {
  public:
    Impl(const contact::JointGeometry &geometry, const FeSettings &settings, const std::string &msh_path)
      : geometry(geometry)
      , meshed(geometry)
      , settings(settings)
      , msh_path(msh_path)
    {
      settings.check("the FE model settings");
      for (const auto *m : {&geometry.bushing, &geometry.pin_material})
        if (!(std::isfinite(m->youngs_modulus) && m->youngs_modulus > 0 && std::isfinite(m->poisson_ratio) &&
              m->poisson_ratio > -1 && m->poisson_ratio < 0.5))
          throw InputError("The FE model needs Young's moduli > 0 Pa and Poisson ratios in "
                           "(−1, 0.5) for both bodies.");
      if (!(std::isfinite(geometry.axial_length) && geometry.axial_length > 0))
        throw InputError("The axial length of the joint must be > 0 m.");

      MeshSpecification spec;
      spec.core_radius = settings.core_radius_fraction * geometry.pin.min_radius();
      spec.outer_radius =
        settings.outer_radius > 0 ? settings.outer_radius : settings.outer_radius_ratio * geometry.bore.mean_radius();
      spec.surface_element_size = settings.surface_element_size;
      spec.max_element_size     = settings.max_element_size;
      spec.size_growth          = settings.size_growth;
      spec.layer_thickness      = settings.refined_layer_thickness;
      spec.refined_half_angle   = settings.refined_arc_half_angle;
      spec.bore_refined_centre  = settings.refined_arc_bore_centre;
      spec.pin_refined_centre   = settings.refined_arc_pin_centre;
      check_pin_bushing_geometry(geometry.bore, geometry.pin, spec);

      // Under MPI every rank holds the whole mesh (replicated, partitioned by METIS
      // for the distributed reference solver); rank 0 writes it, the others wait.
      const unsigned int n_ranks = settings.distribute_reference ? Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
      auto               start   = Clock::now();
      if (n_ranks == 1 || Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        stats.mesh = write_pin_bushing_mesh(geometry.bore, geometry.pin, spec, msh_path);
      if (n_ranks > 1)
        MPI_Barrier(MPI_COMM_WORLD);
      stats.mesh_time = seconds_since(start);
      start           = Clock::now();
      problem         = std::make_unique<ElasticityProblem>(msh_path,
                                                    settings.degree,
                                                    settings.refinements,
                                                    geometry.pin_material,
                                                    geometry.bushing,
                                                    geometry.pin,
                                                    geometry.bore,
                                                    n_ranks);
      problem->run();
      stats.assembly_time     = seconds_since(start);
      stats.n_dofs            = problem->dof_handler.n_dofs();
      stats.n_pin_candidates  = problem->pin_nodes.size();
      stats.n_bore_candidates = problem->bore_nodes.size();
      reference = std::make_unique<ReferenceContactSolver>(*problem, settings.max_active_set_iterations, n_ranks > 1);
    }

    void
    prepare_condensed()
    {
      if (compliance)
        return;
      const auto start = Clock::now();
      compliance = std::make_unique<BoundaryCompliance>(*problem, stats.mesh.pin_sectors, stats.mesh.bore_sectors);
      stats.factorization_time = seconds_since(start);
      condensed                = std::make_unique<CondensedContactSolver>(*problem,
                                                           *compliance,
                                                           settings.max_active_set_iterations,
                                                           settings.primal_dual_iterations);
    }

    // Force control: the pin starts where a rigid pin pushed by the load rests
    // (rigid_rest_position(): on round profiles the radial gap along the load, in a worn
    // pocket off the load's line, where the contact faces the load) plus the predicted elastic
    // approach (predicted_approach(): deterministic, so that a state's result does not
    // depend on what was solved before), and the solver finds the elastic translation U
    // from there. The gap is linearized in U; the gaps are refreshed about e + U with the
    // contact pairing of the first pose (refresh_gaps()) and the state solved again until
    // relinearization_done(). Both solvers take this same path.
    ContactResult
    solve(const LoadCase &load, SolverKind kind, const std::string &vtu_path, const bool all_angles)
    {
      const auto start = Clock::now();
      if (kind == SolverKind::condensed)
        prepare_condensed();
      const double L              = geometry.axial_length;
      const double relative_angle = load.pin_angle - load.bushing_angle;
      const bool   force_control  = load.control == Control::force;
      Tensor<1, 2> P, e;
      double       closure = 0;
      if (force_control)
        {
          const Tensor<1, 2> F = rotate(tensor(load.load), -load.bushing_angle);
          if (!(F.norm() > 0) || !std::isfinite(F.norm()))
            throw InputError("A force-controlled load state needs a finite, non-zero load.");
          P       = F / L;
          closure = predicted_approach(P.norm(),
                                       problem->effective_modulus(),
                                       geometry.bore.mean_radius() - geometry.pin.mean_radius()) +
                    wear_closure(load.wear_compliance, P.norm());
          const Tensor<1, 2> d = F / F.norm();
          e                    = rigid_rest_position(geometry.bore, geometry.pin, relative_angle, d) + closure * d;
        }
      else
        e = rotate(tensor(load.eccentricity), -load.bushing_angle);

      PinPose pose;
      pose.bore           = &geometry.bore;
      pose.relative_angle = relative_angle;
      pose.eccentricity   = e;
      pose.pin_offsets    = pin_offsets.empty() ? nullptr : &pin_offsets;
      ContactKinematics kin;
      if (load.wear_compliance > 0)
        {
          AssertThrow(kind == SolverKind::condensed && force_control,
                      ExcMessage("A load state's wear compliance needs the condensed solver under force control."));
          std::vector<double> diagonal(problem->pin_nodes.size());
          for (unsigned int i = 0; i < diagonal.size(); ++i)
            diagonal[i] = load.wear_compliance / problem->pin_nodes[i].weight;
          condensed->set_wear_diagonal(std::move(diagonal));
        }
      ContactSolution sol;
      try
        {
          sol = kind == SolverKind::condensed ? condensed->solve(pose, force_control, P, closure, kin) :
                                                reference_solve(pose, force_control, P, kin);
        }
      catch (...)
        {
          if (condensed)
            condensed->set_wear_diagonal({});
          throw;
        }
      if (load.wear_compliance > 0)
        condensed->set_wear_diagonal({});
      ++n_solves;
      ContactResult r = result(load, kin, sol, e);
      r.iterations    = sol.iterations;
      if (all_angles || !vtu_path.empty())
        r.bore_angle = compute_kinematics(*problem, pose).bore_angle;
      if (!vtu_path.empty())
        {
          const Vector<double> u =
            kind == SolverKind::reference ? sol.displacement : condensed->displacement_field(kin, sol);
          problem->output_results(u, vtu_path, &contact_traction(r, u.size()));
        }
      r.solve_time = seconds_since(start);
      return r;
    }

    // The pin surface's contact pressure × its outward normal on the pin nodes' DoFs,
    // for the VTU (the bore carries the same forces, spread over the faces the rays
    // meet; the pin side shows the pressure at its own nodes).
    const Vector<double> &
    contact_traction(const ContactResult &r, const std::size_t n_dofs)
    {
      traction.reinit(n_dofs);
      for (unsigned int i = 0; i < problem->pin_nodes.size() && i < r.pressure.size(); ++i)
        for (unsigned int d = 0; d < 2; ++d)
          traction[problem->pin_nodes[i].dofs[d]] = r.pressure[i] * problem->pin_nodes[i].normal[d];
      return traction;
    }

    // How much deeper the pin goes into surfaces that wear by c p during the state: the
    // worn depth under the mean pressure of the nominal Hertz strip, c P/(2b). An
    // estimate for the start and the first window only (the window widens if the
    // solution needs it).
    double
    wear_closure(const double c, const double line_load) const
    {
      if (!(c > 0))
        return 0;
      const double r1 = geometry.bore.mean_radius(), r2 = geometry.pin.mean_radius();
      const double b = std::sqrt(4 * line_load * r1 * r2 / (r1 - r2) / (numbers::pi * problem->effective_modulus()));
      return c * line_load / (2 * b);
    }

    // The reference solver's path: every candidate, the same linearizations and
    // pairings as the condensed solver's (CondensedContactSolver::solve()).
    ContactSolution
    reference_solve(const PinPose &pose, const bool force_control, const Tensor<1, 2> &P, ContactKinematics &kin) const
    {
      PinPose paired = pose, moved = pose;
      kin = compute_kinematics(*problem, paired);
      Tensor<1, 2>    U_pair;
      ContactSolution sol;
      unsigned int    iterations = 0;
      const double    R = smallest_pin_radius(*problem), spacing = candidate_spacing(*problem);
      for (unsigned int update = 1;; ++update)
        {
          sol = reference->solve(kin, force_control, P);
          iterations += sol.iterations;
          U_pair += sol.pin_translation;
          const bool done = relinearization_done(sol.pin_translation, R);
          if (!force_control || (done && !pairing_off_the_solution(U_pair, P / P.norm(), spacing)) ||
              update >= max_relinearizations)
            break;
          if (done || pairing_outdated(U_pair, spacing))
            {
              paired.eccentricity += U_pair;
              U_pair = 0;
              kin    = compute_kinematics(*problem, paired);
              continue;
            }
          moved.eccentricity = paired.eccentricity + U_pair;
          refresh_gaps(*problem, moved, kin);
        }
      sol.last_translation = sol.pin_translation;
      sol.pin_translation  = paired.eccentricity - pose.eccentricity + U_pair;
      sol.iterations       = iterations;
      return sol;
    }

    // The per-candidate arrays (zero force and NaN bore angle outside the kinematics'
    // window), the resultant, the equilibrium residual and the contact extent.
    ContactResult
    result(const LoadCase &load, const ContactKinematics &kin, const ContactSolution &sol, const Tensor<1, 2> &e) const
    {
      ContactResult r;
      r.monotone               = sol.monotone;
      r.n_active               = sol.n_active;
      const auto        &nodes = problem->pin_nodes;
      const unsigned int m     = nodes.size();
      const double       L     = geometry.axial_length;
      r.pin_angle.resize(m);
      r.bore_angle.assign(m, std::numeric_limits<double>::quiet_NaN());
      r.pressure.assign(m, 0.0);
      r.force.assign(m, 0.0);
      for (unsigned int i = 0; i < m; ++i)
        r.pin_angle[i] = nodes[i].angle;
      for (unsigned int p = 0; p < kin.candidates.size(); ++p)
        {
          const unsigned int i = kin.candidates[p];
          r.bore_angle[i]      = kin.bore_angle[p];
          r.pressure[i]        = sol.lambda[p] / nodes[i].weight;
          r.force[i]           = sol.lambda[p] * L;
          r.peak_pressure      = std::max(r.peak_pressure, r.pressure[i]);
        }
      const Tensor<1, 2> resultant = rotate(sol.resultant * L, load.bushing_angle);
      const Tensor<1, 2> ecc       = rotate(e + sol.pin_translation, load.bushing_angle);
      r.resultant                  = {{resultant[0], resultant[1]}};
      r.pin_displacement           = {{ecc[0], ecc[1]}};
      if (load.control == Control::force)
        r.equilibrium_relative_residual = (resultant - tensor(load.load)).norm() / tensor(load.load).norm();
      contact_extent(kin, sol, r);
      return r;
    }

    // Half-angle (seen from the bore centre) and half-width (arc length along the pin)
    // of the contact zone, measured about the direction of the resultant, with the
    // edges extrapolated as in contact_edge().
    void
    contact_extent(const ContactKinematics &kin, const ContactSolution &sol, ContactResult &r) const
    {
      if (sol.resultant.norm() == 0)
        return;
      const double        direction = std::atan2(sol.resultant[1], sol.resultant[0]);
      const unsigned int  w         = kin.candidates.size();
      std::vector<double> beta(w), s(w), p(w);
      for (unsigned int q = 0; q < w; ++q)
        {
          const auto &node = problem->pin_nodes[kin.candidates[q]];
          beta[q]          = wrap(kin.bore_angle[q] - direction);
          const double psi = wrap(node.angle - (direction - kin.relative_angle));
          s[q]             = psi * geometry.pin.radius(node.angle);
          p[q]             = r.pressure[kin.candidates[q]];
        }
      std::vector<unsigned int> order(w);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) { return beta[a] < beta[b]; });
      int first = -1, last = -1;
      for (unsigned int k = 0; k < w; ++k)
        if (sol.lambda[order[k]] > 0)
          {
            if (first < 0)
              first = k;
            last = k;
          }
      if (first < 0)
        return;
      auto edge = [&](int k_last, int k_inner, int k_out, const std::vector<double> &x) {
        const auto at = [&](int k) {
          return order[std::clamp(k, 0, static_cast<int>(w) - 1)];
        };
        return contact_edge(x[at(k_last)], p[at(k_last)], x[at(k_inner)], p[at(k_inner)], x[at(k_out)]);
      };
      const bool   single      = first == last;
      const int    inner_right = single ? last : last - 1;
      const int    inner_left  = single ? first : first + 1;
      const double beta_r      = edge(last, inner_right, last + 1, beta);
      const double beta_l      = edge(first, inner_left, first - 1, beta);
      const double s_r         = edge(last, inner_right, last + 1, s);
      const double s_l         = edge(first, inner_left, first - 1, s);
      r.half_angle             = 0.5 * (beta_r - beta_l);
      r.half_width             = 0.5 * (s_r - s_l);
    }

    // Tributary arcs of the nodal forces, collected on the discrete areas of each
    // profile.
    contact::SurfacePressure
    surface_pressure(const ContactResult &r) const
    {
      contact::SurfacePressure out;
      const unsigned int       m       = r.force.size();
      auto                     collect = [&](const std::vector<double> &angle, const Profile &profile) {
        const unsigned int  n  = profile.n_points();
        const double        da = 2 * pi / n;
        std::vector<double> p(n, 0.0);
        for (unsigned int i = 0; i < m; ++i)
          if (r.force[i] > 0)
            {
              const double a  = angle[i];
              const double lo = a - 0.5 * std::abs(wrap(a - angle[(i + m - 1) % m]));
              const double hi = a + 0.5 * std::abs(wrap(angle[(i + 1) % m] - a));
              if (!(hi > lo))
                continue;
              // Areas k whose interval [ψ_k − da/2, ψ_k + da/2] may overlap [lo, hi].
              const long k0 = static_cast<long>(std::floor((lo + 0.5 * da) / da)) - 1;
              const long k1 = static_cast<long>(std::floor((hi + 0.5 * da) / da)) + 1;
              for (long k = k0; k <= k1; ++k)
                {
                  const double a0 = k * da - 0.5 * da, a1 = a0 + da;
                  const double overlap = std::min(hi, a1) - std::max(lo, a0);
                  if (overlap > 0)
                    p[((k % long(n)) + n) % n] += r.force[i] * overlap / (hi - lo);
                }
            }
        for (unsigned int k = 0; k < n; ++k)
          p[k] /= geometry.axial_length * profile[k] * da;
        return p;
      };
      out.pin  = collect(r.pin_angle, geometry.pin);
      out.bore = collect(r.bore_angle, geometry.bore);
      return out;
    }

    // Profiles since the mesh was made: the bore enters the gaps exactly (its profile is
    // what the rays meet), the pin through a radial offset of each candidate.
    void
    update_profiles(const Profile &bore, const Profile &pin)
    {
      if (bore.n_points() != meshed.bore.n_points() || pin.n_points() != meshed.pin.n_points())
        throw InputError("The FE model's profiles can only be updated by profiles with the same number of samples (" +
                         std::to_string(meshed.bore.n_points()) + " bore, " + std::to_string(meshed.pin.n_points()) +
                         " pin).");
      if (bore.samples() == geometry.bore.samples() && pin.samples() == geometry.pin.samples())
        return;
      geometry.bore = bore;
      geometry.pin  = pin;
      pin_offsets.clear();
      if (pin.samples() == meshed.pin.samples())
        return;
      pin_offsets.resize(problem->pin_nodes.size());
      for (unsigned int i = 0; i < pin_offsets.size(); ++i)
        {
          const double angle = problem->pin_nodes[i].angle;
          pin_offsets[i]     = pin.radius(angle) - meshed.pin.radius(angle);
        }
    }

    contact::JointGeometry                  geometry; ///< current profiles
    const contact::JointGeometry            meshed;   ///< profiles of the mesh
    const FeSettings                        settings;
    const std::string                       msh_path;
    std::vector<double>                     pin_offsets; ///< current − meshed pin radius per candidate (empty: none)
    Vector<double>                          traction;    ///< scratch of contact_traction()
    SetupStatistics                         stats;
    std::unique_ptr<ElasticityProblem>      problem;
    std::unique_ptr<BoundaryCompliance>     compliance;
    std::unique_ptr<CondensedContactSolver> condensed;
    std::unique_ptr<ReferenceContactSolver> reference;
    unsigned long                           n_solves = 0;
  };


  PinBushingModel::PinBushingModel(const contact::JointGeometry &geometry,
                                   const FeSettings             &settings,
                                   const std::string            &msh_path)
    : impl(std::make_unique<Impl>(geometry, settings, msh_path))
  {
  }

  PinBushingModel::~PinBushingModel()
  {
    if (impl && impl->n_solves > 0)
      EffectLedger::instance().add_calls("fe solves", impl->n_solves);
  }

  ContactResult
  PinBushingModel::solve(const LoadCase &load, SolverKind solver, const std::string &vtu_path, const bool all_angles)
  {
    return impl->solve(load, solver, vtu_path, all_angles);
  }

  void
  PinBushingModel::prepare_condensed()
  {
    impl->prepare_condensed();
  }

  void
  PinBushingModel::precompute_compliance()
  {
    impl->prepare_condensed();
    impl->compliance->precompute_all();
  }

  bool
  PinBushingModel::compliance_is_periodic()
  {
    impl->prepare_condensed();
    return impl->compliance->pin_periodic() && impl->compliance->bore_periodic();
  }

  double
  PinBushingModel::compliance_time() const
  {
    return impl->compliance ? impl->compliance->column_time() : 0.0;
  }

  const CondensedTimings &
  PinBushingModel::condensed_timings() const
  {
    static const CondensedTimings none;
    return impl->condensed ? impl->condensed->timings() : none;
  }

  unsigned long
  PinBushingModel::n_compliance_solves() const
  {
    return impl->compliance ? impl->compliance->n_back_substitutions() : 0;
  }

  void
  PinBushingModel::update_profiles(const Profile &bore, const Profile &pin)
  {
    impl->update_profiles(bore, pin);
  }

  double
  PinBushingModel::profile_drift(const Profile &bore, const Profile &pin) const
  {
    const auto &m = impl->meshed;
    if (bore.n_points() != m.bore.n_points() || pin.n_points() != m.pin.n_points())
      return std::numeric_limits<double>::infinity();
    double drift = 0;
    for (unsigned int k = 0; k < bore.n_points(); ++k)
      drift = std::max(drift, std::abs(bore[k] - m.bore[k]));
    for (unsigned int k = 0; k < pin.n_points(); ++k)
      drift = std::max(drift, std::abs(pin[k] - m.pin[k]));
    return drift;
  }

  const contact::JointGeometry &
  PinBushingModel::meshed_geometry() const
  {
    return impl->meshed;
  }

  const contact::JointGeometry &
  PinBushingModel::current_geometry() const
  {
    return impl->geometry;
  }

  const std::string &
  PinBushingModel::mesh_path() const
  {
    return impl->msh_path;
  }

  const SetupStatistics &
  PinBushingModel::statistics() const
  {
    return impl->stats;
  }

  contact::SurfacePressure
  PinBushingModel::surface_pressure(const ContactResult &result) const
  {
    return impl->surface_pressure(result);
  }
} // namespace wearlink::fe
