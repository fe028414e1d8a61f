// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink sweep SCENE.prm --parameter "Section/Entry" --values FROM:TO:COUNT`: run one
// scene per parameter value and draw the bifurcation diagram, the Poincaré points of one
// channel against the parameter (ARCHITECTURE.md, Scale: MPI for parameter sweeps).
//
// Parallel runs use MPI through deal.II (Utilities::MPI::MPI_InitFinalize, initialised
// only in this command): `mpirun -np N wearlink sweep ...`; the same command without
// mpirun is one rank and runs the members in turn. Member i runs on rank i mod N
// (round-robin: neighbouring values, which tend to cost alike, land on different ranks);
// each rank serialises its results and rank 0 gathers them (Utilities::MPI::gather).
// The computation of a member does not depend on the rank or on which members ran
// before it in the same process, so the diagram is the same for any number of ranks.
//
// A member whose value is invalid (outside the entry's pattern) or makes the scene
// impossible (a mechanism that cannot be assembled, a numerical failure) is reported
// with its message and the sweep goes on: this is the one place besides main() that
// catches, because one bad value must not sink a sweep.
//
// Only rank 0 writes, each file atomically (temporary name, then rename):
//   bifurcation.csv   member, parameter value, section index, time, channel value
//   members.csv       member, parameter value, status, number of points, message
//   bifurcation.png   the diagram
//   sweep.json        the command, timings per member and rank, statuses
// The two CSV files hold no timings or ranks, so serial and MPI runs give equal files.
#include "analysis/channels.h"
#include "analysis/recorded_run.h"
#include "app/command_line.h"
#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/json.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/analyses_parameters.h"
#include "io/plot.h"
#include "io/scene.h"
#include "workflows/analyses.h"
#include "workflows/run.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::app
{
  namespace
  {
    const char *const help_text =
      R"(wearlink sweep SCENE.prm --parameter "Section/Entry" --values FROM:TO:COUNT
               [--channel NAME] [--output DIR] [--set "Section/Entry=value" ...]
mpirun -np N wearlink sweep ...   (the same, members spread over N MPI ranks)

Runs SCENE once per value of one scene entry, COUNT values evenly spaced from FROM to TO
(inclusive), and draws the bifurcation diagram: the Poincaré points of one channel
(one point per driving period, from the integrator's dense output at the exact section
time) against the parameter.

The section follows the scene's 'Analyses' entries: Driving period (default 2π/|ω| of
the angle drivers), Section phase, Transient (points before Start time + Transient are
not used). Set them with --set, e.g. --set "Analyses/Transient=1". The scene's own
analyses (phase portraits, Lyapunov exponents) are not run for sweep members, and no
time series is written for them.

Options:
  --parameter PATH   the swept entry, e.g. "Joint A/Clearance/Radial clearance"
  --values F:T:N     N values from F to T (N >= 1; N = 1 gives F)
  --channel NAME     the channel drawn (default: <first clearance joint>_ex_m, the
                     journal-centre x relative to the bushing). Channels: for a body B
                     B_x_m, B_y_m, B_theta_rad, B_vx_m_s, B_vy_m_s, B_omega_rad_s; for a
                     clearance joint J J_ex_m, J_ey_m, J_vex_m_s, J_vey_m_s.
  --output DIR       output directory (default output/<scene name>_sweep)
  --set S/E=V        override another entry for every member (repeatable)
  --quiet            no per-member lines

A member whose value is invalid or whose run fails (e.g. a mechanism that cannot be
assembled) is reported in members.csv, sweep.json and on the screen; the other members
still run. Exit status: 0 if the sweep ran (even with failed members), 2 bad input
(scene, option or channel), 3 if every member failed.

Outputs in DIR (written by rank 0 only, each atomically): bifurcation.csv,
members.csv, bifurcation.png, sweep.json.
)";

    /** The swept values FROM:TO:COUNT. */
    std::vector<double>
    parse_values(const std::string &text)
    {
      const auto fail = [&](const std::string &why) {
        throw InputError("--values '" + text + "': " + why +
                         ". Give FROM:TO:COUNT, e.g. --values 1e-4:5e-4:8 (COUNT values from FROM "
                         "to TO inclusive).");
      };
      const auto parts = dealii::Utilities::split_string_list(text, ':');
      if (parts.size() != 3)
        fail("it needs three fields separated by ':'");
      double bounds[2];
      for (int k = 0; k < 2; ++k)
        {
          std::size_t used = 0;
          try
            {
              bounds[k] = std::stod(parts[k], &used);
            }
          catch (const std::exception &)
            {
              used = 0;
            }
          if (used == 0 || used != parts[k].size() || !std::isfinite(bounds[k]))
            fail("'" + parts[k] + "' is not a finite number");
        }
      long        count = 0;
      std::size_t used  = 0;
      try
        {
          count = std::stol(parts[2], &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      if (used == 0 || used != parts[2].size() || count < 1 || count > 100000)
        fail("COUNT '" + parts[2] + "' must be a whole number from 1 to 100000");
      // Evenly spaced, the ends exact. A value that is zero up to the rounding of the
      // spacing (-1e-4 + 4e-4 / 4 = -1.4e-20) is set to zero, the value the user meant.
      std::vector<double> values(count);
      const double        scale = std::max(std::abs(bounds[0]), std::abs(bounds[1]));
      for (long i = 0; i < count; ++i)
        {
          values[i] = count == 1 ? bounds[0] : bounds[0] + (bounds[1] - bounds[0]) * i / (count - 1);
          if (std::abs(values[i]) < 1e-12 * scale)
            values[i] = 0.0;
        }
      values.back() = count == 1 ? bounds[0] : bounds[1];
      return values;
    }

    /** InputError unless @p path names a declared entry of @p prm. */
    void
    check_entry_exists(dealii::ParameterHandler &prm, const std::string &path, const std::string &file)
    {
      auto                           parts = dealii::Utilities::split_string_list(path, '/');
      const std::string              entry = parts.empty() ? "" : parts.back();
      const std::vector<std::string> sections(parts.begin(), parts.empty() ? parts.end() : parts.end() - 1);
      bool                           ok = !entry.empty() && (sections.empty() || prm.subsection_path_exists(sections));
      if (ok)
        {
          for (const auto &s : sections)
            prm.enter_subsection(s);
          try
            {
              prm.get(entry);
            }
          catch (const dealii::ExceptionBase &)
            {
              ok = false;
            }
          for (std::size_t k = 0; k < sections.size(); ++k)
            prm.leave_subsection();
        }
      if (!ok)
        throw InputError("--parameter '" + path + "' is not an entry of the scene " + file +
                         ". Give the full path \"Section/Sub/Entry\", e.g. \"Joint A/Clearance/Radial "
                         "clearance\"; `wearlink --print-parameters " +
                         file + "` lists them.");
    }

    /** What one member produced. */
    struct MemberResult
    {
      std::size_t         index = 0;
      double              value = 0.0;
      std::string         status; ///< "ok", "invalid", "failed"
      std::string         message;
      std::vector<double> times, points;
      double              wall_time = 0.0;
      int                 rank      = 0;
    };

    Json
    to_json(const MemberResult &m)
    {
      Json j       = Json::object();
      j["index"]   = m.index;
      j["value"]   = m.value;
      j["status"]  = m.status;
      j["message"] = m.message;
      Json t = Json::array(), p = Json::array();
      for (const double v : m.times)
        t.push_back(v);
      for (const double v : m.points)
        p.push_back(v);
      j["times"]       = t;
      j["points"]      = p;
      j["wall_time_s"] = m.wall_time;
      j["rank"]        = m.rank;
      return j;
    }

    MemberResult
    from_json(const Json &j)
    {
      MemberResult m;
      m.index   = static_cast<std::size_t>(json_number(j.at("index")));
      m.value   = json_number(j.at("value"));
      m.status  = j.at("status").get<std::string>();
      m.message = j.at("message").get<std::string>();
      for (std::size_t k = 0; k < j.at("times").size(); ++k)
        m.times.push_back(json_number(j.at("times")[k]));
      for (std::size_t k = 0; k < j.at("points").size(); ++k)
        m.points.push_back(json_number(j.at("points")[k]));
      m.wall_time = json_number(j.at("wall_time_s"));
      m.rank      = static_cast<int>(json_number(j.at("rank")));
      return m;
    }

    std::string
    csv_quote(const std::string &s)
    {
      std::string out = "\"";
      for (const char c : s)
        out += c == '"' ? std::string("\"\"") : c == '\n' ? std::string(" ") : std::string(1, c);
      return out + "\"";
    }

    /**
     * Run member @p index: the scene with the base overrides plus parameter = value,
     * its own analyses off, a Poincaré recorder on @p channel.
     */
    MemberResult
    run_member(const std::string              &file,
               const std::vector<std::string> &base_overrides,
               const std::string              &parameter,
               const std::string              &channel,
               const std::size_t               index,
               const double                    value,
               const int                       rank)
    {
      MemberResult m;
      m.index              = index;
      m.value              = value;
      m.rank               = rank;
      const auto start     = std::chrono::steady_clock::now();
      auto       overrides = base_overrides;
      overrides.push_back(parameter + "=" + format_number(value));
      EffectLedger::instance().reset();
      std::unique_ptr<io::Scene> scene;
      try
        {
          scene = std::make_unique<io::Scene>(io::read_scene(file, overrides));
        }
      catch (const std::exception &e)
        {
          m.status  = "invalid";
          m.message = trim(e.what());
        }
      if (scene)
        try
          {
            const double               period = io::driving_period(*scene);
            const auto                &a      = scene->analyses;
            const double               t0     = scene->start_time + a.section_phase;
            const double               begin  = scene->start_time + a.transient;
            const double               first  = t0 + period * std::ceil(std::max(0.0, begin - t0) / period - 1e-9);
            const auto                 all    = analysis::all_channels(*scene->mechanism, scene->clearance_joints);
            analysis::PoincareRecorder section({analysis::find_channel(all, channel, "--channel")}, first, period);
            // The member needs its section only: the scene's own analyses and time
            // series are switched off.
            scene->analyses.phase_portrait = scene->analyses.poincare = scene->analyses.lyapunov = false;
            scene->write_time_series                                                             = false;
            workflows::RunOptions options;
            options.observers = {&section};
            workflows::run_scene(*scene, options);
            m.status = "ok";
            m.times  = section.section().points.time;
            m.points = section.section().points.values.front();
          }
        catch (const std::exception &e)
          {
            m.status  = "failed";
            m.message = trim(e.what());
          }
      m.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return m;
    }

    int
    run(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--parameter", true},
                                      {"--values", true},
                                      {"--channel", true},
                                      {"--output", true},
                                      {"--set", true, true},
                                      {"--quiet", false}},
                                     "sweep");
      // MPI for this command only. One thread per rank: the ranks are the parallelism.
      int                                      argc           = 1;
      char                                     program[]      = "wearlink";
      char                                    *argv_storage[] = {program, nullptr};
      char                                   **argv           = argv_storage;
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const MPI_Comm                           comm       = MPI_COMM_WORLD;
      const unsigned int                       rank       = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int                       n_ranks    = dealii::Utilities::MPI::n_mpi_processes(comm);
      const auto                               wall_start = std::chrono::steady_clock::now();

      // Everything below until the member loop is the same on every rank, so a bad
      // input fails on all ranks alike (no rank waits in a collective call).
      if (a.positional.size() != 1)
        throw InputError("`wearlink sweep` needs exactly one scene file (given " + std::to_string(a.positional.size()) +
                         "). See `wearlink sweep --help`.");
      const std::string file = a.positional[0];
      if (!a.has("--parameter") || !a.has("--values"))
        throw InputError("`wearlink sweep` needs --parameter \"Section/Entry\" and --values "
                         "FROM:TO:COUNT. See `wearlink sweep --help`.");
      const std::string              parameter = a.value("--parameter");
      const std::vector<double>      values    = parse_values(a.value("--values"));
      const std::vector<std::string> sets      = a.all("--set");
      const std::string              out_dir =
        a.value("--output", "output/" + std::filesystem::path(file).stem().string() + "_sweep");

      // The base scene must be valid, and the channel and the parameter must exist.
      std::string channel;
      {
        io::Scene base = io::read_scene(file, sets);
        check_entry_exists(*base.parameters, parameter, file);
        const auto all = analysis::all_channels(*base.mechanism, base.clearance_joints);
        if (a.has("--channel"))
          channel = analysis::find_channel(all, a.value("--channel"), "--channel").name;
        else if (!base.clearance_joints.empty())
          channel = base.clearance_joints.front()->name() + "_ex_m";
        else
          throw InputError("The scene " + file +
                           " has no clearance joint; choose the channel of "
                           "the bifurcation diagram with --channel (e.g. " +
                           all.front().name + ").");
        io::driving_period(base); // a section needs a driving period
      }

      if (rank == 0)
        std::cout << "wearlink sweep: " << file << ", '" << parameter << "' over " << values.size()
                  << " values, channel " << channel << ", " << n_ranks << " MPI rank" << (n_ranks == 1 ? "" : "s")
                  << "\n";

      // Round-robin members; results serialised as JSON and gathered on rank 0.
      Json mine = Json::array();
      for (std::size_t i = rank; i < values.size(); i += n_ranks)
        {
          const MemberResult m = run_member(file, sets, parameter, channel, i, values[i], rank);
          if (!a.has("--quiet"))
            std::cerr << "[rank " << rank << "] member " << i << " (" << parameter << " = " << values[i]
                      << "): " << m.status << (m.message.empty() ? "" : ": " + m.message) << " ("
                      << std::setprecision(3) << m.wall_time << " s)\n"
                      << std::setprecision(6);
          mine.push_back(to_json(m));
        }
      const std::vector<std::string> gathered = dealii::Utilities::MPI::gather(comm, mine.dump(-1), 0);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      if (rank != 0)
        return 0;

      std::vector<MemberResult> members;
      for (const auto &text : gathered)
        {
          const Json j = Json::parse(text);
          for (std::size_t k = 0; k < j.size(); ++k)
            members.push_back(from_json(j[k]));
        }
      std::sort(members.begin(), members.end(), [](const MemberResult &x, const MemberResult &y) {
        return x.index < y.index;
      });
      Assert(members.size() == values.size(), dealii::ExcInternalError());

      // Outputs (rank 0), each atomically.
      make_output_directory(out_dir);
      std::ostringstream diagram, table;
      diagram << std::setprecision(12) << "member,parameter_value,section,time_s," << channel << "\n";
      table << std::setprecision(12) << "member,parameter_value,status,n_points,message\n";
      io::PlotSeries points;
      points.title         = "Poincaré points";
      points.style         = "points";
      points.options       = "pt 7 ps 0.4 lc rgb 'black'";
      std::size_t n_failed = 0;
      std::string failed_values;
      for (const auto &m : members)
        {
          table << m.index << ',' << m.value << ',' << m.status << ',' << m.points.size() << ',' << csv_quote(m.message)
                << '\n';
          if (m.status != "ok")
            {
              ++n_failed;
              failed_values += (failed_values.empty() ? "" : ", ") + format_number(m.value);
            }
          for (std::size_t k = 0; k < m.points.size(); ++k)
            {
              diagram << m.index << ',' << m.value << ',' << k << ',' << m.times[k] << ',' << m.points[k] << '\n';
              points.x.push_back(m.value);
              points.y.push_back(m.points[k]);
            }
        }
      write_file_atomically(out_dir + "/bifurcation.csv", diagram.str());
      write_file_atomically(out_dir + "/members.csv", table.str());

      io::PlotSpec plot;
      plot.title = "Bifurcation diagram: " + channel + " at the Poincaré sections vs " + parameter +
                   (n_failed ? " (" + std::to_string(n_failed) + " member(s) failed: " + failed_values + ")" : "");
      plot.x_label       = parameter;
      plot.y_label       = channel;
      plot.series        = {points};
      const bool plotted = io::plot_png(plot, out_dir + "/bifurcation.png");

      Json summary           = Json::object();
      summary["scene"]       = file;
      summary["parameter"]   = parameter;
      summary["channel"]     = channel;
      summary["n_members"]   = members.size();
      summary["n_failed"]    = n_failed;
      summary["mpi_ranks"]   = n_ranks;
      summary["wall_time_s"] = wall;
      double member_time     = 0.0;
      Json   list            = Json::array();
      for (const auto &m : members)
        {
          member_time += m.wall_time;
          Json j           = Json::object();
          j["index"]       = m.index;
          j["value"]       = m.value;
          j["status"]      = m.status;
          j["message"]     = m.message;
          j["n_points"]    = m.points.size();
          j["rank"]        = m.rank;
          j["wall_time_s"] = m.wall_time;
          list.push_back(j);
        }
      summary["sum_of_member_wall_times_s"] = member_time;
      summary["members"]                    = list;
      write_file_atomically(out_dir + "/sweep.json", summary.dump(2) + "\n");

      std::cout << "  member  value           status   points\n";
      for (const auto &m : members)
        std::cout << "  " << std::setw(6) << m.index << "  " << std::setw(14) << std::setprecision(6) << m.value << "  "
                  << std::setw(7) << m.status << "  " << std::setw(6) << m.points.size()
                  << (m.message.empty() ? "" : "  " + m.message.substr(0, m.message.find('\n'))) << "\n";
      std::cout << "  " << members.size() - n_failed << " of " << members.size() << " members ran; wall "
                << std::setprecision(4) << wall << " s on " << n_ranks << " rank(s), sum of member times "
                << member_time << " s\n  wrote " << out_dir << "/bifurcation.csv, members.csv, sweep.json"
                << (plotted ? ", bifurcation.png" : " (no PNG: gnuplot missing)") << "\n";
      return n_failed == members.size() ? 3 : 0;
    }
  } // namespace

  extern const Command sweep_command;
  const Command        sweep_command = {"sweep",
                                        "sweep SCENE.prm --parameter \"S/E\" --values FROM:TO:COUNT [--channel NAME] "
                                               "[--output DIR]  bifurcation diagram (MPI: mpirun -np N wearlink sweep ...)",
                                        help_text,
                                        run};
} // namespace wearlink::app
