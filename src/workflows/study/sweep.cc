// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/study/sweep.h"

#include "analysis/channels.h"
#include "analysis/recorded_run.h"
#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/json.h"
#include "base/parameters.h"
#include "base/text.h"
#include "base/timings.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/scene.h"
#include "io/scene_periods.h"
#include "workflows/run/analyses.h"
#include "workflows/run/run.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
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
              // get() of an undeclared entry only asserts in a debug build of deal.II and
              // returns "" in a release build; set() throws in both.
              prm.set(entry, prm.get(entry));
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
    run_member(const std::string        &file,
               const ParameterOverrides &base_overrides,
               const std::string        &parameter,
               const std::string        &channel,
               const std::size_t         index,
               const double              value,
               const int                 rank)
    {
      MemberResult m;
      m.index                      = index;
      m.value                      = value;
      m.rank                       = rank;
      const auto         start     = std::chrono::steady_clock::now();
      ParameterOverrides overrides = base_overrides;
      overrides.set(parameter, format_number(value));
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
        catch (const Interrupted &) // SIGINT/SIGTERM stops the sweep, not this member
          {
            throw;
          }
        catch (const std::exception &e)
          {
            m.status  = "failed";
            m.message = trim(e.what());
          }
      m.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return m;
    }

    /** The base scene must be valid, and the channel and the parameter must exist. */
    std::string
    resolve_channel(const SweepRequest &r)
    {
      const std::string &file = r.file;
      std::string        channel;
      {
        io::Scene base = io::read_scene(file, r.overrides);
        check_entry_exists(*base.parameters, r.parameter, file);
        const auto all = analysis::all_channels(*base.mechanism, base.clearance_joints);
        if (!r.channel.empty())
          channel = analysis::find_channel(all, r.channel, "--channel").name;
        else if (!base.clearance_joints.empty())
          channel = base.clearance_joints.front()->name() + "_ex_m";
        else
          throw InputError("The scene " + file +
                           " has no clearance joint; choose the channel of "
                           "the bifurcation diagram with --channel (e.g. " +
                           all.front().name + ").");
        io::driving_period(base); // a section needs a driving period
      }

      return channel;
    }

    /** Round-robin members; results serialised as JSON and gathered on rank 0 (sorted). */
    std::vector<MemberResult>
    run_members(const SweepRequest &r, const std::string &channel, const MPI_Comm comm)
    {
      const unsigned int rank      = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks   = dealii::Utilities::MPI::n_mpi_processes(comm);
      const auto        &values    = r.values;
      const auto        &parameter = r.parameter;
      Json               mine      = Json::array();
      for (std::size_t i = rank; i < values.size(); i += n_ranks)
        {
          const MemberResult m = run_member(r.file, r.overrides, parameter, channel, i, values[i], rank);
          if (!r.quiet)
            std::cerr << "[rank " << rank << "] member " << i << " (" << parameter << " = " << values[i]
                      << "): " << m.status << (m.message.empty() ? "" : ": " + m.message) << " ("
                      << std::setprecision(3) << m.wall_time << " s)\n"
                      << std::setprecision(6);
          mine.push_back(to_json(m));
        }
      const std::vector<std::string> gathered = dealii::Utilities::MPI::gather(comm, mine.dump(-1), 0);
      std::vector<MemberResult>      members;
      if (rank != 0)
        return members;

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

      return members;
    }

    /** bifurcation.csv/.png, members.csv, sweep.json and the printed table (rank 0). */
    int
    write_outputs(const SweepRequest              &r,
                  const std::string               &channel,
                  const std::vector<MemberResult> &members,
                  const double                     wall,
                  const unsigned int               n_ranks)
    {
      const std::string &out_dir   = r.output_directory;
      const std::string &parameter = r.parameter;
      const std::string &file      = r.file;
      make_output_directory(out_dir);
      std::ostringstream diagram, table;
      diagram << std::setprecision(12) << "member,parameter_value,section,time_s," << channel << "\n";
      table << std::setprecision(12) << "member,parameter_value,status,n_points,message\n";
      io::PlotSeries points;
      points.title         = "Poincaré points";
      points.look          = io::points("black", 0.4);
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
      write_file_atomically(out_dir + "/" + io::outputs::bifurcation_table, diagram.str());
      write_file_atomically(out_dir + "/" + io::outputs::sweep_members, table.str());

      io::PlotSpec plot;
      plot.title = "Bifurcation diagram: " + channel + " at the Poincaré sections vs " + parameter +
                   (n_failed ? " (" + std::to_string(n_failed) + " member(s) failed: " + failed_values + ")" : "");
      plot.x_label       = parameter;
      plot.y_label       = channel;
      plot.series        = {points};
      const bool plotted = io::plot_png(plot, out_dir + "/" + io::outputs::bifurcation_plot);

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
      write_file_atomically(out_dir + "/" + io::outputs::sweep_json, summary.dump(2) + "\n");

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

  int
  run_sweep(const SweepRequest &r)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const Stopwatch    wall;
    // Everything until the member loop is the same on every rank, so a bad input fails
    // on all ranks alike (no rank waits in a collective call).
    const std::string channel = resolve_channel(r);
    if (rank == 0)
      std::cout << "wearlink sweep: " << r.file << ", '" << r.parameter << "' over " << r.values.size()
                << " values, channel " << channel << ", " << n_ranks << " MPI rank" << (n_ranks == 1 ? "" : "s")
                << "\n";
    const auto   members = run_members(r, channel, comm);
    const double seconds = wall.seconds();
    if (rank != 0)
      return 0;
    return write_outputs(r, channel, members, seconds, n_ranks);
  }
} // namespace wearlink::workflows
