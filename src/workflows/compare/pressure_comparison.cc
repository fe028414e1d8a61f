// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/compare/pressure_comparison.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "io/configured_pressure_models.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/scene_periods.h"
#include "wear/archard.h"
#include "wear/load_recorder.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    double
    relative_difference(const std::vector<double> &a, const std::vector<double> &b)
    {
      double d = 0, n = 0;
      for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
        {
          d += (a[k] - b[k]) * (a[k] - b[k]);
          n += b[k] * b[k];
        }
      return n > 0 ? std::sqrt(d / n) : 0.0;
    }

    void
    peak(const std::vector<double> &h, double &value, double &angle_deg)
    {
      const auto it = std::max_element(h.begin(), h.end());
      value         = *it;
      angle_deg     = 360.0 * (it - h.begin()) / h.size();
    }
  } // namespace

  PressureComparison
  compare_pressure_models(io::Scene &scene, const std::vector<std::string> &requested, double cycles)
  {
    if (scene.wear.empty())
      throw InputError("compare-pressure: no clearance joint of " + scene.file +
                       " has a Wear law; set 'Wear law = archard' (and its k_D) on the joints to compare.");
    std::vector<std::string> wearing;
    for (const auto &w : scene.wear)
      wearing.push_back(w->joint);
    const auto models = requested.empty() ? io::configured_pressure_models(scene, wearing) : requested;
    for (const auto &m : models)
      if (!contact::pressure_models().has(m))
        throw InputError("compare-pressure: unknown pressure model '" + m + "'; the valid names are " +
                         contact::pressure_models().pattern() + ".");
    const double                                 period = io::cycle_period(scene);
    std::vector<const contact::ClearanceJoint *> joints;
    for (const auto &w : scene.wear)
      for (const auto *j : scene.clearance_joints)
        if (j->name() == w->joint)
          joints.push_back(j);

    // One load history for all models.
    wear::LoadRecorder rec(joints);
    RunOptions         ro;
    ro.end_time  = scene.start_time + cycles * period;
    ro.observers = {&rec};
    run_scene(scene, ro);
    rec.finish();

    PressureComparison c;
    c.cycles = cycles;
    for (unsigned int i = 0; i < joints.size(); ++i)
      {
        const auto                        &w = *scene.wear[i];
        std::vector<PressureComparisonRow> rows;
        for (const auto &m : models)
          {
            const auto      t0 = std::chrono::steady_clock::now();
            ParameterReader reader(*scene.parameters, scene.file);
            reader.enter("Joint " + w.joint);
            reader.enter("Clearance");
            auto model = contact::pressure_models().create(m, reader, "Pressure model");
            reader.leave();
            reader.leave();
            const auto &g = joints[i]->get_description().geometry;
            model->update_geometry(g);
            wear::ArchardAccumulator acc(g, w.archard.bushing_coefficient, w.archard.pin_coefficient, *model);
            acc.add_history(rec.samples(i),
                            scene.wear_loop.evaluation == wear::PressureEvaluation::every_step,
                            period / scene.wear_loop.samples_per_cycle,
                            scene.start_time);
            PressureComparisonRow r;
            r.joint          = w.joint;
            r.model          = m;
            r.volume_pin     = acc.pin_volume;
            r.volume_bore    = acc.bore_volume;
            r.archard_volume = acc.pin_archard;
            r.depth_pin      = acc.pin_depth();
            r.depth_bore     = acc.bore_depth();
            r.evaluations    = acc.pressure_evaluations;
            peak(r.depth_pin, r.max_depth_pin, r.peak_angle_pin);
            peak(r.depth_bore, r.max_depth_bore, r.peak_angle_bore);
            r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            rows.push_back(std::move(r));
          }
        for (auto &r : rows)
          {
            r.difference_pin  = relative_difference(r.depth_pin, rows.back().depth_pin);
            r.difference_bore = relative_difference(r.depth_bore, rows.back().depth_bore);
            c.rows.push_back(r);
          }
      }
    return c;
  }

  std::string
  PressureComparison::table() const
  {
    std::ostringstream os;
    const std::string  ref = rows.empty() ? "" : rows.back().model;
    os << "Same load history (" << cycles << " cycles) through each pressure model; Archard on both surfaces.\n"
       << "L2 difference: ‖h − h_" << ref << "‖/‖h_" << ref << "‖ of the depth profiles.\n\n";
    os << std::left << std::setw(6) << "joint" << std::setw(13) << "model" << std::right << std::setw(13) << "V_pin mm³"
       << std::setw(13) << "V_bush mm³" << std::setw(14) << "kFs_pin mm³" << std::setw(12) << "h_pin µm" << std::setw(9)
       << "at deg" << std::setw(12) << "h_bush µm" << std::setw(9) << "at deg" << std::setw(11) << "L2 pin"
       << std::setw(11) << "L2 bush" << std::setw(10) << "evals" << std::setw(10) << "wall s" << '\n';
    for (const auto &r : rows)
      os << std::left << std::setw(6) << r.joint << std::setw(13) << r.model << std::right << std::scientific
         << std::setprecision(4) << std::setw(13) << r.volume_pin * 1e9 << std::setw(13) << r.volume_bore * 1e9
         << std::setw(14) << r.archard_volume * 1e9 << std::setprecision(3) << std::setw(12) << r.max_depth_pin * 1e6
         << std::fixed << std::setprecision(1) << std::setw(9) << r.peak_angle_pin << std::scientific
         << std::setprecision(3) << std::setw(12) << r.max_depth_bore * 1e6 << std::fixed << std::setprecision(1)
         << std::setw(9) << r.peak_angle_bore << std::setprecision(3) << std::setw(11) << r.difference_pin
         << std::setw(11) << r.difference_bore << std::setw(10) << r.evaluations << std::setprecision(2)
         << std::setw(10) << r.wall_time << '\n';
    return os.str();
  }

  void
  write_pressure_comparison(const std::string &dir, const PressureComparison &c)
  {
    make_output_directory(dir);
    std::ostringstream os;
    os << "joint,model,volume_pin_m3,volume_bushing_m3,archard_volume_pin_m3,max_depth_pin_m,peak_angle_pin_deg,"
          "max_depth_bushing_m,peak_angle_bushing_deg,l2_difference_pin,l2_difference_bushing,evaluations,wall_time_s\n"
       << std::setprecision(10);
    for (const auto &r : c.rows)
      os << r.joint << ',' << r.model << ',' << r.volume_pin << ',' << r.volume_bore << ',' << r.archard_volume << ','
         << r.max_depth_pin << ',' << r.peak_angle_pin << ',' << r.max_depth_bore << ',' << r.peak_angle_bore << ','
         << r.difference_pin << ',' << r.difference_bore << ',' << r.evaluations << ',' << r.wall_time << '\n';
    write_file_atomically(dir + "/" + io::outputs::compare_pressure_table, os.str());

    std::vector<std::string> joints;
    for (const auto &r : c.rows)
      if (std::find(joints.begin(), joints.end(), r.joint) == joints.end())
        joints.push_back(r.joint);
    for (const auto &j : joints)
      {
        std::ostringstream ds;
        ds << "angle_deg";
        io::PlotSpec spec;
        spec.title      = "Joint " + j + ": wear depth from the same load history (pin: solid, bushing: dashed)";
        spec.x_label    = "angle in the body's own frame [deg]";
        spec.y_label    = "wear depth [um]";
        spec.x_range    = io::Range{0, 360};
        spec.x_tic_step = 45;
        std::vector<const PressureComparisonRow *> rs;
        for (const auto &r : c.rows)
          if (r.joint == j)
            {
              rs.push_back(&r);
              ds << ",pin_" << r.model << "_m,bushing_" << r.model << "_m";
              const auto     colour = static_cast<unsigned>(rs.size());
              io::PlotSeries p{"pin, " + r.model, {}, {}, io::palette_line(colour, 2)};
              io::PlotSeries b{"bushing, " + r.model, {}, {}, io::palette_line(colour, 2).dashed()};
              for (std::size_t k = 0; k < r.depth_pin.size(); ++k)
                {
                  p.x.push_back(360.0 * k / r.depth_pin.size());
                  p.y.push_back(r.depth_pin[k] * 1e6);
                }
              for (std::size_t k = 0; k < r.depth_bore.size(); ++k)
                {
                  b.x.push_back(360.0 * k / r.depth_bore.size());
                  b.y.push_back(r.depth_bore[k] * 1e6);
                }
              spec.series.push_back(p);
              spec.series.push_back(b);
            }
        ds << '\n' << std::setprecision(10);
        const std::size_t n = rs.front()->depth_pin.size();
        for (std::size_t k = 0; k < n; ++k)
          {
            ds << 360.0 * k / n;
            for (const auto *r : rs)
              ds << ',' << r->depth_pin[k] << ',' << (k < r->depth_bore.size() ? r->depth_bore[k] : 0.0);
            ds << '\n';
          }
        write_file_atomically(dir + "/compare_depth_" + j + ".csv", ds.str());
        io::plot_png(spec, dir + "/compare_depth_" + j + ".png");
      }
  }
} // namespace wearlink::workflows
