// SPDX-License-Identifier: LGPL-2.1-or-later
// "Show what accuracy costs in time" (doc/architecture.md §6): run one scene
// many times, each time turning one accuracy knob to one of its values while every
// other entry keeps the scene's value, and measure the wall time of each run and the
// error of the quantities that matter against a reference run of the same knob.
//
// A knob is data (struct Knob): a name, the scene entries it sets, and the values it
// takes, ordered coarse → fine; the last value is the knob's reference. For choices
// that have no "finer" (contact law, Baumgarte factors) the reference is the scene's
// own choice and is placed last. The table of knobs is built from the scene's active
// effects (an effect the scene does not use is not a knob: FE mesh knobs only with
// Pressure model = fe, wear knobs only with a wear law, the step of rk4 or the
// tolerance of dopri5). A study file (subsection "Accuracy study") may select knobs
// and replace their values; see study_file_help().
//
// Quantities per run, each compared with the knob's reference run:
//  - per wearing joint: worn volume of pin and bushing, largest wear depth of pin and
//    bushing, the worn-depth profile of each surface (relative L2 difference
//    ‖h − h_ref‖/‖h_ref‖, profiles of different resolution compared on the reference's
//    angles by periodic linear interpolation);
//  - per clearance joint: the peak normal contact force over the run;
//  - the peak acceleration magnitude of the response body (Wear/Response body, or the
//    last body) over the accepted steps.
// The point-by-point profile difference includes the spikes single impacts leave in a
// profile over a few simulated cycles; two runs that differ only in the chaotic
// trajectory differ there by tens of percent. So each profile is also compared after a
// 10° periodic moving average ("shape"). "worst" is the largest of the worn-volume and
// shape errors when the scene wears (the tool's product), else the largest of the
// force/acceleration errors.
#pragma once

#include "analysis/ensemble_statistics.h"
#include "io/scene.h"

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace wearlink::workflows
{

  /** One accuracy knob: the entries it sets and its values, coarse → fine. */
  struct Knob
  {
    std::string name;        ///< e.g. "integrator-tolerance"
    std::string description; ///< one line, for tables and --help
    /** Per part of a value, the "Section/Sub/Entry" paths that part is written to. */
    std::vector<std::vector<std::string>> targets;
    /** Each value: one string per part (in a study file: parts separated by ';'). */
    std::vector<std::vector<std::string>> values;
    std::string                           reference; ///< what the last value is, in words
  };

  /** What the user asked for (command line and study file). */
  /** The chaos floor's ensemble of a study: members (0: none, or 2 … 100), seed, perturbation [rad]. */
  struct FloorEnsemble
  {
    unsigned int  members      = 4;
    std::uint64_t seed         = 1;
    double        perturbation = 1e-9;
  };

  /**
   * The floor ensemble of @p members (0, or a whole number 2 … 100), @p seed (a whole
   * number 0 … 2⁵³) and @p perturbation (> 0, ≤ 1e-3 rad); InputError naming the option
   * (--ensemble, --seed, --perturbation) and its range otherwise.
   */
  FloorEnsemble
  floor_ensemble(double members, double seed, double perturbation);

  struct StudyRequest
  {
    std::vector<std::string> overrides; ///< applied to every run (after --quick's)
    bool                     quick    = false;
    bool                     progress = true;
    /** Knobs to vary (empty: every knob that applies). */
    std::vector<std::string> knobs;
    /** Replacement values by knob name (each value: parts separated by ';'). */
    std::map<std::string, std::vector<std::string>> values;
    /**
     * Members of the chaos floor (see ChaosFloor; 0 or 1: none): the scene's own run and
     * floor_members − 1 runs perturbed as the members of an ensemble
     * (workflows/ensemble/ensemble.h) with this seed and perturbation.
     */
    unsigned int  floor_members = 4;
    std::uint64_t seed          = 1;
    double        perturbation  = 1e-9; ///< [rad]
  };

  /** Every knob wearlink knows, by name, for a scene using every effect. */
  std::vector<std::string>
  known_knob_names();

  /** The text --help shows about study files. */
  std::string
  study_file_help();

  /**
   * Read a study file (a deal.II parameter file with a subsection "Accuracy study")
   * into @p request. InputError (file, entry, allowed names) for unknown knobs or
   * entries.
   */
  void
  read_study_file(const std::string &file, StudyRequest &request);

  /** The knobs that apply to @p scene (read with the study's base overrides). */
  std::vector<Knob>
  knobs_for(const io::Scene &scene, bool quick);

  struct StudyRow
  {
    std::string knob, value, reference; ///< value and reference as "Entry=v; ..."
    bool        is_reference = false;
    bool        ok           = true;
    std::string failure;       ///< message of a failed run
    double      wall_time = 0; ///< [s], reading + building + running
    double      cpu_time  = 0; ///< [s], the process's CPU time over the same (its cost on a core of its own)
    /** Measured quantities (name → value), e.g. "A/volume_pin_m3". */
    std::map<std::string, double> quantities;
    /** Relative errors against the knob's reference, same names (+ "A/profile_pin"). */
    std::map<std::string, double> errors;
    double                        worst = 0; ///< see the file comment; NaN if unknown
  };

  /**
   * The chaos floor of a study: runs at the scene's own settings whose
   * initial crank angles differ by ~1e-9 rad differ by what no knob can resolve. Every
   * pair of members is compared as a knob's row is with its reference; the mean and the
   * largest of each error over the pairs are the floor that a knob's error must clear to
   * mean anything. Also the members' quantities' mean, standard deviation and 95 %
   * interval.
   */
  struct ChaosFloor
  {
    unsigned int                  members      = 0;
    std::uint64_t                 seed         = 0;
    double                        perturbation = 0;
    std::map<std::string, double> mean_error, max_error; ///< per error name, over the pairs
    /** The pairs' "worst" (the measure of the rows' worst column): mean, smallest, largest. */
    double worst_mean = std::numeric_limits<double>::quiet_NaN();
    double worst_min  = std::numeric_limits<double>::quiet_NaN();
    double worst_max  = std::numeric_limits<double>::quiet_NaN();
    /** The same of the pairs' worn-volume error (largest over surfaces and joints). */
    double                                          volume_mean = std::numeric_limits<double>::quiet_NaN();
    double                                          volume_min  = std::numeric_limits<double>::quiet_NaN();
    double                                          volume_max  = std::numeric_limits<double>::quiet_NaN();
    std::map<std::string, analysis::EnsembleFigure> quantities;
    std::vector<std::string>                        failures; ///< of members that failed
  };

  struct AccuracyStudy
  {
    std::string              scene_file;
    std::vector<std::string> base_overrides;
    bool                     wears = false;
    std::vector<std::string> quantity_names; ///< in column order
    std::vector<StudyRow>    rows;
    ChaosFloor               floor; ///< members 0: none
    /** False on the MPI ranks other than 0 (they measured runs; rank 0 has the study). */
    bool root = true;

    /** The Markdown table (accuracy.md). */
    std::string
    markdown() const;
    /** accuracy.csv. */
    std::string
    csv() const;
    /**
     * accuracy_floor.csv: per quantity (and error) the chaos floor's mean and largest
     * pairwise error, and the members' mean, standard deviation and 95 % interval.
     */
    std::string
    floor_csv() const;
  };

  /**
   * Validate the request against @p scene_file (InputError before any run), then run
   * every value of every selected knob and the chaos floor's members, on the ranks of
   * MPI_COMM_WORLD if MPI is initialised (workflows/study/accuracy_runs.h). A run that fails is
   * a row with ok = false. The study is complete on rank 0 (root = false elsewhere).
   */
  AccuracyStudy
  run_accuracy_study(const std::string &scene_file, const StudyRequest &request);

  /** accuracy.csv, accuracy.md, accuracy_pareto.png into @p dir, each atomically. */
  void
  write_accuracy_study(const std::string &dir, const AccuracyStudy &study);
} // namespace wearlink::workflows
