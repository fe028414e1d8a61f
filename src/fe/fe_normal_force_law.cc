// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/fe_normal_force_law.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/timings.h"
#include "contact/gap.h"
#include "contact/hertz.h"
#include "fe/fe_conformal_table.h"
#include "fe/model_pool.h"
#include "fe/pin_bushing_model.h"
#include "fe/table_cache.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>

namespace wearlink::fe
{
  namespace
  {
    using numbers::pi;
    using numbers::two_pi;

    constexpr const char *cache_format = "wearlink-fe-force-approach-table";
    constexpr int cache_version        = 4; // 3: round pairs on the periodic shared mesh; 4: re-pairing of sliding pins
    /**
     * Half-angle of the refined arc of a round pair's mesh, centred on the one tabulated
     * direction [rad]: 1.5 × the Hertz half-angle b/R1 at the largest load plus 0.2 rad
     * (11°) for the stresses beyond the arc's ends, at most π. Hertz's b overestimates
     * the arc of a conforming pair (measured: 23.4° FE against 26.5° Hertz at 100 kN for
     * R1 = 12 mm, c = 0.5 mm, L = 10 mm), so the contact never leaves the refined arc.
     */
    double
    round_refined_half_angle(const contact::JointGeometry &g, const double max_force)
    {
      const double R1 = g.bore.mean_radius(), R2 = g.pin.mean_radius();
      const double b = contact::hertz_line_contact(max_force / g.axial_length,
                                                   R1 * R2 / (R1 - R2),
                                                   contact::effective_modulus(g.bushing, g.pin_material))
                         .half_width;
      return std::min(pi, 1.5 * b / R1 + 0.2);
    }

    /** The cached table for @p key, or an empty one (missing, damaged, other key). */
    contact::ForceApproachTable
    read_cached(const std::string &file, const std::string &key, TableBuild &build)
    {
      const Json j = read_table_cache(file, cache_format, cache_version, key);
      if (j.is_null())
        return {};
      try
        {
          build.n_solves       = j.at("solves").get<unsigned int>();
          build.max_half_angle = j.at("max_half_angle_rad").get<double>();
          build.n_repaired     = j.value("repaired_points", 0u);
          build.n_failed       = j.value("failed_solves", 0u);
          build.max_repair     = j.value("max_repair_m", 0.0);
          return contact::ForceApproachTable(j.at("forces_N").get<std::vector<double>>(),
                                             j.at("bore_directions").get<unsigned int>(),
                                             j.at("pin_directions").get<unsigned int>(),
                                             j.at("approach_m").get<std::vector<double>>());
        }
      catch (const std::exception &) // a damaged entry: rebuild (the file is overwritten)
        {
          return {};
        }
    }

    void
    write_cached(const std::string                 &file,
                 const std::string                 &key,
                 const contact::ForceApproachTable &t,
                 const TableBuild                  &b)
    {
      Json j;
      j["forces_N"]           = t.forces();
      j["bore_directions"]    = t.n_bore_directions();
      j["pin_directions"]     = t.n_pin_directions();
      j["approach_m"]         = t.approaches();
      j["solves"]             = b.n_solves;
      j["max_half_angle_rad"] = b.max_half_angle;
      j["repaired_points"]    = b.n_repaired;
      j["failed_solves"]      = b.n_failed;
      j["max_repair_m"]       = b.max_repair;
      write_table_cache(file, cache_format, cache_version, key, std::move(j));
    }

    /** The FE approaches of every direction and level on @p model (the expensive part). */
    std::vector<double>
    solve_table(PinBushingModel                          &model,
                const contact::JointGeometry             &g,
                const std::vector<double>                &forces,
                const std::vector<std::array<double, 2>> &directions,
                TableBuild                               &build)
    {
      const Stopwatch solving;
      use_profiles(model, g);
      const contact::Gap  gap(g.bore, g.pin);
      std::vector<double> approach;
      approach.reserve(directions.size() * forces.size());
      for (const auto &[psi_b, psi_p] : directions)
        {
          LoadCase lc;
          lc.control       = Control::force;
          lc.bushing_angle = 0;
          lc.pin_angle     = psi_b - psi_p; // the contact direction psi_b meets the pin at psi_p
          for (const double F : forces)
            {
              lc.load = {{F * std::cos(psi_b), F * std::sin(psi_b)}};
              ++build.n_solves;
              try
                {
                  const ContactResult r = model.solve(lc, SolverKind::condensed);
                  const auto          e = r.pin_displacement;
                  approach.push_back(gap.evaluate(mbs::Vec2(e[0], e[1]), 0.0, lc.pin_angle).penetration);
                  build.max_half_angle = std::max(build.max_half_angle, r.half_angle);
                }
              catch (const NumericalError &e) // filled from its neighbours and counted (fill_failed)
                {
                  approach.push_back(std::numeric_limits<double>::quiet_NaN());
                  if (build.n_failed++ == 0)
                    build.first_failure = std::to_string(F) + " N in the direction " + std::to_string(psi_b) +
                                          " rad (bushing frame), " + std::to_string(psi_p) +
                                          " rad (pin frame): " + e.what();
                }
            }
        }
      build.solve_seconds = solving.seconds();
      return approach;
    }

    /** A model of its own for one table (a round pair's, refined about its one direction). */
    std::vector<double>
    solve_table_on_own_mesh(const contact::JointGeometry             &g,
                            const FeSettings                         &fe,
                            const std::vector<double>                &forces,
                            const std::vector<std::array<double, 2>> &directions,
                            TableBuild                               &build)
    {
      const TemporaryDirectory scratch("fe-table");
      PinBushingModel          model(g, fe, scratch.path() + "/pin_bushing.msh");
      model.prepare_condensed();
      build.mesh_seconds  = model.statistics().mesh_time;
      build.setup_seconds = model.statistics().assembly_time + model.statistics().factorization_time;
      return solve_table(model, g, forces, directions, build);
    }

  } // namespace

  void
  declare_fe_force_law(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    declare_fe_settings(prm);
    declare_required(prm,
                     "Restitution coefficient",
                     Double(0.0, 1.0),
                     "Coefficient of restitution c_e of the Lankarani–Nikravesh hysteresis damping "
                     "on top of the FE elastic force (seed: 0.9).",
                     "none");
    declare(prm,
            "Minimum impact velocity",
            "1e-4",
            Double(1e-12),
            "Guard of the hysteresis term, as for the lankarani-nikravesh law: it uses "
            "max(δ̇⁻, this value, |δ̇|) in place of the impact velocity δ̇⁻.",
            "m/s");
    declare(prm,
            "Table minimum force",
            "10",
            Double(0, 1e9),
            "Smallest load level of the FE force–approach table. Below its approach the "
            "force follows the power law that continues the table's end slope down to zero.",
            "N");
    declare(prm,
            "Table maximum force",
            "1e5",
            Double(0, 1e9),
            "Largest load level of the table, at most 1e9 N. Beyond its approach the force follows "
            "the power law of the table's end slope; every such evaluation is counted in summary.json "
            "(extrapolations_above_table, trial stages of rejected steps included), and a run whose "
            "accepted steps reach an elastic force above this level (max_elastic_force_N) is warned "
            "about (warnings).",
            "N");
    declare(prm,
            "Table load levels",
            "16",
            Integer(2, 200),
            "Number of load levels, spaced logarithmically between the minimum and maximum force. "
            "For worn profiles under Clearance model = conformal they set the conformal table's "
            "overlap levels: the approaches of the nominal round pair at these loads (Johnson's line "
            "contact), shared by all its directions, its force a monotone cubic in (ln overlap, ln "
            "force) between them. On the nine-bar's worn joint A, 8 levels (×3 apart from 10 N to 20 kN) "
            "and 12 gave the same error against direct FE solves (14.2 and 13.4 % rms over its pocket; "
            "doc/models.md §1.7).",
            "none");
    declare(prm,
            "Table bore directions",
            "72",
            Integer(1, 360),
            "Directions tabulated in the bushing frame (uniform over 2π) for worn, non-circular "
            "profiles; round profiles need one. Under Clearance model = conformal: the directions of "
            "the pin's displacement of the conformal table, between which the force is interpolated "
            "linearly. A worn pocket must be resolved: at a given overlap the FE force changes by "
            "tens of percent within a few degrees of the pocket's axis. Measured on the nine-bar's "
            "worn joint A against direct FE solves at the peak loads (8 µm overlap, ±40° about the "
            "pocket): rms force error 11 % with 24 directions, 6 % with 48, 4 % with 72 (the "
            "force-approach table of 8 directions used before: 29 %); 72 directions take as long to "
            "tabulate in the FE wear scene as its 8 × 8 force-approach table did. Under deepest-point "
            "and per-area: the contact directions of the force-approach table.",
            "none");
    declare(prm,
            "Table pin directions",
            "4",
            Integer(1, 360),
            "Directions in the pin frame tabulated for worn profiles. Under Clearance model = "
            "conformal: the relative angles θ_pin − θ_bushing of the conformal table (one if the pin "
            "is round); every relative angle and direction is a ray of 'Table load levels' FE solves. "
            "The nine-bar's pins wear into wide, shallow dents (±60°, 11–15 µm): 2, 4 and 8 relative "
            "angles gave rms force errors of 25, 24 and 22 % over its pocket at all loads (48 "
            "directions). Under "
            "deepest-point and per-area: the contact directions of the force-approach table in the "
            "pin frame (every pair of bore and pin directions is one FE load sequence).",
            "none");
    declare(prm,
            "Table cache",
            "true",
            Bool(),
            "Keep tables on disk by geometry ($WEARLINK_CACHE_DIR, else $XDG_CACHE_HOME/wearlink, "
            "else ~/.cache/wearlink), so that a second run of the same joints does not rebuild them.",
            "none");
  }

  FeForceLawSettings
  read_fe_force_law(ParameterReader &reader)
  {
    FeForceLawSettings s;
    s.fe                  = read_fe_settings(reader);
    s.restitution         = reader.get_double("Restitution coefficient");
    s.min_impact_velocity = reader.get_positive("Minimum impact velocity");
    s.min_force           = reader.get_positive("Table minimum force");
    s.max_force           = reader.get_positive("Table maximum force");
    s.n_levels            = static_cast<unsigned int>(reader.get_integer("Table load levels"));
    s.n_bore_directions   = static_cast<unsigned int>(reader.get_integer("Table bore directions"));
    s.n_pin_directions    = static_cast<unsigned int>(reader.get_integer("Table pin directions"));
    s.cache               = reader.get_bool("Table cache");
    if (!(s.max_force > s.min_force))
      reader.fail("Table maximum force",
                  "it must be larger than 'Table minimum force' (" + std::to_string(s.min_force) + " N)");
    return s;
  }

  /**
   * Make the approach increase with the load in every direction, from the top level
   * down: an approach not below the next level's is replaced by the power law of the
   * segment above it (slope d ln δ / d ln F of that segment, 1 at the top). On worn,
   * conforming profiles the lowest levels carry the load on one or two nodes in the
   * worn pocket, and their rigid overlap is noise at the scale of tens of nanometres
   * (measured: 0.17 µm at 10 N against 0.15 µm at 20 N in one direction after
   * 10,000 revolutions): repairs up to @p tolerance (1 % of the surface element size)
   * are that noise. A larger one is physics the table cannot hold — in a worn pocket
   * the frictionless pin slides sideways as the load grows, and the rigid overlap at
   * its equilibrium need not grow (measured: 0.47 µm at 40 N, 0.25 µm at 80 N on the FE
   * scene's worn joint B): it is repaired the same way, counted apart
   * (n_repaired_beyond_noise, the first in first_large_repair) and warned about, so that
   * a run goes on with a flagged approximation instead of stopping.
   */
  void
  make_monotone(std::vector<double>                      &approach,
                const std::vector<double>                &forces,
                const std::vector<std::array<double, 2>> &directions,
                const double                              tolerance,
                TableBuild                               &build)
  {
    const std::size_t K = forces.size();
    for (std::size_t d = 0; d < directions.size(); ++d)
      for (std::size_t k = K - 1; k-- > 0;)
        {
          double      &a     = approach[d * K + k];
          const double above = approach[d * K + k + 1];
          if (a < above && a > 0) // a pin resting in a worn pocket may overlap by nothing at all
            continue;
          double slope = 1;
          if (k + 2 < K && approach[d * K + k + 2] > above && above > 0)
            slope = std::log(approach[d * K + k + 2] / above) / std::log(forces[k + 2] / forces[k + 1]);
          const double repaired = above * std::pow(forces[k] / forces[k + 1], std::max(slope, 0.1));
          if (!(a - repaired <= tolerance) && build.n_repaired_beyond_noise++ == 0)
            build.first_large_repair = "in the direction " + std::to_string(directions[d][0]) +
                                       " rad (bushing frame), " + std::to_string(directions[d][1]) +
                                       " rad (pin frame) the approach at " + std::to_string(forces[k]) + " N was " +
                                       std::to_string(a * 1e6) + " µm, above the " + std::to_string(above * 1e6) +
                                       " µm at " + std::to_string(forces[k + 1]) + " N";
          build.max_repair = std::max(build.max_repair, a - repaired);
          ++build.n_repaired;
          a = repaired;
        }
  }

  void
  fill_failed_levels(std::vector<double>                           &values,
                     const std::vector<double>                     &levels,
                     const std::function<std::string(std::size_t)> &run_name,
                     const std::string                             &what,
                     const std::string                             &first_failure)
  {
    const std::size_t K = levels.size();
    for (std::size_t d = 0; d * K < values.size(); ++d)
      {
        double                  *y = &values[d * K];
        std::vector<std::size_t> ok;
        std::size_t              failed = 0;
        for (std::size_t k = 0; k < K; ++k)
          {
            if (std::isfinite(y[k]))
              ok.push_back(k);
            failed += std::isnan(y[k]) ? 1 : 0;
          }
        if (failed == 0)
          continue;
        if (ok.size() < 2 || 4 * failed > K)
          throw NumericalError("The FE contact solver failed at " + std::to_string(failed) + " of the " +
                               std::to_string(K) + " " + what + " in the direction " + run_name(d) +
                               "; refine the contact surfaces ('Surface element size'). The first failure of the "
                               "table: " +
                               first_failure);
        for (std::size_t k = 0; k < K; ++k)
          if (std::isnan(y[k]))
            {
              auto        hi = std::upper_bound(ok.begin(), ok.end(), k);
              std::size_t i, j; // the two solved levels the line goes through
              if (hi == ok.begin())
                i = ok[0], j = ok[1];
              else if (hi == ok.end())
                i = ok[ok.size() - 2], j = ok.back();
              else
                i = *(hi - 1), j = *hi;
              y[k] = y[i] + (y[j] - y[i]) * (levels[k] - levels[i]) / (levels[j] - levels[i]);
            }
      }
  }

  // A level whose FE solve failed is filled by the power law through its nearest solved
  // neighbours in the same direction: fill_failed_levels() in ln δ against ln F.
  void
  fill_failed(std::vector<double>                      &approach,
              const std::vector<double>                &forces,
              const std::vector<std::array<double, 2>> &directions,
              const std::string                        &first_failure)
  {
    std::vector<double> ln_f(forces.size()), ln_a(approach.size());
    for (std::size_t k = 0; k < forces.size(); ++k)
      ln_f[k] = std::log(forces[k]);
    for (std::size_t r = 0; r < approach.size(); ++r)
      ln_a[r] = std::isfinite(approach[r]) && approach[r] > 0 ? std::log(approach[r]) : numbers::nan;
    const auto name = [&](const std::size_t d) {
      return std::to_string(directions[d][0]) + " rad (bushing frame), " + std::to_string(directions[d][1]) +
             " rad (pin frame)";
    };
    fill_failed_levels(ln_a, ln_f, name, "load levels of the force–approach table", first_failure);
    for (std::size_t r = 0; r < approach.size(); ++r)
      if (!(std::isfinite(approach[r]) && approach[r] > 0)) // the solved ones are kept to the bit
        approach[r] = std::exp(ln_a[r]);
  }

  std::vector<double>
  table_load_levels(const FeForceLawSettings &s)
  {
    std::vector<double> forces(s.n_levels);
    for (unsigned int k = 0; k < s.n_levels; ++k)
      forces[k] = s.min_force * std::pow(s.max_force / s.min_force, double(k) / (s.n_levels - 1));
    return forces;
  }

  contact::ForceApproachTable
  build_force_approach_table(const contact::JointGeometry     &g,
                             const FeForceLawSettings         &s,
                             TableBuild                       &build,
                             std::shared_ptr<PinBushingModel> *shared)
  {
    const Stopwatch clock;
    build                            = TableBuild();
    const bool                round  = g.bore.is_round() && g.pin.is_round();
    const unsigned int        n_b    = round ? 1 : s.n_bore_directions;
    const unsigned int        n_p    = round ? 1 : s.n_pin_directions;
    const std::vector<double> forces = table_load_levels(s);
    // The table is solved on the joint's shared model (the fe pressure model's too; for a
    // round pair a periodic mesh, whose one sector of columns serves every direction),
    // whose mesh may be of slightly less worn profiles ('Remesh depth'): those belong to
    // the key. A table in the cache needs no model: none is made for it.
    auto              model = find_shared_model(g, s.fe);
    const std::string key   = table_geometry_key(g, s, model ? &model->meshed_geometry() : nullptr);
    if (s.cache)
      {
        build.cache_file                   = table_cache_file("fe_force_table", key);
        contact::ForceApproachTable cached = read_cached(build.cache_file, key, build);
        if (!cached.empty())
          {
            build.from_cache = true;
            build.seconds    = clock.seconds();
            if (shared != nullptr)
              *shared = model;
            return cached;
          }
      }
    bool reused = false;
    model       = shared_model(g, s.fe, &reused);
    if (!reused)
      {
        build.mesh_seconds  = model->statistics().mesh_time;
        build.setup_seconds = model->statistics().assembly_time + model->statistics().factorization_time;
      }
    if (shared != nullptr)
      *shared = model;
    std::vector<std::array<double, 2>> directions;
    for (unsigned int i = 0; i < n_b; ++i)
      for (unsigned int j = 0; j < n_p; ++j)
        directions.push_back({{two_pi * i / n_b, two_pi * j / n_p}});
    // A worn table's directions go all around both surfaces: its solves would ask for
    // nearly every compliance column, one block at a time; computed up front they run
    // on every core (BoundaryCompliance::precompute_all(); 19.7 s → 10.2 s for a worn
    // pair at the default 25 µm mesh, FeBenchmark.FullInfluenceMatrixOfAWornPair).
    // So, too, the one sector of columns that a periodic (round) pair keeps, which a
    // table of one direction asks for all of over its load levels.
    const Stopwatch columns;
    if (directions.size() > 1 || model->compliance_is_periodic())
      model->precompute_compliance();
    const double        column_seconds = columns.seconds();
    std::vector<double> approach       = solve_table(*model, g, forces, directions, build);
    build.solve_seconds += column_seconds; // the columns count with the solves that need them
    if (build.n_failed > 0)
      {
        fill_failed(approach, forces, directions, build.first_failure);
        std::cerr << "[wearlink] warning: the FE contact solver failed at " << build.n_failed << " of "
                  << build.n_solves << " force–approach table points; they were filled from their neighbours "
                  << "(table_failed_solves in summary.json). The first: " << build.first_failure << "\n";
      }
    make_monotone(approach, forces, directions, 0.01 * s.fe.effective_surface_element_size(), build);
    if (build.n_repaired_beyond_noise > 0)
      std::cerr << "[wearlink] warning: the FE force–approach table is not monotone in the load at "
                << build.n_repaired_beyond_noise << " of " << build.n_solves
                << " points beyond the noise of 1 % of the surface element size (the pin slides sideways in a worn "
                << "pocket as the load grows); they were made monotone (table_repairs_beyond_noise, "
                << "table_max_repair_m in summary.json). The first: " << build.first_large_repair << "\n";
    contact::ForceApproachTable table(forces, n_b, n_p, approach);
    if (s.cache)
      write_cached(build.cache_file, key, table, build);
    build.seconds = clock.seconds();
    return table;
  }

  std::vector<double>
  fe_approach_curve(const contact::JointGeometry &g,
                    const FeForceLawSettings     &s,
                    const std::vector<double>    &forces,
                    const double                  bore_angle,
                    const double                  pin_angle,
                    TableBuild                   &build)
  {
    const Stopwatch clock;
    build                      = TableBuild();
    FeSettings fe              = s.fe;
    fe.refined_arc_half_angle  = round_refined_half_angle(g, forces.back());
    fe.refined_arc_bore_centre = bore_angle;
    fe.refined_arc_pin_centre  = pin_angle;
    auto curve                 = solve_table_on_own_mesh(g, fe, forces, {{{bore_angle, pin_angle}}}, build);
    build.seconds              = clock.seconds();
    return curve;
  }

  FeNormalForceLaw::FeNormalForceLaw(FeForceLawSettings s)
    : TabulatedNormalForceLaw(s.restitution, s.min_impact_velocity)
    , settings(std::move(s))
  {
  }

  FeNormalForceLaw::~FeNormalForceLaw() = default;

  void
  FeNormalForceLaw::count_build()
  {
    total_build_seconds += last_build.seconds;
    ++n_builds;
    n_cached += last_build.from_cache ? 1 : 0;
  }

  contact::ForceApproachTable
  FeNormalForceLaw::build_table(const contact::JointGeometry &g)
  {
    contact::ForceApproachTable table = build_force_approach_table(g, settings, last_build, &model);
    count_build();
    return table;
  }

  void
  FeNormalForceLaw::update_geometry(const contact::JointGeometry &g)
  {
    geometry = std::make_unique<contact::JointGeometry>(g);
    if (conformal_table) // its evaluations count with the law's
      {
        conformal_counts[0] += conformal_table->n_evaluations();
        conformal_counts[1] += conformal_table->n_above();
        conformal_counts[2] += conformal_table->n_below();
      }
    if (conformal && !(g.bore.is_round() && g.pin.is_round()))
      {
        conformal_table = build_conformal_table(g, settings, last_build, &model);
        count_build();
        clear_table();
        return;
      }
    conformal_table.reset();
    TabulatedNormalForceLaw::update_geometry(g);
  }

  void
  FeNormalForceLaw::use_conformal(const bool on)
  {
    if (on == conformal)
      return;
    conformal = on;
    // A round pair's table serves both forms; worn profiles need the other kind.
    if (geometry && !(geometry->bore.is_round() && geometry->pin.is_round()))
      update_geometry(contact::JointGeometry(*geometry));
  }

  const contact::ConformalField *
  FeNormalForceLaw::conformal_field() const
  {
    return conformal_table.get();
  }

  PhaseTimings
  FeNormalForceLaw::timings() const
  {
    PhaseTimings t;
    t.contact_law_tables = total_build_seconds;
    return t;
  }

  Json
  FeNormalForceLaw::conformal_report() const
  {
    const auto &n     = conformal_table->nodes();
    const auto  K     = n.overlaps.size();
    double      f_low = std::numeric_limits<double>::infinity(), f_high = f_low;
    for (std::size_t run = 0; run * K < n.ln_force.size(); ++run)
      {
        f_low  = std::min(f_low, std::exp(n.ln_force[run * K]));
        f_high = std::min(f_high, std::exp(n.ln_force[run * K + K - 1]));
      }
    Json j;
    j["table_kind"]            = "conformal";
    j["table_load_levels"]     = K;
    j["table_bore_directions"] = n.n_bore;
    j["table_pin_directions"]  = n.n_pin;
    j["table_overlap_range_m"] = Json{n.overlaps.front(), n.overlaps.back()};
    // The forces every direction reaches at the smallest and largest overlap level: the
    // range the run's largest elastic force is checked against.
    j["table_force_range_N"]        = Json{f_low, f_high};
    j["evaluations"]                = conformal_counts[0] + conformal_table->n_evaluations();
    j["extrapolations_above_table"] = conformal_counts[1] + conformal_table->n_above();
    j["extrapolations_below_table"] = conformal_counts[2] + conformal_table->n_below();
    return j;
  }

  Json
  FeNormalForceLaw::report() const
  {
    Json j = conformal_table ? conformal_report() : TabulatedNormalForceLaw::report();
    if (!conformal_table)
      j["table_kind"] = "force-approach";
    j["table_fe_solves"]            = last_build.n_solves;
    j["table_build_time_s"]         = last_build.seconds;
    j["table_build_mesh_time_s"]    = last_build.mesh_seconds;
    j["table_build_setup_time_s"]   = last_build.setup_seconds;
    j["table_build_solve_time_s"]   = last_build.solve_seconds;
    j["table_from_cache"]           = last_build.from_cache;
    j["table_builds"]               = n_builds;
    j["table_builds_from_cache"]    = n_cached;
    j["table_build_time_total_s"]   = total_build_seconds;
    j["table_max_half_angle_deg"]   = last_build.max_half_angle * 180 / pi;
    j["table_repaired_points"]      = last_build.n_repaired;
    j["table_repairs_beyond_noise"] = last_build.n_repaired_beyond_noise;
    j["table_failed_solves"]        = last_build.n_failed;
    j["table_max_repair_m"]         = last_build.max_repair;
    j["table_within_validity"]      = last_build.max_half_angle < pi / 2;
    return j;
  }
} // namespace wearlink::fe
