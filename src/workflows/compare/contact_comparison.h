// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-contact`: the validation of the simplified contact laws against the
// FE model, for every clearance joint of a scene.
//  1. Force–approach curves on one approach grid: the sphere law the dynamics use by
//     default (K δ^1.5, K from seed eq. 10), the cylindrical closed forms that include
//     the axial length (Johnson; ESDU-78035: contact/cylindrical_contact.h), a linear
//     Winkler layer (if the scene gives its 'winkler/Layer thickness'), and the FE model
//     (fe/fe_normal_force_law.h; its definition of the approach is the one of all
//     curves); on worn profiles (a wear run's bore_<J>.csv, pin_<J>.csv) the FE curve in
//     the direction of the deepest bore wear as well.
//  2. Each law's deviation from FE: the force it gives at the approach at which the FE
//     model carries 100 N, 1 kN, 10 kN and 100 kN.
//  3. Each dynamics law's effect: the scene run for N driving cycles with every clearance
//     joint on lankarani-nikravesh, johnson, esdu-78035 and fe (same restitution):
//     contact fraction, mean and peak normal force, impacts, peak acceleration, wall
//     time; in a wear scene also one wear iteration with the law (the scene's Cycles per
//     iteration from assembly and its pressure model: steps 1–2 of wear/wear_loop.h, no
//     extrapolation, no profile update) and the volumes it wears off pin and bushing of
//     each wearing joint, next to Archard's k_D ∫ F_n |v_t| dt.
//  4. Pressure distributions (workflows/compare/contact_pressures.h): per joint four loads from
//     the mean to the peak normal force in contact of the lankarani-nikravesh run (the
//     effect run, or with --no-effects a run of load_range_cycles), spaced geometrically,
//     through hertz-strip, winkler (if given) and fe, fresh and worn.
#pragma once

#include "base/parameters.h"
#include "workflows/compare/contact_pressures.h"

#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct ContactComparisonRequest
  {
    std::string        scene_file;
    ParameterOverrides overrides;
    double             cycles = 100;   ///< driving cycles of each effect run
    std::string        worn_directory; ///< "" or a wear run's output (bore_<J>.csv, pin_<J>.csv)
    bool               effects  = true;
    bool               progress = true;
    /** Driving cycles of the lankarani-nikravesh run that sets the pressure loads without effect runs. */
    double load_range_cycles = 10;
  };

  /** One column of force_approach.csv. */
  struct ForceCurve
  {
    std::string         joint, law, state; ///< state: "fresh" or "worn"
    std::vector<double> force;             ///< [N] on the common approach grid (NaN: outside validity)
  };

  struct LawDeviation
  {
    std::string         joint, law, state;
    std::vector<double> ratio; ///< F_law / F_FE at the FE approach of each reference load
  };

  struct EffectRow
  {
    std::string         law;
    std::vector<double> contact_fraction, peak_force; ///< per joint [-], [N]
    std::vector<double> mean_contact_force;           ///< per joint, ∫ F_n dt over the time in contact [N]
    std::vector<long>   impacts;
    double              peak_acceleration = 0; ///< largest |a| component of any body [m/s²]
    double              wall_time         = 0; ///< [s], table set-up included
    double              table_setup_time  = 0; ///< [s], the fe law's tables
    long                steps             = 0;
    /** Per wearing joint (ContactComparison::wear_joints), one wear iteration with this law: */
    std::vector<double> wear_volume_pin, wear_volume_bushing;       ///< Σ h A [m³]
    std::vector<double> archard_volume_pin, archard_volume_bushing; ///< k_D ∫ F_n |v_t| dt [m³]
    double              wear_wall_time = 0;                         ///< [s]
  };

  struct ContactComparison
  {
    std::vector<std::string>  joints;
    std::vector<double>       approach; ///< the grid [m]
    std::vector<ForceCurve>   curves;
    std::vector<double>       reference_loads{1e2, 1e3, 1e4, 1e5}; ///< [N]
    std::vector<LawDeviation> deviations;
    double                    cycles = 0;
    std::vector<EffectRow>    effects;
    std::vector<std::string>  wear_joints;     ///< joints with a wear law (effect runs only)
    double                    wear_cycles = 0; ///< simulated cycles of each wear iteration
    PressureDistributions     pressures;

    /** The printed tables: deviations from FE, the effects, the pressure distributions. */
    std::string
    table() const;
  };

  ContactComparison
  compare_contact(const ContactComparisonRequest &request);

  /**
   * force_approach.csv, force_approach.png, deviations.csv, effects.csv, pressure.csv,
   * pressure.png, compare_contact.txt into @p dir.
   */
  void
  write_contact_comparison(const std::string &dir, const ContactComparison &c);
} // namespace wearlink::workflows
