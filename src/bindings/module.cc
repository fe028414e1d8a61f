// SPDX-License-Identifier: LGPL-2.1-or-later
// The C++ part of the Python module `wearlink` (doc/python.md): a layer beside app/ that
// calls the same workflows. It reads scenes through io::read_scene (the same validation
// and messages as the program), runs them into an output folder it holds as the program
// does, and hands back the summary, the worn profiles and the CSV tables as numpy arrays
// that own the C++ storage (no copy). The Python package (bindings/python/wearlink/) builds
// its objects on top: Scene, run(), life(), Result, Table.
//
// The GIL is released while a scene is read or run, so that other Python threads and a
// Jupyter kernel stay responsive; a progress callback takes the GIL back for its call.
// In the interpreter's main thread SIGINT stops a run as it stops the program (the run
// throws at its next check, its temporary files are removed) and is raised as
// wearlink.Interrupted, a KeyboardInterrupt.
#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/json.h"
#include "base/output_directory.h"
#include "io/contact_case.h"
#include "io/csv.h"
#include "io/output_names.h"
#include "io/scene.h"
#include "register_all.h"
#include "workflows/compare/contact_comparison.h"
#include "workflows/ensemble/ensemble.h"
#include "workflows/ensemble/uncertain_inputs.h"
#include "workflows/run/contact_case.h"
#include "workflows/run/first_look.h"
#include "workflows/run/run.h"
#include "workflows/study/accuracy_study.h"
#include "workflows/study/convergence_study.h"
#include "workflows/wear/calibration.h"
#include "workflows/wear/life.h"
#include "workflows/wear/wear_run.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;

namespace wearlink::bindings
{
  namespace
  {
    /**
     * @p v as a float64 array of @p shape (C order) without a copy: the array owns the
     * vector's storage through a capsule.
     */
    py::array_t<double>
    array_of(std::vector<double> &&v, std::vector<py::ssize_t> shape = {})
    {
      if (shape.empty())
        shape = {static_cast<py::ssize_t>(v.size())};
      auto       *held = new std::vector<double>(std::move(v));
      py::capsule owner(held, [](void *p) { delete static_cast<std::vector<double> *>(p); });
      return py::array_t<double>(shape, held->data(), owner);
    }

    /** The scene in @p file with the entries @p sets ("Section/Entry=value"), read with the GIL released. */
    io::Scene
    read(const std::string &file, const std::vector<std::string> &sets)
    {
      py::gil_scoped_release released;
      return io::read_scene(file, ParameterOverrides(sets));
    }

    /** What Scene shows of a scene: its title, bodies and clearance joints, and whether it wears. */
    py::dict
    describe(const std::string &file, const std::vector<std::string> &sets)
    {
      const auto               scene = read(file, sets);
      std::vector<std::string> bodies, joints, wearing;
      for (const auto &b : scene.mechanism->get_bodies())
        bodies.push_back(b.name);
      for (const auto *j : scene.clearance_joints)
        joints.push_back(j->name());
      for (const auto &w : scene.wear)
        wearing.push_back(w->joint);
      py::dict d;
      d["title"]            = scene.title;
      d["bodies"]           = bodies;
      d["clearance_joints"] = joints;
      d["wearing_joints"]   = wearing;
      d["start_time_s"]     = scene.start_time;
      d["end_time_s"]       = scene.end_time;
      return d;
    }

    /** The value of the entry @p path ("Section/Subsection/Entry") of the scene, as text. */
    std::string
    entry(const std::string &file, const std::vector<std::string> &sets, const std::string &path)
    {
      const auto scene = read(file, sets);
      // The tree of every entry with its value (a name without its entry is not in it).
      std::ostringstream tree;
      scene.parameters->print_parameters(tree, dealii::ParameterHandler::ShortJSON);
      const Json               all = Json::parse(tree.str());
      const Json              *at  = &all;
      std::stringstream        in(path);
      std::vector<std::string> parts;
      for (std::string p; std::getline(in, p, '/');)
        parts.push_back(p);
      for (const auto &p : parts)
        {
          if (!at->is_object() || !at->contains(p))
            {
              at = nullptr;
              break;
            }
          at = &at->at(p);
        }
      if (at == nullptr || !at->is_string())
        throw InputError("In " + file + ", there is no entry '" + path + "'" +
                         (at != nullptr ? " (it is a section: name one of its entries)" : "") +
                         ". `wearlink --print-parameters " + file + "` lists every entry the scene can have.");
      return at->get<std::string>();
    }

    /** The worn profiles of every wearing joint: radii [m] at `angle_rad`, now and at the start. */
    py::dict
    profiles_of(wear::WearState &&st)
    {
      py::dict out;
      for (auto &j : st.joints)
        {
          std::vector<double> angles(j.bore.n_points());
          for (unsigned int k = 0; k < angles.size(); ++k)
            angles[k] = j.bore.angle(k);
          py::dict d;
          d["angle_rad"]      = array_of(std::move(angles));
          d["bore"]           = array_of(std::move(j.bore.samples()));
          d["pin"]            = array_of(std::move(j.pin.samples()));
          d["initial_bore"]   = array_of(std::move(j.initial_bore.samples()));
          d["initial_pin"]    = array_of(std::move(j.initial_pin.samples()));
          out[j.name.c_str()] = d;
        }
      return out;
    }

    /**
     * The progress callback of a run: @p callback (a Python callable taking the fraction
     * and the progress line), called with the GIL.
     */
    workflows::ProgressCallback
    progress_of(const py::object &callback)
    {
      if (callback.is_none())
        return {};
      return [callback](const double fraction, const std::string &line) {
        py::gil_scoped_acquire held;
        callback(fraction, line);
      };
    }

    /**
     * @p work without the GIL and, if @p catch_interrupt, with SIGINT stopping it (the
     * work throws Interrupted at its next check, or this does right after it): how every
     * command of the module runs its C++.
     */
    template <class Work>
    void
    in_cpp(const bool catch_interrupt, Work &&work)
    {
      std::optional<InterruptScope> interrupts;
      py::gil_scoped_release        released;
      if (catch_interrupt)
        interrupts.emplace();
      work();
      throw_if_interrupted();
    }

    /**
     * @p directory held for a command that writes @p files (created; an earlier run's files
     * refused, or removed with @p overwrite): from rank 0 once MPI runs, every rank getting
     * its refusal.
     */
    std::unique_ptr<OutputDirectory>
    hold(const std::string &directory, const bool overwrite, const RunFiles &files)
    {
      const auto make = [&] {
        return std::make_unique<OutputDirectory>(directory,
                                                 overwrite ? EarlierRun::overwrite : EarlierRun::refuse,
                                                 files,
                                                 "Give it a new or empty folder, or overwrite=True.");
      };
      int mpi_started = 0;
      MPI_Initialized(&mpi_started);
      return mpi_started ? workflows::held_on_root(make) : make();
    }

    /** A command's answer: its report (the table the program prints) and its summary (JSON text, or ""). */
    py::dict
    answer(const std::string &report, const std::string &summary)
    {
      py::dict d;
      d["summary"]  = summary;
      d["report"]   = report;
      d["wear"]     = false;
      d["profiles"] = py::dict();
      return d;
    }

    /** What a run hands back to run()'s caller. */
    struct Outcome
    {
      std::string                    summary; ///< summary.json's text
      std::optional<wear::WearState> state;   ///< of a wear run
    };

    /** A command's work on the scene read, into the folder held, telling @p progress. */
    using Work = std::function<Outcome(io::Scene &, const std::string &, const workflows::ProgressCallback &)>;

    /**
     * Read the scene in @p file with @p sets, hold @p directory (created; it must hold no
     * earlier run's files, unless @p overwrite: then those are removed) and do @p work in
     * it, without the GIL and, if @p catch_interrupt, with SIGINT stopping it. Returns the
     * summary (JSON text), whether it wore, and the worn profiles.
     */
    py::dict
    held_run(const std::string                            &file,
             const std::vector<std::string>               &sets,
             const std::string                            &directory,
             const bool                                    overwrite,
             const py::object                             &callback,
             const bool                                    catch_interrupt,
             const Work                                   &work,
             const std::function<void(const io::Scene &)> &check = {})
    {
      const auto progress = progress_of(callback);
      Outcome    outcome;
      in_cpp(catch_interrupt, [&] {
        auto scene = io::read_scene(file, ParameterOverrides(sets));
        if (check)
          check(scene); // before the folder is held: bad input writes nothing
        const auto held = hold(directory, overwrite, io::outputs::run());
        outcome         = work(scene, directory, progress);
      });
      py::dict d;
      d["summary"]  = outcome.summary;
      d["wear"]     = outcome.state.has_value();
      d["profiles"] = outcome.state ? profiles_of(std::move(*outcome.state)) : py::dict();
      return d;
    }

    /** `wearlink run`'s work: the wear loop if a joint wears, else one run with its first look. */
    Outcome
    run_work(io::Scene &scene, const std::string &dir, const workflows::ProgressCallback &progress)
    {
      Outcome o;
      if (workflows::has_wear(scene))
        {
          workflows::WearRunOptions w;
          w.output_directory = dir;
          w.progress         = false;
          w.on_progress      = progress;
          auto r             = workflows::run_wear(scene, w);
          o.summary          = r.summary.dump();
          o.state            = std::move(r.state);
        }
      else
        {
          workflows::RunOptions ro;
          ro.output_directory = dir;
          ro.on_progress      = progress;
          o.summary           = workflows::run_with_first_look(scene, ro).summary.dump();
        }
      return o;
    }

    /** `wearlink life`'s work: the wear loop until the scene's Life criteria are decided. */
    Outcome
    life_work(io::Scene &scene, const std::string &dir, const workflows::ProgressCallback &progress)
    {
      workflows::LifeRunOptions l;
      l.output_directory = dir;
      l.progress         = false;
      l.on_progress      = progress;
      auto    r          = workflows::run_life(scene, l);
      Outcome o;
      o.summary = r.wear.summary.dump();
      o.state   = std::move(r.wear.state);
      return o;
    }

    /** The command @p command ("run" or "life") on the scene, as held_run() says. */
    py::dict
    execute(const std::string              &command,
            const std::string              &file,
            const std::vector<std::string> &sets,
            const std::string              &directory,
            const bool                      overwrite,
            const py::object               &callback,
            const bool                      catch_interrupt)
    {
      if (command == "life")
        return held_run(file, sets, directory, overwrite, callback, catch_interrupt, life_work, [](const io::Scene &s) {
          workflows::check_life_criteria(s);
        });
      if (command == "run")
        return held_run(file, sets, directory, overwrite, callback, catch_interrupt, run_work);
      throw InputError("The module runs the commands run and life, not '" + command + "'.");
    }

    /** MPI for the ensembles: started at the first one (unless started already), finished at exit. */
    std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;

    void
    start_mpi()
    {
      int started = 0;
      MPI_Initialized(&started);
      if (started)
        return;
      static int    argc           = 1;
      static char   program[]      = "python3";
      static char  *argv_storage[] = {program, nullptr};
      static char **argv           = argv_storage;
      mpi                          = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
      py::module_::import("atexit").attr("register")(py::cpp_function([] { mpi.reset(); }));
    }

    /** This process's rank and the number of ranks (MPI started). */
    py::tuple
    mpi_ranks()
    {
      start_mpi();
      return py::make_tuple(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD),
                            dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    }

    /** What runs one member of a `run` (@p life false) or a `life` ensemble. */
    workflows::MemberRun
    member_run(const bool life)
    {
      return [life](io::Scene &scene, const std::string &dir, const std::string &, const bool resume) {
        if (life)
          {
            workflows::LifeRunOptions l;
            l.output_directory = dir;
            l.resume           = resume;
            l.progress         = false;
            return workflows::run_life(scene, l).wear.summary;
          }
        if (workflows::has_wear(scene))
          {
            workflows::WearRunOptions w;
            w.output_directory = dir;
            w.resume           = resume;
            w.progress         = false;
            return workflows::run_wear(scene, w).summary;
          }
        workflows::RunOptions ro;
        ro.output_directory = dir;
        return workflows::run_scene(scene, ro);
      };
    }

    /**
     * `wearlink run|life --ensemble N` (@p command "run" or "life") of the scene into
     * @p directory, its members over the MPI ranks; every rank gets the ensemble's summary.
     */
    py::dict
    ensemble(const std::string              &command,
             const std::string              &file,
             const std::vector<std::string> &sets,
             const std::string              &directory,
             const bool                      overwrite,
             const double                    members,
             const double                    seed,
             const double                    perturbation,
             const bool                      saltelli,
             const bool                      catch_interrupt)
    {
      if (command != "run" && command != "life")
        throw InputError("An ensemble runs the command run or life, not '" + command + "'.");
      start_mpi();
      workflows::EnsembleOptions o;
      o.scene_file       = file;
      o.overrides        = ParameterOverrides(sets);
      o.request          = workflows::ensemble_request(members, seed, perturbation, saltelli);
      o.command          = command;
      o.output_directory = directory;
      o.progress         = false;
      std::string summary;
      bool        all_failed = false;
      in_cpp(catch_interrupt, [&] {
        const auto scene = io::read_scene(file, o.overrides);
        if (command == "life")
          workflows::check_life_criteria(scene);
        workflows::check_uncertain_members(o, scene); // before the folder is held: bad input writes nothing
        const auto held =
          hold(directory, overwrite, workflows::ensemble_files(directory, o.request.members, io::outputs::run()));
        const Json s = workflows::run_ensemble(o, member_run(command == "life"), all_failed);
        summary      = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, s.dump(), 0);
      });
      if (all_failed)
        throw NumericalError("Every member of the ensemble failed; " + directory +
                             "/summary.json has each member's message.");
      return answer("", summary);
    }

    /** `wearlink compare-contact`: the simplified contact laws against the FE model, into @p directory. */
    py::dict
    compare_contact(const std::string              &file,
                    const std::vector<std::string> &sets,
                    const std::string              &directory,
                    const bool                      overwrite,
                    const std::string              &worn,
                    const double                    cycles,
                    const bool                      effects,
                    const bool                      catch_interrupt)
    {
      workflows::ContactComparisonRequest r;
      r.scene_file     = file;
      r.overrides      = ParameterOverrides(sets);
      r.worn_directory = worn;
      r.cycles         = cycles;
      r.effects        = effects;
      r.progress       = false;
      std::string report;
      in_cpp(catch_interrupt, [&] {
        const auto held = hold(directory, overwrite, io::outputs::compare_contact());
        const auto c    = workflows::compare_contact(r);
        workflows::write_contact_comparison(directory, c);
        report = c.table();
      });
      return answer(report, "");
    }

    /** `wearlink contact`: the FE contact of one pin–bushing pair (a contact case file), into @p directory. */
    py::dict
    contact(const std::string              &file,
            const std::vector<std::string> &sets,
            const std::string              &directory,
            const bool                      overwrite,
            const bool                      catch_interrupt)
    {
      start_mpi();
      std::string summary;
      in_cpp(catch_interrupt, [&] {
        dealii::ParameterHandler prm;
        io::declare_contact_case(prm);
        const auto                contact_case = io::load_contact_case(prm, file, sets);
        workflows::ContactCaseRun run;
        run.output_directory = directory;
        run.root             = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
        run.n_ranks          = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
        const auto held      = hold(directory, overwrite, io::outputs::contact());
        summary              = workflows::run_contact_case(contact_case, prm, run).dump();
      });
      return answer("", summary);
    }

    /** The accuracy study's Markdown (rank 0; "" elsewhere), its files written into @p directory. */
    std::string
    accuracy_report(const std::string              &file,
                    const std::vector<std::string> &sets,
                    const std::string              &directory,
                    const bool                      quick,
                    const std::vector<std::string> &knobs,
                    const std::string              &study_file,
                    const workflows::FloorEnsemble &floor)
    {
      workflows::StudyRequest r;
      r.overrides = sets;
      r.quick     = quick;
      r.progress  = false;
      if (!study_file.empty())
        workflows::read_study_file(study_file, r);
      if (!knobs.empty())
        r.knobs = knobs;
      r.floor_members = floor.members;
      r.seed          = floor.seed;
      r.perturbation  = floor.perturbation;
      const auto s    = workflows::run_accuracy_study(file, r);
      if (!s.root)
        return "";
      workflows::write_accuracy_study(directory, s);
      return s.markdown();
    }

    /** The convergence study's Markdown (rank 0; "" elsewhere), its files written into @p directory. */
    std::string
    convergence_report(const std::string              &file,
                       const std::vector<std::string> &sets,
                       const std::string              &directory,
                       const std::vector<double>      &refinements,
                       const workflows::FloorEnsemble &floor)
    {
      workflows::ConvergenceRequest r;
      r.overrides    = ParameterOverrides(sets);
      r.refinements  = refinements;
      r.members      = floor.members;
      r.seed         = floor.seed;
      r.perturbation = floor.perturbation;
      r.progress     = false;
      const auto s   = workflows::run_convergence_study(file, r);
      if (!s.root)
        return "";
      workflows::write_convergence_study(directory, s);
      return s.markdown();
    }

    /**
     * `wearlink study accuracy|convergence` (@p kind) of the scene into @p directory: the
     * accuracy study (@p quick, @p knobs, a study file @p study_file) or the convergence
     * study (@p refinements), with a chaos floor of @p members perturbed runs. The report
     * (the study's Markdown) on every rank.
     */
    py::dict
    study(const std::string              &kind,
          const std::string              &file,
          const std::vector<std::string> &sets,
          const std::string              &directory,
          const bool                      overwrite,
          const bool                      quick,
          const std::vector<std::string> &knobs,
          const std::string              &study_file,
          const std::vector<double>      &refinements,
          const double                    members,
          const double                    seed,
          const double                    perturbation,
          const bool                      catch_interrupt)
    {
      if (kind != "accuracy" && kind != "convergence")
        throw InputError("A study is 'accuracy' or 'convergence', not '" + kind + "'.");
      const auto floor    = workflows::floor_ensemble(members, seed, perturbation);
      const bool accuracy = kind == "accuracy";
      start_mpi();
      std::string report;
      in_cpp(catch_interrupt, [&] {
        const auto held =
          hold(directory, overwrite, accuracy ? io::outputs::accuracy_study() : io::outputs::convergence_study());
        report = accuracy ? accuracy_report(file, sets, directory, quick, knobs, study_file, floor) :
                            convergence_report(file, sets, directory, refinements, floor);
        report = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, report, 0);
      });
      return answer(report, "");
    }

    /** `wearlink calibrate`: the wear coefficients from measured mass losses or profiles, into @p directory. */
    py::dict
    calibrate(const std::string              &file,
              const std::vector<std::string> &sets,
              const std::string              &measurements,
              const std::string              &directory,
              const bool                      overwrite,
              const double                    members,
              const double                    seed,
              const double                    perturbation,
              const double                    tolerance,
              const double                    max_runs,
              const bool                      catch_interrupt)
    {
      workflows::CalibrationOptions o;
      o.scene_file        = file;
      o.measurements_file = measurements;
      o.overrides         = ParameterOverrides(sets);
      o.output_directory  = directory;
      o.progress          = false;
      o                   = workflows::calibration_options(o, members, seed, perturbation, tolerance, max_runs);
      start_mpi();
      std::string report, summary;
      in_cpp(catch_interrupt, [&] {
        auto       problem = workflows::load_calibration(o); // bad input: before the folder is held
        const auto held    = hold(directory, overwrite, io::outputs::calibrate());
        const Json r       = workflows::calibrate(problem, o); // the same on every rank
        summary            = r.dump();
        report             = workflows::calibration_table(r);
      });
      return answer(report, summary);
    }

    /** A CSV table of numbers: its header and its rows as a two-dimensional array (a field that is no number: NaN). */
    py::tuple
    read_csv(const std::string &file)
    {
      std::vector<std::string> names;
      std::vector<double>      values;
      std::size_t              n_rows = 0, n_columns = 0;
      {
        py::gil_scoped_release released;
        const auto             table = io::CsvTable::read(file, "table");
        names                        = table.columns();
        n_rows                       = table.n_rows();
        n_columns                    = table.n_columns();
        values.resize(n_rows * n_columns);
        for (std::size_t r = 0; r < n_rows; ++r)
          for (std::size_t c = 0; c < n_columns; ++c)
            {
              const std::string &f   = table.field(r, c);
              char              *end = nullptr;
              const double       x   = std::strtod(f.c_str(), &end);
              values[r * n_columns + c] =
                (!f.empty() && end != nullptr && *end == '\0') ? x : std::numeric_limits<double>::quiet_NaN();
            }
      }
      const auto rows = static_cast<py::ssize_t>(n_rows), columns = static_cast<py::ssize_t>(n_columns);
      return py::make_tuple(names, array_of(std::move(values), {rows, columns}));
    }
  } // namespace
} // namespace wearlink::bindings

PYBIND11_MODULE(_wearlink, m)
{
  using namespace wearlink;
  m.doc() = "The C++ part of the wearlink module; use `import wearlink` (doc/python.md).";
  dealii::deal_II_exceptions::disable_abort_on_exception();
  register_all();

  // wearlink's failures as Python exceptions (doc/running.md, "Exit status"; doc/python.md).
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<EstimationError>(m, "EstimationError", PyExc_ValueError);
  py::register_exception<NumericalError>(m, "NumericalError", PyExc_RuntimeError);
  py::register_exception<IoError>(m, "EnvironmentFault", PyExc_OSError);
  py::register_exception<Interrupted>(m, "Interrupted", PyExc_KeyboardInterrupt);

  m.def("describe", &bindings::describe, py::arg("file"), py::arg("sets"));
  m.def("entry", &bindings::entry, py::arg("file"), py::arg("sets"), py::arg("path"));
  // Called by the package (python/wearlink/__init__.py) with positional arguments.
  m.def("execute", &bindings::execute);
  m.def("ensemble", &bindings::ensemble);
  m.def("compare_contact", &bindings::compare_contact);
  m.def("calibrate", &bindings::calibrate);
  m.def("contact", &bindings::contact);
  m.def("study", &bindings::study);
  m.def("mpi_ranks", &bindings::mpi_ranks);
  m.def("read_csv", &bindings::read_csv, py::arg("file"));
}
