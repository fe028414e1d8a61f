// SPDX-License-Identifier: LGPL-2.1-or-later
// The `fe` normal force law of a clearance joint: the elastic force against the
// approach δ taken from the 2D contact FE model of the joint's current (worn) profiles,
// with the Lankarani–Nikravesh hysteresis damping on top (the same factor, restitution
// and impact-velocity guard as the `lankarani-nikravesh` law).
//
// Definition of the approach. The bushing ring is held on its outer edge; the pin is
// loaded through its rigid core (it translates, it does not rotate) by a force F in the
// direction n = (cos φ, sin φ) from the bore centre; the FE model finds the equilibrium
// pin centre e_FE (force control, frictionless). The approach is the overlap of the
// *rigid* profiles at that pin position, δ = −min_φ g(φ; e_FE) — exactly the δ the joint
// computes from the gap of the rigid profiles (contact/gap.h). So the table answers
// the question the dynamics ask: at this rigid overlap, which force do the elastic
// bodies carry? For round profiles δ = |e_FE| − c.
//
// The table (contact/force_approach_table.h): 'Table load levels' forces spaced
// logarithmically from 'Table minimum force' to 'Table maximum force' [N]; round
// profiles need one direction (on the periodic mesh of fe/pin_bushing_mesher.h), worn ones
// 'Table bore directions' × 'Table pin directions' (the contact direction in the
// bushing frame, and in the pin frame, which the joint's relative rotation decouples).
// It is rebuilt in update_geometry() (construction and every profile update) and
// cached on disk by geometry (fe/table_cache.h); a cached table that does not read back
// cleanly is rebuilt.
//
// Worn profiles in a joint of the conformal form (ClearanceForm::conformal, the default)
// get the law's own conformal field instead: the FE resultant as a function of the pin's
// displacement vector in the pocket, tabulated under displacement control
// (fe/fe_conformal_table.h; the same three table knobs set its grid). The joint says
// which form it uses (use_conformal()) before the law builds, so the law builds only
// what the form needs: the conformal table, or this force–approach table for the
// deepest-point and per-area forms (and for round pairs, which the joint never asks for
// a field).
#pragma once

#include "contact/force_approach_table.h"
#include "contact/tabulated_normal_force_law.h"
#include "fe/fe_settings.h"

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace wearlink::fe
{
  class PinBushingModel;

  struct FeForceLawSettings
  {
    FeSettings   fe;
    double       restitution         = 0.9;  ///< c_e [-]
    double       min_impact_velocity = 1e-4; ///< the L-N guard [m/s]
    double       min_force           = 10;   ///< F_0 [N]
    double       max_force           = 1e5;  ///< F_{K−1} [N]
    unsigned int n_levels            = 16;
    unsigned int n_bore_directions   = 72; ///< worn profiles only
    unsigned int n_pin_directions    = 4;  ///< worn profiles only
    bool         cache               = true;
  };

  /** Declare the law's entries (the FE numerics and the table) in the current subsection. */
  void
  declare_fe_force_law(dealii::ParameterHandler &prm);

  FeForceLawSettings
  read_fe_force_law(ParameterReader &reader);

  /** How one table was obtained. */
  struct TableBuild
  {
    double       seconds                 = 0; ///< wall time of building (or reading) it [s]
    double       mesh_seconds            = 0; ///< of which gmsh [s]
    double       setup_seconds           = 0; ///< assembly and factorization [s]
    double       solve_seconds           = 0; ///< the FE load states, compliance columns included [s]
    bool         from_cache              = false;
    unsigned int n_solves                = 0;
    double       max_half_angle          = 0; ///< largest FE contact half-angle over the table [rad]
    unsigned int n_repaired              = 0; ///< approaches replaced to make the table monotone (see the .cc)
    unsigned int n_repaired_beyond_noise = 0; ///< of which by more than the noise tolerance
    std::string  first_large_repair;          ///< where the first of those was
    double       max_repair = 0;              ///< the largest such change [m]
    unsigned int n_failed   = 0;              ///< points whose FE solve failed, filled from their neighbours
    std::string  first_failure;               ///< where and why the first of them failed
    std::string  cache_file;
  };

  /**
   * Make @p approach (directions × levels, levels fastest) increase with the load in
   * every direction; violations up to @p tolerance [m] are noise, larger ones are
   * counted apart in @p build. See the .cc for the rule.
   */
  void
  make_monotone(std::vector<double>                      &approach,
                const std::vector<double>                &forces,
                const std::vector<std::array<double, 2>> &directions,
                double                                    tolerance,
                TableBuild                               &build);

  /**
   * Fill the values of failed FE solves (NaN) in @p values: runs of levels.size() values
   * (one run per table direction, levels fastest) of a quantity y against x = @p levels
   * (increasing). A failed value is interpolated linearly in x between its nearest solved
   * (finite) neighbours in its run, or continued by the line through the two nearest
   * solved on one side; infinite values are neither filled nor used (the caller's
   * markers). More than a quarter of a run failing, or fewer than two solved, is a
   * NumericalError that names the run (@p run_name of its index), the levels (@p what)
   * and the table's first failure.
   */
  void
  fill_failed_levels(std::vector<double>                           &values,
                     const std::vector<double>                     &levels,
                     const std::function<std::string(std::size_t)> &run_name,
                     const std::string                             &what,
                     const std::string                             &first_failure);

  /** The table's load levels: n_levels forces spaced logarithmically from min_force to max_force [N]. */
  std::vector<double>
  table_load_levels(const FeForceLawSettings &settings);

  /**
   * Tabulate the elastic force against the approach for @p geometry (see the file
   * comment). Approaches that do not increase with the load by no more than 1 % of
   * the surface element size (noise of a worn pocket at the lowest loads) are repaired
   * and counted; a larger violation is a NumericalError. The table is solved on the
   * joint's shared model of fe/model_pool.h (kept in @p shared if given, so that it
   * outlives the call): a round pair's is a periodic mesh, whose one sector of
   * compliance columns serves every direction.
   */
  contact::ForceApproachTable
  build_force_approach_table(const contact::JointGeometry     &geometry,
                             const FeForceLawSettings         &settings,
                             TableBuild                       &build,
                             std::shared_ptr<PinBushingModel> *shared = nullptr);

  /**
   * The FE approach at each of @p forces (increasing) in one contact direction
   * (@p bore_angle in the bushing frame, @p pin_angle in the pin frame) on a mesh refined
   * about it: one curve of a table, for comparisons (`wearlink compare-contact`). Not
   * checked for monotonicity (on a worn pocket the pin may slide sideways as the load
   * grows, and the rigid overlap need not increase): the caller decides.
   */
  std::vector<double>
  fe_approach_curve(const contact::JointGeometry &geometry,
                    const FeForceLawSettings     &settings,
                    const std::vector<double>    &forces,
                    double                        bore_angle,
                    double                        pin_angle,
                    TableBuild                   &build);

  class FeConformalTable;

  class FeNormalForceLaw : public contact::TabulatedNormalForceLaw
  {
  public:
    explicit FeNormalForceLaw(FeForceLawSettings settings);
    ~FeNormalForceLaw() override;

    /**
     * Build what the joint's form needs for @p geometry (see the file comment): the
     * conformal table for worn profiles under use_conformal(true), else the
     * force–approach table.
     */
    void
    update_geometry(const contact::JointGeometry &geometry) override;

    /** The joint's form; rebuilds for the current geometry if that changes what is needed. */
    void
    use_conformal(bool conformal) override;

    /** The conformal table in use (worn profiles, conformal form), or nullptr. */
    const contact::ConformalField *
    conformal_field() const override;

    /**
     * The table's (TabulatedNormalForceLaw::report, or the conformal table's) and its
     * builds: times, cache use, validity.
     */
    Json
    report() const override;

    /** contact_law_tables: every table build so far (the one at construction included). */
    PhaseTimings
    timings() const override;

  protected:
    contact::ForceApproachTable
    build_table(const contact::JointGeometry &geometry) override;

  private:
    /** Count the build just made (last_build) in the totals. */
    void
    count_build();
    /** The report of the conformal table. */
    Json
    conformal_report() const;

    const FeForceLawSettings settings;
    std::shared_ptr<PinBushingModel>
         model;             ///< the joint's shared FE model, kept across profile updates ('Remesh depth')
    bool conformal = false; ///< the joint asks worn profiles for a conformal field
    std::unique_ptr<contact::JointGeometry> geometry;        ///< the current one (after the first update_geometry())
    std::unique_ptr<FeConformalTable>       conformal_table; ///< worn profiles under the conformal form
    /** Evaluations, and those above and below the levels, of the conformal tables replaced so far. */
    long         conformal_counts[3] = {0, 0, 0};
    TableBuild   last_build;
    double       total_build_seconds = 0;
    unsigned int n_builds = 0, n_cached = 0;
  };
} // namespace wearlink::fe
