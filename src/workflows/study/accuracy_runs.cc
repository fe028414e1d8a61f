// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/study/accuracy_runs.h"

#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/timings.h"
#include "io/scene_periods.h"
#include "io/wear_outputs.h"
#include "workflows/run/run.h"
#include "workflows/wear/wear_run.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    /** Peak normal force of every clearance joint and peak |a| of one body. */
    class PeakObserver : public mbs::StepObserver
    {
    public:
      PeakObserver(const io::Scene &scene, int body)
        : scene(scene)
        , body(body)
        , force(scene.clearance_joints.size(), 0.0)
      {
      }
      void
      on_step(const mbs::StepContext &c) override
      {
        const auto           n = scene.mechanism->n_coordinates();
        const mbs::StateView s(c.y.data(), c.y.data() + n);
        for (std::size_t k = 0; k < force.size(); ++k)
          force[k] = std::max(force[k], scene.clearance_joints[k]->diagnostics(s).normal_force);
        acceleration = std::max(acceleration, std::hypot(c.dydt[n + 3 * body], c.dydt[n + 3 * body + 1]));
      }
      const io::Scene    &scene;
      const int           body;
      std::vector<double> force;
      double              acceleration = 0;
    };

  } // namespace

  Measurement
  measure(const std::string &file, const ParameterOverrides &overrides)
  {
    Measurement   m;
    const auto    t0 = std::chrono::steady_clock::now();
    const clock_t c0 = std::clock();
    try
      {
        io::Scene    scene = io::read_scene(file, overrides);
        PeakObserver peaks(scene, io::response_body(scene));
        if (has_wear(scene))
          {
            WearRunOptions w;
            w.progress      = false;
            w.final_outputs = false;
            w.observers     = {&peaks};
            const auto r    = run_wear(scene, w);
            for (const auto &js : r.state.joints)
              {
                const auto &h                         = js.history.back();
                m.quantities[js.name + " V_pin"]      = h.volume_pin;
                m.quantities[js.name + " V_bush"]     = h.volume_bore;
                m.quantities[js.name + " h_pin"]      = h.max_depth_pin;
                m.quantities[js.name + " h_bush"]     = h.max_depth_bore;
                m.quantities[js.name + " he_pin"]     = h.envelope_depth_pin;
                m.quantities[js.name + " he_bush"]    = h.envelope_depth_bore;
                m.quantities[js.name + " rough_pin"]  = h.roughness_pin;
                m.quantities[js.name + " rough_bush"] = h.roughness_bore;
                m.profiles[js.name + " profile_pin"]  = h.depth_pin;
                m.profiles[js.name + " profile_bush"] = h.depth_bore;
              }
          }
        else
          {
            RunOptions o;
            o.observers = {&peaks};
            run_scene(scene, o);
          }
        for (std::size_t k = 0; k < peaks.force.size(); ++k)
          m.quantities[scene.clearance_joints[k]->name() + " F_peak"] = peaks.force[k];
        m.quantities["a_peak"] = peaks.acceleration;
      }
    catch (const Interrupted &) // SIGINT/SIGTERM stops the study, not this row
      {
        throw;
      }
    catch (const Error &e)
      {
        m.ok      = false;
        m.failure = e.message();
      }
    m.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    m.cpu_time  = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    return m;
  }


  Json
  to_json(const Measurement &m)
  {
    Json j           = Json::object();
    j["ok"]          = m.ok;
    j["failure"]     = m.failure;
    j["wall_time_s"] = m.wall_time;
    j["cpu_time_s"]  = m.cpu_time;
    j["quantities"]  = m.quantities;
    j["profiles"]    = m.profiles;
    return j;
  }

  Measurement
  measurement_from_json(const Json &j)
  {
    Measurement m;
    m.ok        = j.at("ok").get<bool>();
    m.failure   = j.at("failure").get<std::string>();
    m.wall_time = json_number(j.at("wall_time_s"));
    m.cpu_time  = json_number(j.at("cpu_time_s"));
    for (auto it = j.at("quantities").begin(); it != j.at("quantities").end(); ++it)
      m.quantities[it.key()] = it.value().is_number() ? json_number(it.value()) : std::nan("");
    for (auto it = j.at("profiles").begin(); it != j.at("profiles").end(); ++it)
      for (const auto &v : it.value())
        m.profiles[it.key()].push_back(v.is_number() ? json_number(v) : std::nan(""));
    return m;
  }

  double
  predicted_cost(const io::Scene &scene, const io::Scene &reference)
  {
    double cycles = 1;
    if (has_wear(scene))
      cycles = scene.wear_loop.n_iterations * scene.wear_loop.cycles_per_iteration;
    else if (const double period = io::driving_period_if_known(scene); period > 0)
      cycles = (scene.end_time - scene.start_time) / period;
    const auto &in = scene.simulation.integrator, &ref = reference.simulation.integrator;
    double      f = 1;
    if (in.type == mbs::IntegratorType::rk4 && ref.type == mbs::IntegratorType::rk4)
      f = ref.time_step / in.time_step;
    else if (in.type != mbs::IntegratorType::rk4 && ref.type != mbs::IntegratorType::rk4)
      f = std::pow(ref.relative_tolerance / in.relative_tolerance, 0.2);
    if (in.type == mbs::IntegratorType::dop853)
      f *= 1.3;
    for (const auto &w : scene.wear)
      if (w->pressure_model == "fe")
        {
          f *= 2;
          break;
        }
    return std::max(cycles, 1e-3) * f;
  }

  bool
  is_study_root()
  {
    int initialised = 0;
    MPI_Initialized(&initialised);
    return !initialised || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  namespace
  {
    /** The jobs by predicted cost, largest first (ties in plan order). */
    std::vector<std::size_t>
    largest_first(const std::vector<StudyJob> &jobs)
    {
      std::vector<std::size_t> order(jobs.size());
      for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return jobs[a].cost > jobs[b].cost;
      });
      return order;
    }

    /** "3 min 20 s", "45 s". */
    std::string
    duration(const double seconds)
    {
      std::ostringstream os;
      const long         s = std::lround(std::max(0.0, seconds));
      if (s >= 60)
        os << s / 60 << " min " << s % 60 << " s";
      else
        os << s << " s";
      return os.str();
    }

    /**
     * The queue of a study's jobs shared by the ranks: a counter on rank 0 that every
     * rank increments atomically (MPI one-sided, passive target) when it is free, so a
     * rank never waits while jobs are left. Without MPI (or on one rank), a plain counter.
     */
    class JobQueue
    {
    public:
      JobQueue(const MPI_Comm comm, const bool shared)
        : comm(comm)
        , shared(shared)
      {
        if (!shared)
          return;
        long *base = nullptr;
        MPI_Win_allocate(dealii::Utilities::MPI::this_mpi_process(comm) == 0 ? sizeof(long) : 0,
                         sizeof(long),
                         MPI_INFO_NULL,
                         comm,
                         &base,
                         &window);
        if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
          {
            const long zero = 0;
            MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window);
            MPI_Put(&zero, 1, MPI_LONG, 0, 0, 1, MPI_LONG, window);
            MPI_Win_unlock(0, window);
          }
        MPI_Barrier(comm);
        MPI_Win_lock_all(0, window);
      }
      ~JobQueue()
      {
        if (!shared)
          return;
        MPI_Win_unlock_all(window);
        MPI_Win_free(&window);
      }
      JobQueue(const JobQueue &) = delete;
      JobQueue &
      operator=(const JobQueue &) = delete;

      /** The position of the next job to run. */
      std::size_t
      next()
      {
        if (!shared)
          return taken++;
        const long one = 1;
        long       position;
        MPI_Fetch_and_op(&one, &position, MPI_LONG, 0, 0, MPI_SUM, window);
        MPI_Win_flush(0, window);
        return static_cast<std::size_t>(position);
      }

    private:
      MPI_Comm    comm;
      bool        shared;
      MPI_Win     window = MPI_WIN_NULL;
      std::size_t taken  = 0;
    };

    /**
     * Run jobs from the queue until none is left, with a line per run and the estimated
     * time left: the predicted cost of the jobs not yet taken, shared by the ranks, at
     * this rank's measured seconds per unit of predicted cost.
     */
    Json
    run_from_queue(const std::string           &file,
                   const std::vector<StudyJob> &jobs,
                   JobQueue                    &queue,
                   const unsigned int           rank,
                   const unsigned int           n_ranks,
                   const bool                   progress)
    {
      const auto        order     = largest_first(jobs);
      const std::string who       = n_ranks > 1 ? " rank " + std::to_string(rank) : std::string();
      Json              out       = Json::array();
      double            done_cost = 0, done_seconds = 0, cpu = 0;
      for (std::size_t position = queue.next(); position < order.size(); position = queue.next())
        {
          const auto       &job = jobs[order[position]];
          const Measurement m   = measure(file, job.overrides);
          out.push_back({{"job", order[position]}, {"measurement", to_json(m)}});
          done_cost += job.cost;
          done_seconds += m.wall_time;
          cpu += m.cpu_time;
          if (!progress)
            continue;
          double left = 0;
          for (std::size_t k = position + 1; k < order.size(); ++k)
            left += jobs[order[k]].cost;
          std::ostringstream os;
          os << "[wearlink] study" << who << "  run " << position + 1 << '/' << order.size() << "  " << job.label
             << "  " << std::setprecision(3) << m.wall_time << " s" << (m.ok ? "" : "  FAILED: " + m.failure)
             << "  (about " << duration(left / n_ranks * done_seconds / done_cost) << " left)\n";
          std::cerr << os.str();
        }
      if (progress)
        std::cerr << "[wearlink] study" << who << ": " << out.size() << " runs, " << duration(done_seconds) << " wall, "
                  << duration(cpu) << " CPU (its wall time on a core of its own)\n";
      return out;
    }
  } // namespace

  std::vector<Measurement>
  measure_jobs(const std::string &file, const std::vector<StudyJob> &jobs, const bool progress)
  {
    int initialised = 0;
    MPI_Initialized(&initialised);
    const MPI_Comm           comm    = MPI_COMM_WORLD;
    const unsigned int       rank    = initialised ? dealii::Utilities::MPI::this_mpi_process(comm) : 0;
    const unsigned int       n_ranks = initialised ? dealii::Utilities::MPI::n_mpi_processes(comm) : 1;
    std::vector<std::string> gathered;
    {
      JobQueue   queue(comm, n_ranks > 1);
      const Json mine = run_from_queue(file, jobs, queue, rank, n_ranks, progress);
      gathered =
        n_ranks > 1 ? dealii::Utilities::MPI::gather(comm, mine.dump(-1), 0) : std::vector<std::string>{mine.dump(-1)};
    }
    std::vector<Measurement> all(jobs.size());
    if (rank != 0)
      return {};
    for (const auto &text : gathered)
      for (const auto &entry : Json::parse(text))
        all[static_cast<std::size_t>(json_number(entry.at("job")))] = measurement_from_json(entry.at("measurement"));
    return all;
  }
} // namespace wearlink::workflows
