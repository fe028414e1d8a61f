// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/wear_outputs.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "io/csv.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/profile_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    using numbers::pi;

    /** Read a response CSV written by write_response_csv (for the plot); false if absent. */
    bool
    read_response(const std::string &path, std::vector<double> &t, std::vector<double> &ax, std::vector<double> &ay)
    {
      if (!std::filesystem::exists(path))
        return false;
      const CsvTable table = CsvTable::read(path, "response file");
      table.require_rectangular();
      if (table.columns().size() != 5)
        throw InputError("'" + path + "' is not a response file of wearlink (time, x, y, a_x, a_y columns).");
      t  = table.numbers(0);
      ax = table.numbers(3);
      ay = table.numbers(4);
      return true;
    }

    /** A "nice" magnification 1, 2, 5 × 10^k not above @p m. */
    double
    nice(double m)
    {
      const double p = std::pow(10.0, std::floor(std::log10(m)));
      for (const double f : {5.0, 2.0, 1.0})
        if (f * p <= m)
          return f * p;
      return p;
    }

    void
    plot_profile(const std::string &path,
                 const std::string &title,
                 const Profile     &initial,
                 const Profile     &worn,
                 double             magnification)
    {
      PlotSpec spec;
      spec.title  = title;
      spec.polar  = true;
      spec.width  = 800;
      spec.height = 800;
      PlotSeries     a{"initial", {}, {}, line("gray40").dashed()};
      PlotSeries     b{"worn (wear magnified)", {}, {}, line("red", 2)};
      const unsigned n = initial.n_points();
      for (unsigned k = 0; k <= n; ++k)
        {
          const unsigned i   = k % n;
          const double   psi = 2 * pi * k / n;
          a.x.push_back(psi);
          a.y.push_back(initial[i]);
          b.x.push_back(psi);
          b.y.push_back(initial[i] + magnification * (worn[i] - initial[i]));
        }
      const double rmax = std::max(initial.max_radius(),
                                   initial.max_radius() + magnification * (worn.max_radius() - initial.min_radius()));
      spec.polar_reach  = 1.05 * rmax;
      spec.series       = {a, b};
      plot_png(spec, path);
    }
  } // namespace

  void
  write_wear_history(const std::string &path, const Scene &scene, const wear::WearState &st)
  {
    std::ostringstream os;
    os << "iteration,revolutions,extrapolation_factor";
    for (const auto &j : st.joints)
      for (const char *q : {"_volume_pin_mm3",
                            "_volume_bushing_mm3",
                            "_mass_loss_pin_mg",
                            "_mass_loss_bushing_mg",
                            "_max_depth_pin_um",
                            "_max_depth_bushing_um",
                            "_envelope_depth_pin_um",
                            "_envelope_depth_bushing_um",
                            "_roughness_pin",
                            "_roughness_bushing",
                            "_archard_volume_pin_mm3",
                            "_archard_volume_bushing_mm3",
                            "_mean_normal_force_N",
                            "_sliding_distance_m"})
        os << ',' << j.name << q;
    os << '\n' << std::setprecision(10);
    double revolutions = 0;
    for (unsigned int it = 0; it < st.iterations_done; ++it)
      {
        revolutions += st.factors[it] * scene.wear_loop.cycles_per_iteration;
        os << it + 1 << ',' << revolutions << ',' << st.factors[it];
        for (unsigned int i = 0; i < st.joints.size(); ++i)
          {
            const auto &r = st.joints[i].history[it];
            const auto &a = scene.wear[i]->archard;
            os << ',' << r.volume_pin * 1e9 << ',' << r.volume_bore * 1e9 << ',' << r.volume_pin * a.pin_density * 1e6
               << ',' << r.volume_bore * a.bushing_density * 1e6 << ',' << r.max_depth_pin * 1e6 << ','
               << r.max_depth_bore * 1e6 << ',' << r.envelope_depth_pin * 1e6 << ',' << r.envelope_depth_bore * 1e6
               << ',' << r.roughness_pin << ',' << r.roughness_bore << ',' << r.archard_pin * 1e9 << ','
               << r.archard_bore * 1e9 << ',' << r.mean_normal_force << ',' << r.sliding_distance;
          }
        os << '\n';
      }
    write_file_atomically(path, os.str());
  }

  void
  write_profiles_msh(const std::string &path, const Profile &bore, const Profile &pin)
  {
    std::ostringstream os;
    os << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 1 \"bore\"\n1 2 \"pin\"\n$EndPhysicalNames\n";
    const unsigned nb = bore.n_points(), np = pin.n_points();
    os << "$Nodes\n" << nb + np << '\n' << std::setprecision(17);
    for (unsigned k = 0; k < nb; ++k)
      os << k + 1 << ' ' << bore[k] * std::cos(bore.angle(k)) << ' ' << bore[k] * std::sin(bore.angle(k)) << " 0\n";
    for (unsigned k = 0; k < np; ++k)
      os << nb + k + 1 << ' ' << pin[k] * std::cos(pin.angle(k)) << ' ' << pin[k] * std::sin(pin.angle(k)) << " 0\n";
    os << "$EndNodes\n$Elements\n" << nb + np << '\n';
    for (unsigned k = 0; k < nb; ++k)
      os << k + 1 << " 1 2 1 1 " << k + 1 << ' ' << (k + 1) % nb + 1 << '\n';
    for (unsigned k = 0; k < np; ++k)
      os << nb + k + 1 << " 1 2 2 2 " << nb + k + 1 << ' ' << nb + (k + 1) % np + 1 << '\n';
    os << "$EndElements\n";
    write_file_atomically(path, os.str());
  }

  namespace
  {
    /** wear_depth_<J>.csv: cumulative depth per area after each iteration (seed Fig 5). */
    void
    write_depth_csv(const std::string &dir, const wear::JointWearState &j)
    {
      const unsigned     n_it = static_cast<unsigned>(j.history.size());
      std::ostringstream os;
      os << "# cumulative wear depth after each iteration; pin angles in the pin's frame, bore angles in "
            "the bushing's frame\nangle_deg";
      for (unsigned it = 0; it < n_it; ++it)
        os << ",pin_it" << it + 1 << "_m";
      for (unsigned it = 0; it < n_it; ++it)
        os << ",bushing_it" << it + 1 << "_m";
      os << '\n' << std::setprecision(10);
      const unsigned n = j.pin.n_points();
      for (unsigned k = 0; k < n; ++k)
        {
          os << 360.0 * k / n;
          for (unsigned it = 0; it < n_it; ++it)
            os << ',' << j.history[it].depth_pin[k];
          for (unsigned it = 0; it < n_it; ++it)
            os << ',' << (k < j.history[it].depth_bore.size() ? j.history[it].depth_bore[k] : 0.0);
          os << '\n';
        }
      write_file_atomically(dir + "/wear_depth_" + j.name + ".csv", os.str());
    }

    /** wear_depth_<J>.png: the depth curves of up to six iterations, pin and bushing. */
    void
    plot_depth(const std::string &dir, const wear::JointWearState &j)
    {
      const unsigned n_it = static_cast<unsigned>(j.history.size());
      const unsigned n    = j.pin.n_points();
      PlotSpec       spec;
      spec.title            = "Joint " + j.name + ": wear depth after each iteration (pin: solid, bushing: dashed)";
      spec.x_label          = "angle in the body's own frame [deg]";
      spec.y_label          = "wear depth [um]";
      spec.x_range          = Range{0, 360};
      spec.x_tic_step       = 45;
      const unsigned stride = std::max(1u, (n_it + 5) / 6);
      for (unsigned it = 0; it < n_it; ++it)
        {
          if ((n_it - 1 - it) % stride != 0)
            continue;
          const auto colour = static_cast<unsigned>(spec.series.size() / 2 + 1); // distinct per curve pair
          PlotSeries p{"pin, it " + std::to_string(it + 1), {}, {}, palette_line(colour, 2)};
          PlotSeries b{"bushing, it " + std::to_string(it + 1), {}, {}, palette_line(colour, 2).dashed()};
          for (unsigned k = 0; k < n; ++k)
            {
              p.x.push_back(360.0 * k / n);
              p.y.push_back(j.history[it].depth_pin[k] * 1e6);
            }
          for (unsigned k = 0; k < j.bore.n_points(); ++k)
            {
              b.x.push_back(360.0 * k / j.bore.n_points());
              b.y.push_back(j.history[it].depth_bore[k] * 1e6);
            }
          spec.series.push_back(p);
          spec.series.push_back(b);
        }
      plot_png(spec, dir + "/wear_depth_" + j.name + ".png");
    }

    /**
     * The reconstructed profiles (seed Figs 6–7): profiles_<J>.csv/.msh, the worn
     * profiles as scene profile files (bore_<J>.csv, pin_<J>.csv), and magnified plots.
     */
    void
    write_profiles(const std::string &dir, const Scene &scene, const wear::JointWearState &j)
    {
      const unsigned n_it = static_cast<unsigned>(j.history.size());
      const unsigned n    = j.pin.n_points();
      // Reconstructed profiles (seed Figs 6–7).
      std::ostringstream ps;
      ps << "angle_rad,bore_initial_m,bore_worn_m,pin_initial_m,pin_worn_m\n" << std::setprecision(17);
      for (unsigned k = 0; k < n; ++k)
        ps << j.pin.angle(k) << ',' << j.initial_bore[k] << ',' << j.bore[k] << ',' << j.initial_pin[k] << ','
           << j.pin[k] << '\n';
      write_file_atomically(dir + "/profiles_" + j.name + ".csv", ps.str());
      write_profiles_msh(dir + "/profiles_" + j.name + ".msh", j.bore, j.pin);
      // The worn profiles in the scene's profile-file format, so that a scene can
      // start from them ('Bore profile file', 'Pin profile file').
      write_profile_csv(j.bore, dir + "/bore_" + j.name + ".csv", "worn bore of joint " + j.name + ", bushing frame");
      write_profile_csv(j.pin, dir + "/pin_" + j.name + ".csv", "worn pin of joint " + j.name + ", pin frame");
      // Each surface at its own magnification (stated in its title), unless fixed.
      auto magnification = [&](double depth) {
        const double m = scene.wear_loop.magnification;
        if (m > 0)
          return m;
        return depth > 0 ? nice(0.15 * j.initial_pin.mean_radius() / depth) : 1.0;
      };
      auto title = [](const std::string &what, double m) {
        std::ostringstream t;
        t << what << " (wear magnified x" << m << ")";
        return t.str();
      };
      const double m_bore = magnification(n_it ? j.history.back().max_depth_bore : 0.0);
      const double m_pin  = magnification(n_it ? j.history.back().max_depth_pin : 0.0);
      plot_profile(dir + "/profile_" + j.name + "_bore.png",
                   title("Joint " + j.name + ": bushing bore surface", m_bore),
                   j.initial_bore,
                   j.bore,
                   m_bore);
      plot_profile(dir + "/profile_" + j.name + "_pin.png",
                   title("Joint " + j.name + ": pin surface", m_pin),
                   j.initial_pin,
                   j.pin,
                   m_pin);
    }

    /** wear_volume.png: worn volume of each surface against revolutions. */
    void
    plot_volume(const std::string &dir, const Scene &scene, const wear::WearState &st)
    {
      // Worn volume vs revolutions.
      {
        PlotSpec spec;
        spec.title   = "Worn volume";
        spec.x_label = "revolutions";
        spec.y_label = "worn volume [mm^3]";
        for (const auto &j : st.joints)
          {
            PlotSeries p{j.name + " pin", {0}, {0}, line_points("", 2, Marker::automatic)};
            PlotSeries b{j.name + " bushing", {0}, {0}, line_points("", 2, Marker::automatic).dashed()};
            double     revolutions = 0;
            for (unsigned it = 0; it < j.history.size(); ++it)
              {
                revolutions += st.factors[it] * scene.wear_loop.cycles_per_iteration;
                p.x.push_back(revolutions);
                p.y.push_back(j.history[it].volume_pin * 1e9);
                b.x.push_back(revolutions);
                b.y.push_back(j.history[it].volume_bore * 1e9);
              }
            spec.series.push_back(p);
            spec.series.push_back(b);
          }
        plot_png(spec, dir + "/wear_volume.png");
      }
    }

    /** response_after.csv and response.png: the response before and after wear (seed Fig 8). */
    void
    write_response(const std::string &dir, const analysis::ResponseRecorder &after)
    {
      // Dynamic response before and after wear (seed Fig 8).
      write_response_csv(dir + "/" + io::outputs::response_after, after);
      std::vector<double> tb, axb, ayb;
      PlotSpec            spec;
      spec.title   = after.body_name + ": acceleration before and after wear (same initial state)";
      spec.x_label = "time from the start [s]";
      spec.y_label = "acceleration [m/s^2]";
      if (read_response(dir + "/" + io::outputs::response_before, tb, axb, ayb))
        {
          spec.series.push_back({"a_y before wear", tb, ayb, line("blue", 1)});
          spec.series.push_back({"a_x before wear", tb, axb, line("dark-green", 1)});
        }
      spec.series.push_back({"a_y after wear", after.t, after.ay, line("red", 1)});
      spec.series.push_back({"a_x after wear", after.t, after.ax, line("orange", 1)});
      plot_png(spec, dir + "/response.png");
    }
  } // namespace

  void
  write_wear_outputs(const std::string                &dir,
                     const Scene                      &scene,
                     const wear::WearState            &st,
                     const analysis::ResponseRecorder &after)
  {
    for (const auto &j : st.joints)
      {
        write_depth_csv(dir, j);
        plot_depth(dir, j);
        write_profiles(dir, scene, j);
      }
    plot_volume(dir, scene, st);
    write_response(dir, after);
  }

  void
  write_response_csv(const std::string &path, const analysis::ResponseRecorder &r)
  {
    std::ostringstream os;
    os << "time_s," << r.body_name << "_x_m," << r.body_name << "_y_m," << r.body_name << "_ax_m_s2," << r.body_name
       << "_ay_m_s2\n"
       << std::setprecision(10);
    for (std::size_t i = 0; i < r.t.size(); ++i)
      os << r.t[i] << ',' << r.x[i] << ',' << r.y[i] << ',' << r.ax[i] << ',' << r.ay[i] << '\n';
    write_file_atomically(path, os.str());
  }

} // namespace wearlink::io
