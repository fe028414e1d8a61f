// SPDX-License-Identifier: LGPL-2.1-or-later
// Ensembles: a wear run or a life run repeated N times with initial
// conditions perturbed by a physically tiny, seeded amount, spread over the ranks of
// MPI_COMM_WORLD, and the mean, standard deviation and 95 % confidence interval of every
// summary figure. The clearance dynamics are chaotic: one run is one sample, and the
// ensemble's spread is the floor below which a figure's difference means nothing.
//
// The perturbation: member k shifts the initial angle of every angle driver d of the
// scene ('Joint <d>/Angle offset') by σ z_{k,d}, z from analysis::member_normals(seed, k)
// (standard normal, reproducible on any platform and rank count), σ = 1e-9 rad by
// default (--perturbation): 0.08 nm at the tip of a 0.08 m crank, far below the
// integrator's position tolerance and any manufacturing tolerance, yet the trajectories
// part within a few driving cycles (the clearance dynamics' Lyapunov exponents are
// 40–350 1/s, doc/tutorials/nonlinear_dynamics.md).
//
// Each member is a complete run (wear or life) into DIR/member_<k>/ with its own files
// and checkpoint; member k runs on rank k mod N_ranks, and its result depends on the
// scene, the seed and k only. Rank 0 gathers the members' summaries and writes, each
// atomically: DIR/summary.json (`ensemble.<figure>.{mean,std,ci95_low,ci95_high,p05,p50,p95,
// members}`,
// the members with their perturbations and figures), DIR/ensemble.csv (one row per
// member) and DIR/ensemble.png (each figure's members relative to their mean, with the
// 95 % interval of the mean). A member that fails (a numerical failure) is reported
// with its message; the statistics are over the members that ran. A life ensemble adds
// `ensemble_life` (each criterion's revolutions and hours over the members that decided
// it: mean, std, 95 % interval of the mean, P05 / P10 / P50 / P90 / P95; the ensemble's life, the
// smallest P10 of the criteria every member decided) and DIR/life.png (the band of the
// members' criteria against revolutions, from their life_history.csv) and DIR/life_cdf.png
// (the empirical CDF of each decided criterion's revolutions). A scene with uncertain
// inputs (`subsection Uncertainty`) adds their sampled values to each member and the
// sensitivities of the headline figures (workflows/ensemble/uncertain_inputs.h, DIR/sensitivity.png).
// All of it is
// computed on rank 0 from the members' summaries and files, which depend on the seed and
// the member index only: the same on any number of ranks.
#pragma once

#include "base/json.h"
#include "base/output_directory.h"
#include "base/parameters.h"
#include "io/scene.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct EnsembleRequest
  {
    unsigned int  members      = 0;    ///< N ≥ 2
    std::uint64_t seed         = 1;    ///< of the perturbations
    double        perturbation = 1e-9; ///< σ of each angle driver's initial angle [rad]
    /** --sensitivity saltelli: the uncertain inputs laid out as a Saltelli design (uncertain_inputs.h). */
    bool saltelli = false;
  };

  /**
   * The request of @p members members (a whole number 2 … 1000), @p seed (a whole number
   * 0 … 2⁵³) and @p perturbation (> 0, ≤ 1e-3 rad), with a Saltelli design if @p saltelli;
   * InputError naming the option (--ensemble, --seed, --perturbation) and its range otherwise.
   */
  EnsembleRequest
  ensemble_request(double members, double seed, double perturbation, bool saltelli);

  /** The files of an ensemble in @p dir: its own, @p member_files, and the member folders (asked for and earlier ones). */
  RunFiles
  ensemble_files(const std::string &dir, unsigned int members, const RunFiles &member_files);

  /**
   * @p hold on rank 0 of MPI_COMM_WORLD (MPI initialised; rank 0 writes the outputs):
   * every other rank receives its refusal (InputError, IoError) and throws the same, so
   * that all ranks stop alike. Returns nullptr on the other ranks.
   */
  std::unique_ptr<OutputDirectory>
  held_on_root(const std::function<std::unique_ptr<OutputDirectory>()> &hold);

  /** The text `--help` shows about --ensemble, --seed and --perturbation. */
  std::string
  ensemble_help();

  /**
   * @p base with member @p k's perturbation of @p scene's angle drivers (scene read with
   * @p base); the shifts [rad] by driver name into @p shifts if given. InputError if the
   * scene has no angle driver.
   */
  ParameterOverrides
  member_overrides(const io::Scene               &scene,
                   const ParameterOverrides      &base,
                   const EnsembleRequest         &request,
                   unsigned int                   k,
                   std::map<std::string, double> *shifts = nullptr);

  /**
   * The figures of a wear or life run's summary.json, by name: per wearing joint J
   * J_wear_volume_pin_m3, J_wear_volume_bushing_m3, J_max_wear_depth_{pin,bushing}_m,
   * J_mass_loss_{pin,bushing}_mg, J_sliding_distance_m, J_mean_normal_force_N; per
   * clearance joint J_max_normal_force_N, J_fraction_in_contact and per body
   * B_max_abs_ax_m_s2, B_max_abs_ay_m_s2 (of the run after wear, or the plain run); the
   * response body's peak accelerations before and after wear and their ratios
   * (response_*); with a life block life_<criterion>_revolutions and life_revolutions
   * (criteria not decided are left out).
   */
  std::map<std::string, double>
  summary_figures(const Json &summary);

  /**
   * What runs one member: its scene (perturbed), its folder, its progress prefix and
   * whether to resume the run in that folder → its summary.
   */
  using MemberRun =
    std::function<Json(io::Scene &scene, const std::string &directory, const std::string &prefix, bool resume)>;

  struct EnsembleOptions
  {
    std::string        scene_file;
    ParameterOverrides overrides; ///< the user's --set, for every member
    EnsembleRequest    request;
    std::string        output_directory;
    std::string        command;          ///< "run", "life": for the summary
    bool               resume   = false; ///< finished members are read back, the others resumed
    bool               progress = true;
  };

  /**
   * Run the members of @p options on the ranks of MPI_COMM_WORLD (initialised; one rank
   * is a serial ensemble) with @p run, and write the ensemble's files on rank 0. Returns
   * DIR/summary.json's content on rank 0 (null elsewhere). Exit status through
   * @p all_failed: true if every member failed.
   */
  Json
  run_ensemble(const EnsembleOptions &options, const MemberRun &run, bool &all_failed);

  /**
   * summary.json's `ensemble_life` of a life ensemble from its @p members (run_ensemble's
   * records: status and the member's condensed life block): per criterion how many members
   * decided it, left it undecided or did not reach it, and over the members that decided
   * it the revolutions and hours as mean, std, 95 % interval of the mean and P10 / P50 /
   * P90 (analysis::percentile, type 7; `percentile_definition` says so); and the
   * ensemble's life: of the criteria every member decided, the one with the smallest P10
   * (`criterion`, `p10_revolutions`, `p10_hours`, `p50_*`, `p90_*`, `mean_revolutions`,
   * `ci95_mean_revolutions`, `members_decided`, `reason`). A trend criterion some member
   * left undecided is decided on the trend of the members' mean response (the measures at
   * the revolutions every member measured, averaged: the scatter falls by √members) as a
   * life run decides it, `trend_of_the_mean` in its block; if that puts it before the
   * wear criteria's smallest P10 it is the ensemble's life (`criterion`, `located_by`,
   * `revolutions`, `interval_revolutions`, `within_tolerance`, `members_decided`,
   * `reason`). Any other criterion some member left undecided is not the ensemble's life.
   */
  Json
  ensemble_life(const std::vector<Json> &members);

  /** The printed table of an ensemble summary: figure, mean, std, 95 % interval, members. */
  std::string
  ensemble_table(const Json &summary);

  /** The printed table of an ensemble_life block: per criterion its spread, then the life. */
  std::string
  ensemble_life_table(const Json &life);

  /** Sub-folder name of member @p k of @p n ("member_00", …). */
  std::string
  member_directory_name(unsigned int k, unsigned int n);
} // namespace wearlink::workflows
