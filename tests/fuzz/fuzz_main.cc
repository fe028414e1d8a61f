// SPDX-License-Identifier: LGPL-2.1-or-later
// wearlink_fuzz: two campaigns against the wearlink executable.
//
//   wearlink_fuzz mutants --binary WEARLINK --source SRC --work DIR [--seed S] [--first I] [--count N]
//   wearlink_fuzz scenes  --binary WEARLINK --source SRC --work DIR [--seed S] [--first I] [--count N]
//   options: --timeout SECONDS (60)  --findings DIR (WORK/findings)  --verbose 1 (a line per run)
//   $WEARLINK_FUZZ_BINARY, if set, replaces --binary (e.g. another build's wearlink)
//   $WEARLINK_FUZZ_SEED, if set, replaces --seed (new mutants under the registered tests)
//
// mutants: mutant I of seed S is a shipped scene with 1–3 mutations (mutator.cc), run
// shortened (BaseScene::shortening) or only validated. Each must end without a signal
// or timeout, with a documented exit status (documented_exit_statuses; 1, an internal
// error, is a failure), on 0 with a summary.json that parses and holds only finite
// numbers and a finite time_series.csv, on failure with a message and no summary.json,
// and never with a partial file left behind.
//
// scenes: scene I of seed S is a shipped clearance-joint scene with random physical data
// within physical ranges (clearance, masses and inertias, elastic moduli, restitution,
// friction, crank speed, integrator tolerances, Baumgarte factors). Besides the checks
// above it must not be rejected as bad input (exit 2), and wherever the reported
// constraint violation exceeds violation_warning_factor × the position tolerance (and
// violation_warning_floor_m),
// summary.json must say so in its `warnings` list.
//
// faults: case I of seed S is a shipped scene, run shortened, under one fault of its
// environment: a full disk (every file limited to 2 kB … 4 MB, RLIMIT_FSIZE: a write
// beyond fails as on a full disk), or SIGKILL, SIGTERM or SIGHUP at a random instant
// (0.05 … 2 s) followed by its resumption (`--resume` from the checkpoint a wear run
// left, else the run again with --overwrite). The faulted run must end with 0 or 4 (a
// full disk; on 4 a message that says to free space) or by its signal (128 + N for
// SIGTERM and SIGHUP), never leave its lock, and — except after SIGKILL, whose partial
// files the next run removes — never a partial file; the resumed run must succeed as a
// mutant's run does. A read-only folder is not among the faults: the campaign runs as
// root, whom no permission stops. Open MPI's start-up (`contact`) keeps its store in
// memory (PMIX_MCA_gds=hash): its shared-memory files would fall under the file-size
// limit too, which a full output disk does not reach.
//
// Every failure prints the seed and index, the mutations, the tail of the program's
// output, and the folder it was saved to (FINDINGS/<campaign>-s<S>-i<I>/: the mutated
// files, the program's log and outputs, and rerun.sh, which reruns it from that
// folder). The program exits 1 if anything failed. A run is a function of (seed,
// index) alone: `--first I --count 1` reruns one.
#include "fuzz.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace
{
  namespace fs = std::filesystem;
  using namespace wearlink::fuzz;

  struct Options
  {
    std::string   campaign, binary, source, work, findings;
    std::uint64_t seed    = 1;
    std::uint64_t first   = 0;
    std::uint64_t count   = 100;
    bool          verbose = false; ///< one line per run
    Limits        limits;
  };

  [[noreturn]] void
  usage(const std::string &why)
  {
    std::cerr << "wearlink_fuzz: " << why << "\n"
              << "usage: wearlink_fuzz mutants|scenes|faults --binary WEARLINK --source SRC --work DIR\n"
                 "         [--seed S] [--first I] [--count N] [--timeout SECONDS] [--findings DIR] [--verbose 1]\n";
    std::exit(2);
  }

  Options
  parse(int argc, char **argv)
  {
    if (argc < 2)
      usage("no campaign");
    Options o;
    o.campaign = argv[1];
    if (o.campaign != "mutants" && o.campaign != "scenes" && o.campaign != "faults")
      usage("unknown campaign '" + o.campaign + "'");
    for (int i = 2; i < argc; ++i)
      {
        const std::string a = argv[i];
        if (i + 1 >= argc)
          usage("option " + a + " needs a value");
        const std::string v = argv[++i];
        if (a == "--binary")
          o.binary = v;
        else if (a == "--source")
          o.source = v;
        else if (a == "--work")
          o.work = v;
        else if (a == "--findings")
          o.findings = v;
        else if (a == "--seed")
          o.seed = std::stoull(v);
        else if (a == "--first")
          o.first = std::stoull(v);
        else if (a == "--count")
          o.count = std::stoull(v);
        else if (a == "--verbose")
          o.verbose = v != "0";
        else if (a == "--timeout")
          o.limits.timeout_s = std::stod(v);
        else
          usage("unknown option " + a);
      }
    if (const char *b = std::getenv("WEARLINK_FUZZ_BINARY"); b != nullptr && *b != '\0')
      o.binary = b;
    if (const char *s = std::getenv("WEARLINK_FUZZ_SEED"); s != nullptr && *s != '\0')
      o.seed = std::stoull(s);
    if (o.binary.empty() || o.source.empty() || o.work.empty())
      usage("--binary, --source and --work are required");
    o.binary = fs::absolute(o.binary).string();
    o.source = fs::absolute(o.source).string();
    o.work   = fs::absolute(o.work).string();
    if (o.findings.empty())
      o.findings = (fs::path(o.work) / "findings").string();
    if (!fs::exists(o.binary))
      usage("no program " + o.binary);
    return o;
  }

  std::string
  fixed(const double x, const int digits = 2)
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << x;
    return s.str();
  }

  std::string
  sci(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(3) << x;
    return s.str();
  }

  /** What one campaign saw, for the closing table. */
  struct Tally
  {
    std::map<std::string, int>                        by_status;
    std::map<std::string, std::map<std::string, int>> by_scene; // scene -> status -> count
    std::vector<std::string>                          failures;
    double                                            wall = 0, slowest = 0;
    std::string                                       slowest_what;
    std::uint64_t                                     n = 0;

    void
    add(const std::string &scene, const std::string &status, const double wall_s, const std::string &what)
    {
      ++n;
      ++by_status[status];
      ++by_scene[scene][status];
      wall += wall_s;
      if (wall_s > slowest)
        {
          slowest      = wall_s;
          slowest_what = what;
        }
    }

    void
    print(const std::string &title) const
    {
      std::cout << "\n"
                << title << ": " << n << " runs, " << failures.size() << " failed; wall " << fixed(wall, 1)
                << " s (mean " << fixed(n ? wall / n : 0) << " s, slowest " << fixed(slowest) << " s: " << slowest_what
                << ")\n  by status:";
      for (const auto &[s, c] : by_status)
        std::cout << "  " << s << " × " << c;
      std::cout << "\n  by scene:\n";
      for (const auto &[scene, statuses] : by_scene)
        {
          std::cout << "    " << std::left << std::setw(26) << scene << std::right;
          for (const auto &[s, c] : statuses)
            std::cout << "  " << s << " × " << c;
          std::cout << "\n";
        }
      if (!failures.empty())
        {
          std::cout << "  failures:\n";
          for (const auto &f : failures)
            std::cout << "    " << f << "\n";
        }
    }
  };

  /**
   * Keep a failing case: copy @p dir (the mutated files, log and outputs) to the
   * findings folder, with rerun.sh (the program's command line, from that folder) and
   * README.txt (what was done and what went wrong). Returns the folder.
   */
  std::string
  save_finding(const Options                  &o,
               const std::string              &name,
               const std::string              &dir,
               const std::vector<std::string> &args,
               const std::string              &header)
  {
    const fs::path to = fs::path(o.findings) / name;
    fs::remove_all(to);
    fs::create_directories(to.parent_path());
    fs::copy(dir, to, fs::copy_options::recursive);
    {
      std::ofstream rerun(to / "rerun.sh");
      rerun << "#!/bin/sh\n";
      std::istringstream lines(header);
      for (std::string line; std::getline(lines, line);)
        rerun << "# " << line << "\n";
      rerun << "# Reruns the case from this folder (outputs in ./out).\n"
            << "cd \"$(dirname \"$0\")\" && rm -rf out && WEARLINK_CACHE_DIR=\"$PWD/cache\" " << shell_command(args)
            << "\n";
    }
    fs::permissions(to / "rerun.sh", fs::perms::owner_exec, fs::perm_options::add);
    {
      std::ofstream readme(to / "README.txt");
      readme << header << "\n";
    }
    return to.string();
  }

  /** Whether summary.json's `warnings` list has an entry that names the constraint violation. */
  bool
  warns_about_constraints(const nlohmann::json &summary)
  {
    if (!summary.contains("warnings") || !summary["warnings"].is_array())
      return false;
    for (const auto &w : summary["warnings"])
      {
        std::string text = w.is_string() ? w.get<std::string>() : w.dump();
        std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
        if (text.find("constraint") != std::string::npos)
          return true;
      }
    return false;
  }

  // ---- campaign: mutants ----------------------------------------------------------------

  int
  run_mutants(const Options &o, const Tree &tree, const std::vector<BaseScene> &scenes)
  {
    Tally tally;
    for (std::uint64_t i = o.first; i < o.first + o.count; ++i)
      {
        Random           random(o.seed, 1, i);
        const BaseScene &scene    = random.pick(scenes);
        const bool       validate = random.chance(scene.validate_fraction);
        const Mutant     mutant   = mutate(tree, scene, random);

        const std::string dir = (fs::path(o.work) / ("mutant-" + std::to_string(i))).string();
        fs::remove_all(dir);
        write_tree(mutant.tree, dir);
        std::vector<std::string> args = {o.binary, scene.command};
        if (validate)
          args.push_back("--validate");
        args.insert(args.end(), {scene.file, "--output", "out"});
        if (scene.command == "run")
          args.push_back("--quiet");
        for (const auto &s : scene.shortening)
          args.insert(args.end(), {"--set", s});

        const Outcome  outcome = run_program(args,
                                            dir,
                                            {{"WEARLINK_CACHE_DIR", (fs::path(o.work) / "cache").string()}},
                                            (fs::path(dir) / "log.txt").string(),
                                            o.limits);
        nlohmann::json summary;
        const auto     problems =
          check_run(outcome, (fs::path(dir) / "out").string(), !validate, o.limits.timeout_s, summary);
        const std::string mode = validate ? "validate" : scene.command;
        tally.add(scene.name + " (" + mode + ")",
                  outcome.status_text(o.limits.timeout_s),
                  outcome.wall_s,
                  "mutant " + std::to_string(i));

        if (o.verbose)
          std::cout << "mutant " << i << "  " << scene.name << " (" << mode << ")  "
                    << outcome.status_text(o.limits.timeout_s) << "  " << fixed(outcome.wall_s) << " s  "
                    << mutant.mutations.front() << (mutant.mutations.size() > 1 ? " (+more)" : "") << "\n"
                    << tail_lines(outcome.output, 1) << std::flush;
        if (!problems.empty())
          {
            std::ostringstream h;
            h << "FAIL mutant seed " << o.seed << " index " << i << ": scene " << scene.name << " (" << mode << "), "
              << outcome.status_text(o.limits.timeout_s) << " after " << fixed(outcome.wall_s) << " s\n";
            for (const auto &m : mutant.mutations)
              h << "  mutation: " << m << "\n";
            for (const auto &p : problems)
              h << "  problem:  " << p << "\n";
            h << "  output (last lines):\n" << tail_lines(outcome.output, 6);
            const auto saved =
              save_finding(o, "mutants-s" + std::to_string(o.seed) + "-i" + std::to_string(i), dir, args, h.str());
            std::cout << h.str() << "  saved:    " << saved << "\n  rerun:    " << saved << "/rerun.sh\n"
                      << "  or:       wearlink_fuzz mutants --seed " << o.seed << " --first " << i
                      << " --count 1 --binary ... --source ... --work ...\n"
                      << std::endl;
            // Include cycles crash today (a fix is under way); tagged so that the rest stands out.
            const bool cycle = std::any_of(mutant.mutations.begin(), mutant.mutations.end(), [](const std::string &m) {
              return m.compare(0, 6, "cycle:") == 0;
            });
            tally.failures.push_back(std::string(cycle ? "[include cycle] " : "") + "mutant " + std::to_string(i) +
                                     " (" + scene.name + ", " + mode + "): " + problems.front() + " [" +
                                     mutant.mutations.front() + "]");
          }
        fs::remove_all(dir);
        if ((i - o.first + 1) % 50 == 0)
          std::cout << "... " << (i - o.first + 1) << " of " << o.count << " mutants, " << tally.failures.size()
                    << " failed" << std::endl;
      }
    tally.print("mutants seed " + std::to_string(o.seed) + ", indices " + std::to_string(o.first) + "–" +
                std::to_string(o.first + o.count - 1));
    return tally.failures.empty() ? 0 : 1;
  }

  // ---- campaign: random physical scenes ---------------------------------------------------

  std::vector<std::string>
  split_list(const std::string &s)
  {
    std::vector<std::string> out;
    std::stringstream        in(s);
    std::string              item;
    while (std::getline(in, item, ','))
      {
        const auto b = item.find_first_not_of(' ');
        const auto e = item.find_last_not_of(' ');
        if (b != std::string::npos)
          out.push_back(item.substr(b, e - b + 1));
      }
    return out;
  }

  std::string
  num(const double x)
  {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
  }

  /**
   * Random physical data for @p scene: every value within what a real mechanism of this
   * kind could have. Returns the --set overrides; @p position_tolerance receives the
   * integrator's position tolerance they set.
   */
  std::vector<std::string>
  physical_variant(const Tree &tree, const BaseScene &scene, Random &r, double &position_tolerance)
  {
    const auto               flat = flatten(tree, scene.file);
    std::vector<std::string> s    = scene.shortening;
    const auto               get  = [&](const std::string &k) {
      const auto it = flat.find(k);
      return it == flat.end() ? std::string() : it->second;
    };
    const auto real = [&](const std::string &k, const double fallback) {
      const auto v = get(k);
      return v.empty() ? fallback : std::strtod(v.c_str(), nullptr);
    };

    // A longer piece of the cycle than the mutants run: 1–4 × their End time.
    s.front() = "Simulation/End time=" + num(scene.end_time * r.uniform(1, 4));

    for (const auto &j : scene.clearance_joints)
      {
        const std::string c    = "Joint " + j + "/Clearance/";
        const double      bore = real(c + "Bore radius", 0.01);
        // Profile files fix the clearance of a worn joint; the others get 20 µm–1 mm.
        if (get(c + "Bore profile file").empty() && get(c + "Pin profile file").empty())
          s.push_back(c + "Radial clearance=" + num(r.log_uniform(2e-5, std::min(1e-3, 0.1 * bore))));
        s.push_back(c + "Bushing elastic modulus=" + num(r.log_uniform(50e9, 400e9)));
        s.push_back(c + "Pin elastic modulus=" + num(r.log_uniform(50e9, 400e9)));
        s.push_back(c + "Bushing Poisson ratio=" + num(r.uniform(0.25, 0.35)));
        s.push_back(c + "Pin Poisson ratio=" + num(r.uniform(0.25, 0.35)));
        const std::string normal = get(c + "Normal force law");
        if (!normal.empty() && normal != "hertz" && normal != "fe")
          s.push_back(c + normal + "/Restitution coefficient=" + num(r.uniform(0.5, 0.99)));
        const std::string friction = get(c + "Friction law");
        if (friction == "modified-coulomb" || friction == "coulomb")
          s.push_back(c + friction + "/Friction coefficient=" + num(r.uniform(0, 0.4)));
      }

    // Masses and inertias scaled together (same shapes, other materials or sections).
    for (const auto &b : split_list(get("Mechanism/Bodies")))
      {
        const double f = r.log_uniform(0.5, 2);
        s.push_back("Body " + b + "/Mass=" + num(real("Body " + b + "/Mass", 1) * f));
        s.push_back("Body " + b + "/Moment of inertia=" + num(real("Body " + b + "/Moment of inertia", 1e-3) * f));
      }

    // Crank speeds: every driver by one factor (the nine-bar's two cranks stay in step).
    const double speed = r.log_uniform(0.5, 1.5);
    for (const auto &j : split_list(get("Mechanism/Joints")))
      if (get("Joint " + j + "/Type") == "angle-driver")
        s.push_back("Joint " + j + "/Angular velocity=" + num(real("Joint " + j + "/Angular velocity", 0) * speed));

    // Integrator: tolerances from tight to loose, Baumgarte from none to stiff.
    position_tolerance = r.log_uniform(1e-11, 1e-7);
    s.push_back("Integrator/Relative tolerance=" + num(r.log_uniform(1e-8, 1e-4)));
    s.push_back("Integrator/Position tolerance=" + num(position_tolerance));
    s.push_back("Integrator/Velocity tolerance=" + num(r.log_uniform(1e-8, 1e-4)));
    const bool stabilized = !r.chance(0.15);
    s.push_back("Integrator/Baumgarte alpha=" + num(stabilized ? r.uniform(1, 20) : 0));
    s.push_back("Integrator/Baumgarte beta=" + num(stabilized ? r.uniform(1, 20) : 0));
    return s;
  }

  int
  run_scenes(const Options &o, const Tree &tree, const std::vector<BaseScene> &all)
  {
    // Mechanism scenes with clearance joints whose runs stay cheap (FE tables and
    // analyses take seconds even shortened).
    std::vector<BaseScene> scenes;
    for (const auto &s : all)
      if (s.command == "run" && !s.clearance_joints.empty() && !s.fe && !s.analyses)
        scenes.push_back(s);
    if (scenes.empty())
      usage("no clearance-joint scene under " + o.source + "/params");

    Tally  tally;
    int    over_tolerance = 0, over_factor = 0;
    double worst_ratio = 0;
    for (std::uint64_t i = o.first; i < o.first + o.count; ++i)
      {
        Random                         random(o.seed, 2, i);
        const BaseScene               &scene     = random.pick(scenes);
        double                         tolerance = 0;
        const std::vector<std::string> overrides = physical_variant(tree, scene, random, tolerance);

        const std::string dir = (fs::path(o.work) / ("scene-" + std::to_string(i))).string();
        fs::remove_all(dir);
        write_tree(tree, dir);
        std::vector<std::string> args = {o.binary, "run", scene.file, "--output", "out", "--quiet"};
        for (const auto &s : overrides)
          args.insert(args.end(), {"--set", s});
        const Outcome  outcome = run_program(args,
                                            dir,
                                            {{"WEARLINK_CACHE_DIR", (fs::path(o.work) / "cache").string()}},
                                            (fs::path(dir) / "log.txt").string(),
                                            o.limits);
        nlohmann::json summary;
        auto problems = check_run(outcome, (fs::path(dir) / "out").string(), true, o.limits.timeout_s, summary);
        if (outcome.exited && outcome.exit_status == 2)
          problems.push_back("a physical variant was rejected as bad input");
        double violation = 0;
        if (summary.is_object() && summary.contains("max_constraint_violation_m") &&
            summary["max_constraint_violation_m"].is_number())
          {
            violation          = summary["max_constraint_violation_m"].get<double>();
            const double ratio = violation / tolerance;
            worst_ratio        = std::max(worst_ratio, ratio);
            over_tolerance += ratio > 1;
            const bool must_warn =
              violation > std::max(violation_warning_factor * tolerance, violation_warning_floor_m);
            over_factor += must_warn;
            if (must_warn && !warns_about_constraints(summary))
              problems.push_back("max_constraint_violation_m = " + sci(violation) + " is " + sci(ratio) +
                                 " × the position tolerance " + sci(tolerance) +
                                 ", and summary.json has no warning about it (`warnings`)");
          }
        else if (outcome.exited && outcome.exit_status == 0)
          problems.push_back("summary.json has no max_constraint_violation_m");
        tally.add(scene.name, outcome.status_text(o.limits.timeout_s), outcome.wall_s, "scene " + std::to_string(i));

        if (o.verbose)
          std::cout << "scene " << i << "  " << scene.name << "  " << outcome.status_text(o.limits.timeout_s) << "  "
                    << fixed(outcome.wall_s) << " s  violation " << sci(violation) << " = "
                    << sci(violation / tolerance) << " × tolerance\n"
                    << tail_lines(outcome.output, 1) << std::flush;
        if (!problems.empty())
          {
            std::ostringstream h;
            h << "FAIL random scene seed " << o.seed << " index " << i << ": " << scene.name << ", "
              << outcome.status_text(o.limits.timeout_s) << " after " << fixed(outcome.wall_s) << " s\n";
            for (const auto &p : problems)
              h << "  problem:  " << p << "\n";
            h << "  output (last lines):\n" << tail_lines(outcome.output, 6);
            // The scene files are the shipped ones: keep only the one run and its includes.
            for (const auto &[path, text] : tree)
              {
                const auto c = closure(tree, scene.file);
                if (std::find(c.begin(), c.end(), path) == c.end())
                  fs::remove(fs::path(dir) / path);
              }
            const auto saved =
              save_finding(o, "scenes-s" + std::to_string(o.seed) + "-i" + std::to_string(i), dir, args, h.str());
            std::cout << h.str() << "  saved:    " << saved << "\n  rerun:    " << saved << "/rerun.sh\n" << std::endl;
            tally.failures.push_back("scene " + std::to_string(i) + " (" + scene.name + "): " + problems.front());
          }
        fs::remove_all(dir);
        if ((i - o.first + 1) % 25 == 0)
          std::cout << "... " << (i - o.first + 1) << " of " << o.count << " scenes, " << tally.failures.size()
                    << " failed" << std::endl;
      }
    tally.print("random scenes seed " + std::to_string(o.seed) + ", indices " + std::to_string(o.first) + "–" +
                std::to_string(o.first + o.count - 1));
    std::cout << "  constraint violation / position tolerance: worst " << sci(worst_ratio) << "; above 1 in "
              << over_tolerance << " runs, above " << violation_warning_factor << " and " << violation_warning_floor_m
              << " m (a warning required) in " << over_factor << "\n";
    return tally.failures.empty() ? 0 : 1;
  }

  // ---- campaign: environment faults -------------------------------------------------------

  /** One fault of the environment: a file-size limit (a full disk) or a signal at an instant. */
  struct Fault
  {
    std::string   name;
    std::uint64_t file_size = 0; ///< bytes per file; 0: the campaign's default limit
    int           signal    = 0;
    double        instant   = 0; ///< [s] after the start
  };

  Fault
  draw_fault(Random &r)
  {
    Fault             f;
    const std::size_t kind = r.below(4);
    if (kind == 0)
      {
        f.file_size = static_cast<std::uint64_t>(r.log_uniform(2e3, 4e6));
        f.name      = "full disk at " + num(static_cast<double>(f.file_size) / 1e3) + " kB a file";
        return f;
      }
    f.signal  = kind == 1 ? SIGKILL : (kind == 2 ? SIGTERM : SIGHUP);
    f.instant = r.uniform(0.05, 2.0);
    f.name = std::string(kind == 1 ? "SIGKILL" : (kind == 2 ? "SIGTERM" : "SIGHUP")) + " at " + num(f.instant) + " s";
    return f;
  }

  /** The problems of a run under @p f beyond check_run's (exit status, lock, message). */
  std::vector<std::string>
  fault_problems(const Fault &f, const Outcome &outcome, const std::string &out)
  {
    std::vector<std::string> p;
    const bool               killed = outcome.stopped && f.signal == SIGKILL && !outcome.exited;
    if (!killed && fs::exists(fs::path(out) / ".wearlink.lock"))
      p.push_back("the lock file was left behind");
    if (f.file_size > 0 && outcome.exited && outcome.exit_status != 0 && outcome.exit_status != 4)
      p.push_back("a full disk ended with " + outcome.status_text(0) + ", not 0 or 4");
    if (f.file_size > 0 && outcome.exited && outcome.exit_status == 4 &&
        outcome.output.find("Free some space") == std::string::npos)
      p.push_back("exit 4 without saying to free some space");
    if (f.signal != 0 && f.signal != SIGKILL && outcome.stopped && outcome.exited && outcome.exit_status != 0 &&
        outcome.exit_status != 128 + f.signal)
      p.push_back("stopped by signal " + std::to_string(f.signal) + " but ended with " + outcome.status_text(0));
    return p;
  }

  /** The command line of @p scene into "out" (@p resume: --resume out; else --output out [--overwrite]). */
  std::vector<std::string>
  fault_args(const Options &o, const BaseScene &scene, const bool resume, const bool overwrite)
  {
    std::vector<std::string> args = {o.binary, scene.command, scene.file};
    if (resume)
      args.insert(args.end(), {"--resume", "out"});
    else
      args.insert(args.end(), {"--output", "out"});
    if (overwrite)
      args.push_back("--overwrite");
    if (scene.command == "run")
      args.push_back("--quiet");
    for (const auto &x : scene.shortening)
      args.insert(args.end(), {"--set", x});
    return args;
  }

  /**
   * Case @p i: the faulted run, checked, then (after a signal that stopped it) its
   * resumption, checked as a mutant's run. Problems into @p problems; returns the
   * status text for the tally.
   */
  std::string
  run_fault_case(const Options            &o,
                 const BaseScene          &scene,
                 const Fault              &f,
                 const std::string        &dir,
                 std::vector<std::string> &problems)
  {
    const std::vector<std::pair<std::string, std::string>> env    = {{"WEARLINK_CACHE_DIR",
                                                                      (fs::path(o.work) / "cache").string()},
                                                                     {"PMIX_MCA_gds", "hash"}};
    const std::string                                      out    = (fs::path(dir) / "out").string();
    Limits                                                 faulty = o.limits;
    if (f.file_size > 0)
      faulty.file_size = f.file_size;
    faulty.stop_signal   = f.signal;
    faulty.stop_after_s  = f.instant;
    const Outcome  first = run_program(fault_args(o, scene, false, false), dir, env, dir + "/log.txt", faulty);
    nlohmann::json summary;
    const bool     stopped = first.stopped && !(first.exited && first.exit_status == 0);
    if (!stopped)
      problems = check_run(first, out, true, o.limits.timeout_s, summary);
    else if (f.signal != SIGKILL)
      for (const auto &p : partial_files(out))
        problems.push_back("partial file left behind after the signal: " + p);
    for (const auto &p : fault_problems(f, first, out))
      problems.push_back(p);
    if (!stopped)
      return first.status_text(o.limits.timeout_s);
    const bool    resume = scene.wear && scene.command == "run" && fs::exists(fs::path(out) / "checkpoint.json");
    const Outcome again  = run_program(fault_args(o, scene, resume, !resume), dir, env, dir + "/log2.txt", o.limits);
    for (const auto &p : check_run(again, out, true, o.limits.timeout_s, summary))
      problems.push_back((resume ? "resumed: " : "rerun: ") + p);
    if (again.exited && again.exit_status != 0)
      problems.push_back((resume ? "resumed: " : "rerun: ") + again.status_text(o.limits.timeout_s) + ": " +
                         tail_lines(again.output, 2));
    return first.status_text(o.limits.timeout_s) + (resume ? ", resumed " : ", rerun ") +
           again.status_text(o.limits.timeout_s);
  }

  int
  run_faults(const Options &o, const Tree &tree, const std::vector<BaseScene> &scenes)
  {
    // The files of params/ that are no scene of their own (measurements) fail as bad
    // input with or without a fault: the faults go to the scenes and contact cases.
    std::vector<BaseScene> runnable;
    for (const auto &s : scenes)
      if (s.command == "contact" || flatten(tree, s.file).count("Mechanism/Bodies") != 0)
        runnable.push_back(s);
    Tally tally;
    for (std::uint64_t i = o.first; i < o.first + o.count; ++i)
      {
        Random            random(o.seed, 3, i);
        const BaseScene  &scene = random.pick(runnable);
        const Fault       f     = draw_fault(random);
        const std::string dir   = (fs::path(o.work) / ("fault-" + std::to_string(i))).string();
        fs::remove_all(dir);
        write_tree(tree, dir);
        std::vector<std::string> problems;
        const auto               start  = std::chrono::steady_clock::now();
        const std::string        status = run_fault_case(o, scene, f, dir, problems);
        const double             wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        tally.add(scene.name + " (" + scene.command + ")",
                  f.name.substr(0, f.name.find(' ')) + ": " + status.substr(0, status.find(',')),
                  wall,
                  "fault " + std::to_string(i));
        if (o.verbose)
          std::cout << "fault " << i << "  " << scene.name << "  " << f.name << "  " << status << "  " << fixed(wall)
                    << " s\n"
                    << std::flush;
        if (!problems.empty())
          {
            std::ostringstream h;
            h << "FAIL fault seed " << o.seed << " index " << i << ": scene " << scene.name << ", " << f.name << ", "
              << status << "\n";
            for (const auto &p : problems)
              h << "  problem:  " << p << "\n";
            const auto saved = save_finding(o,
                                            "faults-s" + std::to_string(o.seed) + "-i" + std::to_string(i),
                                            dir,
                                            fault_args(o, scene, false, false),
                                            h.str());
            std::cout << h.str() << "  saved:    " << saved << "\n" << std::endl;
            tally.failures.push_back("fault " + std::to_string(i) + " (" + scene.name + ", " + f.name +
                                     "): " + problems.front());
          }
        fs::remove_all(dir);
      }
    tally.print("faults seed " + std::to_string(o.seed) + ", indices " + std::to_string(o.first) + "–" +
                std::to_string(o.first + o.count - 1));
    return tally.failures.empty() ? 0 : 1;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      const Options o = parse(argc, argv);
      fs::remove_all(o.work);
      fs::create_directories(o.work);
      const Tree tree   = read_tree(o.source);
      const auto scenes = base_scenes(tree);
      std::cout << "wearlink_fuzz " << o.campaign << ": seed " << o.seed << ", indices " << o.first << "–"
                << o.first + o.count - 1 << ", program " << o.binary << ", timeout " << o.limits.timeout_s
                << " s\n  documented exit statuses:";
      for (const int s : documented_exit_statuses)
        std::cout << " " << s;
      std::cout << "\n  scenes:";
      for (const auto &s : scenes)
        std::cout << " " << s.name;
      std::cout << "\n" << std::endl;
      if (o.campaign == "faults")
        return run_faults(o, tree, scenes);
      return o.campaign == "mutants" ? run_mutants(o, tree, scenes) : run_scenes(o, tree, scenes);
    }
  catch (const std::exception &e)
    {
      std::cerr << "wearlink_fuzz: " << e.what() << "\n";
      return 2;
    }
}
