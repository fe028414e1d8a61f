// SPDX-License-Identifier: LGPL-2.1-or-later
// The fuzz harness: scene files as text, the mutator, the runner that
// spawns the wearlink executable under a timeout, and the checks on what it leaves
// behind. The harness does not link the wearlink library: it only needs the program,
// so that building it takes seconds. See fuzz_main.cc for the campaigns.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace wearlink::fuzz
{
  /**
   * The exit statuses wearlink documents (`wearlink --help`): 0 success, 2 bad input,
   * 3 numerical failure in a valid scene, 4 an I/O fault (being added with the
   * output-folder locks). 1 is an internal error, i.e. a bug, and is not in this list.
   * The only place the harness knows them.
   */
  inline constexpr std::array<int, 4> documented_exit_statuses = {0, 2, 3, 4};

  bool
  is_documented_exit_status(int status);

  /**
   * The documented rule (doc/running.md, "Validity warnings"): a constraint violation beyond
   * violation_warning_factor × the integrator's position tolerance, and at least
   * violation_warning_floor_m, must be in summary.json's `warnings`.
   */
  inline constexpr double violation_warning_factor  = 1000;
  inline constexpr double violation_warning_floor_m = 1e-6;

  // ---- randomness -------------------------------------------------------------------

  /**
   * A generator for mutant or scene @p index of campaign @p seed: each one is a function
   * of (seed, stream, index) alone, so that a single failure reruns without the ones
   * before it. The helpers below use only the raw 64-bit output (the distributions of
   * <random> are not the same across standard libraries).
   */
  class Random
  {
  public:
    Random(std::uint64_t seed, std::uint64_t stream, std::uint64_t index);

    /** Uniform in [0, 1). */
    double
    uniform();

    /** Uniform in [lo, hi). */
    double
    uniform(double lo, double hi);

    /** Log-uniform in [lo, hi), lo > 0. */
    double
    log_uniform(double lo, double hi);

    /** Uniform integer in [0, n), n > 0. */
    std::size_t
    below(std::size_t n);

    /** True with probability @p p. */
    bool
    chance(double p);

    template <typename T>
    const T &
    pick(const std::vector<T> &v)
    {
      return v[below(v.size())];
    }

  private:
    std::mt19937_64 engine;
  };

  // ---- scene files ------------------------------------------------------------------

  /**
   * The files a scene may read, as text, by path relative to a sandbox root that mirrors
   * the source tree: every .prm under params/ and the .csv profiles in meshes/worn/. A mutant is a changed copy
   * written into its own folder, so that relative includes and profile paths resolve
   * exactly as in the source tree.
   */
  using Tree = std::map<std::string, std::string>;

  /** Read the tree from the source directory @p source_dir. */
  Tree
  read_tree(const std::string &source_dir);

  /** Write @p tree under @p dir (created; existing files overwritten). */
  void
  write_tree(const Tree &tree, const std::string &dir);

  /** One line of a .prm file, classified. */
  struct PrmLine
  {
    enum class Kind
    {
      blank,
      comment,
      set,
      subsection,
      end,
      include,
      other
    };
    Kind        kind = Kind::other;
    std::string path;  ///< for `set`: the entry's full path, "Joint A/Clearance/Radial clearance"
    std::string value; ///< for `set`: the value without the comment; for include: the file
    std::size_t value_begin = 0, value_end = 0; ///< for `set`: where the value sits in the line
  };

  /** Split @p text into lines (without the '\n'). */
  std::vector<std::string>
  split_lines(const std::string &text);

  /** Join @p lines with '\n' (and a final one). */
  std::string
  join_lines(const std::vector<std::string> &lines);

  /** Classify every line of a .prm text, tracking the subsection path. */
  std::vector<PrmLine>
  classify(const std::vector<std::string> &lines);

  /**
   * The files scene @p scene (a path in @p tree) reads: itself, its includes (relative to
   * the including file, as wearlink resolves them), transitively, and the profile files
   * its entries name; each once, the scene first.
   */
  std::vector<std::string>
  closure(const Tree &tree, const std::string &scene);

  /** Every entry of @p scene after its includes, "Section/Entry" -> value (last one wins). */
  std::map<std::string, std::string>
  flatten(const Tree &tree, const std::string &scene);

  /** @p path (a tree path) relative to the folder of tree path @p from. */
  std::string
  relative_to(const std::string &path, const std::string &from);

  // ---- shipped scenes ---------------------------------------------------------------

  /** A shipped scene and how to make a run of it cheap. */
  struct BaseScene
  {
    std::string              name;    ///< "nine_bar_wear"
    std::string              file;    ///< tree path, "params/nine_bar_wear.prm"
    std::string              command; ///< "run" or "contact"
    bool                     wear              = false;
    bool                     fe                = false;
    bool                     analyses          = false;
    double                   end_time          = 0; ///< shortened End time [s] (run only)
    double                   validate_fraction = 0; ///< share of mutants only validated
    std::vector<std::string> shortening;            ///< --set "S/E=V" that keep a run cheap
    std::vector<std::string> clearance_joints;      ///< names of joints with Model = clearance
  };

  /** Every scene directly in params/ of @p tree, with its shortening overrides. */
  std::vector<BaseScene>
  base_scenes(const Tree &tree);

  // ---- running wearlink -------------------------------------------------------------

  struct Limits
  {
    double        timeout_s     = 60;
    std::uint64_t address_space = std::uint64_t(6) << 30;   ///< bytes (a huge allocation fails, not the machine)
    std::uint64_t file_size     = std::uint64_t(512) << 20; ///< bytes per file written
    int           stop_signal   = 0; ///< sent to the program (not its group) after stop_after_s; 0: none
    double        stop_after_s  = 0; ///< [s]
  };

  struct Outcome
  {
    bool        exited      = false; ///< WIFEXITED
    int         exit_status = -1;    ///< if exited
    int         signal      = 0;     ///< if killed by a signal (and not by the timeout)
    bool        timed_out   = false;
    bool        stopped     = false; ///< Limits::stop_signal was sent
    double      wall_s      = 0;
    std::string output; ///< stdout and stderr together

    /** "exit 2", "signal 11 (Segmentation fault)", "timeout after 60 s". */
    std::string
    status_text(double timeout_s) const;
  };

  /**
   * Run @p argv (argv[0] an absolute path) in folder @p cwd with @p environment added,
   * stdout and stderr to @p log_file, under @p limits. The child gets its own process
   * group, and only that group is killed on a timeout.
   */
  Outcome
  run_program(const std::vector<std::string>                         &argv,
              const std::string                                      &cwd,
              const std::vector<std::pair<std::string, std::string>> &environment,
              const std::string                                      &log_file,
              const Limits                                           &limits);

  /** @p args as one shell command line (each argument quoted where needed). */
  std::string
  shell_command(const std::vector<std::string> &args);

  // ---- checks -----------------------------------------------------------------------

  /** Paths (in JSON-pointer style) of the numbers in @p j that are not finite, and of nulls. */
  std::vector<std::string>
  non_finite_numbers(const nlohmann::json &j, const std::string &at = "");

  /** "row r, column c" of the first non-finite number in a CSV file, or "". */
  std::string
  first_non_finite_csv_value(const std::string &file);

  /** Files below @p dir whose name holds ".partial" (a write that was never completed). */
  std::vector<std::string>
  partial_files(const std::string &dir);

  /**
   * The problems with a finished wearlink run whose output folder is @p output_dir:
   * signal, timeout, an undocumented or internal exit status; on success a summary.json
   * that parses and holds finite numbers only, finite CSV tables, no partial
   * files; on failure a message and no summary.json. @p expect_summary is false for
   * --validate. Empty if all is well; @p summary receives the parsed summary.
   */
  std::vector<std::string>
  check_run(const Outcome     &outcome,
            const std::string &output_dir,
            bool               expect_summary,
            double             timeout_s,
            nlohmann::json    &summary);

  /** The last @p n non-empty lines of @p text, indented. */
  std::string
  tail_lines(const std::string &text, std::size_t n);

  // ---- mutations --------------------------------------------------------------------

  /** One mutant: the changed tree and what was done to it. */
  struct Mutant
  {
    Tree                     tree;
    std::vector<std::string> mutations; ///< one description each
  };

  /** Apply 1–3 random mutations to the files @p scene reads. */
  Mutant
  mutate(const Tree &base, const BaseScene &scene, Random &random);
} // namespace wearlink::fuzz
