// SPDX-License-Identifier: LGPL-2.1-or-later
// Reading a scene: see scene.h for the sequence. The tree is declared in
// scene_declarations.cc; this file reads it and assembles the scene.
#include "analysis/analyses_parameters.h"
#include "analysis/life_parameters.h"
#include "analysis/uncertainty_parameters.h"
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/profile.h"
#include "base/text.h"
#include "contact/clearance_parameters.h"
#include "contact/friction_law.h"
#include "contact/gap.h"
#include "contact/normal_force_law.h"
#include "io/profile_file.h"
#include "io/scene.h"
#include "io/scene_declarations.h"
#include "io/scene_periods.h"
#include "mbs/assembly.h"
#include "mbs/mbs_parameters.h"

#include <filesystem>
#include <set>

namespace wearlink::io
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace P = dealii::Patterns;

    // ------------------------------------------------------------------------------
    // Pre-scan: the names that decide which subsections exist.

    void
    pre_scan(const std::string        &file,
             const ParameterOverrides &overrides,
             std::vector<std::string> &bodies,
             std::vector<std::string> &joints)
    {
      ParameterHandler prm;
      prm.enter_subsection("Mechanism");
      prm.declare_entry("Bodies", "", P::Anything());
      prm.declare_entry("Joints", "", P::Anything());
      prm.leave_subsection();
      read_prm_file(prm, file, true);
      ParameterOverrides mech;
      for (const auto &o : overrides.settings())
        if (o.rfind("Mechanism/Bodies", 0) == 0 || o.rfind("Mechanism/Joints", 0) == 0)
          mech.append({{o}});
      apply_overrides(prm, mech);
      ParameterReader r(prm, file);
      r.enter("Mechanism");
      bodies = r.get_list("Bodies");
      joints = r.get_list("Joints");
      std::set<std::string> seen;
      for (const auto &b : bodies)
        {
          if (b == "ground")
            r.fail("Bodies", "'ground' is the fixed frame and must not be listed as a body");
          if (!seen.insert(b).second)
            r.fail("Bodies", "the body name '" + b + "' appears twice; names must be unique");
        }
      seen.clear();
      for (const auto &j : joints)
        if (!seen.insert(j).second)
          r.fail("Joints", "the joint name '" + j + "' appears twice; names must be unique");
    }

    /** Required entries inside inactive parts of the tree are not required. */
    void
    check_active_required_entries(const ParameterHandler         &prm,
                                  const std::string              &file,
                                  const std::vector<std::string> &inactive_prefixes)
    {
      std::vector<std::string> missing;
      for (const auto &m : prm.get_entries_wrongly_not_set())
        {
          // Demangle deal.II's internal path ("_20" = blank, "." between levels).
          std::string p;
          for (std::size_t i = 0; i < m.size(); ++i)
            if (m[i] == '.')
              p += '/';
            else if (m[i] == '_' && i + 2 < m.size() + 1 && std::isxdigit(m[i + 1]) && std::isxdigit(m[i + 2]))
              {
                p += static_cast<char>(std::stoi(m.substr(i + 1, 2), nullptr, 16));
                i += 2;
              }
            else
              p += m[i];
          bool inactive = false;
          for (const auto &prefix : inactive_prefixes)
            if (p.rfind(prefix, 0) == 0)
              inactive = true;
          if (!inactive)
            missing.push_back(p);
        }
      if (!missing.empty())
        throw InputError("In " + file +
                         ", these required entries are not set (physical data has no "
                         "default; set them in the scene or with --set):\n  " +
                         join(missing, "\n  "));
    }

    mbs::Vec2
    vec(const std::array<double, 2> &p)
    {
      return {p[0], p[1]};
    }

    std::string
    resolve_relative(const std::string &scene_file, const std::string &path)
    {
      namespace fs = std::filesystem;
      fs::path p   = path;
      if (p.is_relative())
        p = fs::path(scene_file).parent_path() / p;
      return p.string();
    }

    // ------------------------------------------------------------------------------
    // Construction.

    /**
     * The two profiles of the clearance joint in @p r's current section (round, or from
     * its profile files) into @p d, for the nominal @p size. In a sliced joint, a file
     * name's "{slice}" stands for the slice's number @p slice ("01", "02", …: one worn
     * profile per slice, as a wear run writes them).
     */
    void
    read_clearance_profiles(ParameterReader                    &r,
                            const contact::ClearanceSize       &size,
                            const std::string                  &slice,
                            contact::ClearanceJointDescription &d)
    {
      const double pin_radius = size.bore_radius - size.radial_clearance;
      auto         profile    = [&](const std::string &entry, double radius) {
        std::string f = r.get(entry);
        if (f.empty())
          return Profile::round(radius, size.n_areas);
        if (const auto at = f.find("{slice}"); at != std::string::npos && !slice.empty())
          f.replace(at, 7, slice);
        const std::string path = resolve_relative(r.file(), f);
        std::error_code   ec; // a name too long for the system is a name of no file, not an exception
        if (!std::filesystem::exists(path, ec))
          r.fail(entry, "the file '" + path + "' does not exist" + (ec ? " (" + ec.message() + ")" : std::string()));
        return io::read_profile_csv(path, size.n_areas);
      };
      d.geometry.bore = profile("Bore profile file", size.bore_radius);
      d.geometry.pin  = profile("Pin profile file", pin_radius);
      io::check_profile_radius(r, "Bore profile file", d.geometry.bore, size.bore_radius, "Bore radius");
      io::check_profile_radius(r,
                               "Pin profile file",
                               d.geometry.pin,
                               pin_radius,
                               "pin radius (Bore radius − Radial clearance)");
      if (!(d.geometry.bore.mean_radius() > d.geometry.pin.mean_radius()))
        r.fail_section("the pin profile (mean radius " + format_number(d.geometry.pin.mean_radius()) +
                       " m) is not smaller than the bore profile (mean radius " +
                       format_number(d.geometry.bore.mean_radius()) + " m): the pin does not fit in the bore.");
      io::check_pin_inside_bore(r, d.geometry.bore, d.geometry.pin);
    }

    /**
     * The laws of the clearance joint in @p r's current section, made for the joint (or
     * for one of its slices) named @p name.
     */
    std::unique_ptr<contact::ClearanceJoint>
    make_clearance_joint(Scene &scene, ParameterReader &r, contact::ClearanceJointDescription d)
    {
      auto normal = contact::normal_force_laws().create(d.normal_force_law, r, "Normal force law");
      std::unique_ptr<contact::FrictionLaw> friction;
      if (r.get("Friction law") != "none")
        {
          friction = contact::friction_laws().create(r.get("Friction law"), r, "Friction law");
          if (d.slice.index == 0)
            contact::check_friction_coefficient(d.slice.count > 1 ? d.slice.joint : d.name,
                                                friction->coefficient(),
                                                scene.warnings);
        }
      return std::make_unique<contact::ClearanceJoint>(std::move(d), std::move(normal), std::move(friction));
    }

    /**
     * Assembly pins the pin centre at the initial eccentricity @p e0 (bushing frame),
     * where the rigid profiles of @p d (a joint or a slice: its bore centre moved by the
     * misalignment) must not overlap (round ones: |e0| < c; a worn bore also admits its
     * pocket), at the bodies' initial angles.
     */
    void
    check_initial_eccentricity(const Scene                              &scene,
                               ParameterReader                          &r,
                               const contact::ClearanceJointDescription &d,
                               const mbs::Vec2                          &e0,
                               const double                              clearance)
    {
      const auto angle_guess = [&](const int body) {
        return body == mbs::ground ? 0.0 : scene.mechanism->get_bodies()[body].initial_angle;
      };
      const double overlap =
        contact::Gap(d.geometry.bore, d.geometry.pin)
          .evaluate(e0 - d.slice.bore_offset, 0.0, angle_guess(d.pin_body) - angle_guess(d.bushing_body))
          .penetration;
      if (overlap < 0)
        return;
      if (d.slice.count > 1)
        r.fail("Initial eccentricity",
               "at slice " + std::to_string(d.slice.index + 1) + " of " + std::to_string(d.slice.count) +
                 " (z = " + format_number(d.slice.position, 4) + " m, bore centre moved by the misalignment by " +
                 format_number(d.slice.bore_offset.norm(), 3) + " m) the pin would overlap the bore by " +
                 format_number(overlap, 3) + " m",
               "The misaligned (crowned, relieved) pin must fit in its bore at assembly: lower Slices/Misalignment "
               "(its offset over the half length, L/2 tan γ, must stay within the radial clearance " +
                 format_number(clearance) + " m), or move the initial eccentricity against the tilt.");
      r.fail("Initial eccentricity",
             "the pin would overlap the bore there by " + format_number(overlap) +
               " m; it must lie inside the clearance (round profiles: a length smaller than the radial "
               "clearance, " +
               format_number(clearance) + " m)");
    }

    void
    build_clearance_joint(Scene             &scene,
                          ParameterReader   &r,
                          const std::string &joint,
                          int                body_1,
                          const mbs::Vec2   &point_1,
                          int                body_2,
                          const mbs::Vec2   &point_2)
    {
      r.enter("Clearance");
      contact::ClearanceJointDescription d;
      d.name               = joint;
      d.clearance_form     = scene.wear_loop.clearance_form;
      d.conformal_cells    = scene.wear_loop.conformal_cells;
      const bool bush_on_1 = r.get("Bushing on") == "body 1";
      d.bushing_body       = bush_on_1 ? body_1 : body_2;
      d.bushing_point      = bush_on_1 ? point_1 : point_2;
      d.pin_body           = bush_on_1 ? body_2 : body_1;
      d.pin_point          = bush_on_1 ? point_2 : point_1;
      if (d.pin_body == mbs::ground && d.bushing_body == mbs::ground)
        r.fail_section("a clearance joint needs at least one moving body.");

      const auto size = contact::read_clearance_size(r);
      contact::read_clearance_materials(r, d);
      d.normal_force_law                          = r.get("Normal force law");
      const auto                           layout = contact::read_slice_layout(r, d);
      const mbs::Vec2                      e0     = vec(r.get_point("Initial eccentricity"));
      std::shared_ptr<contact::ElasticPin> pin; // a bending pin, shared by the slices
      const auto                           pool = layout.count > 1 ? std::make_shared<contact::FieldPool>() : nullptr;
      std::vector<const contact::ClearanceJoint *> slices;
      for (unsigned int i = 0; i < layout.count; ++i)
        {
          const std::string number = layout.count > 1 ? contact::slice_number(i, layout.count) : std::string();
          read_clearance_profiles(r, size, number, d);
          if (i == 0)
            pin = contact::make_elastic_pin(d, layout);
          auto slice              = contact::slice_of(d, layout, i);
          slice.slice.elastic_pin = pin;
          slice.slice.field_pool  = pool;
          check_initial_eccentricity(scene, r, slice, e0, size.radial_clearance);
          if (auto w = wear::read_joint_wear(r, slice.name))
            scene.wear.push_back(std::move(w));
          auto element = make_clearance_joint(scene, r, std::move(slice));
          scene.clearance_joints.push_back(element.get());
          slices.push_back(element.get());
          scene.mechanism->add_force_element(std::move(element));
        }
      if (pin)
        pin->attach(slices);
      r.leave();

      // Rotate e0 with the bushing's initial angle guess (exact after assembly for a
      // ground bushing; a good guess otherwise). One pin per joint: a sliced joint's
      // slices share the pin, and the nominal bore centre is its assembly's.
      const double bushing_angle =
        d.bushing_body == mbs::ground ? 0.0 : scene.mechanism->get_bodies()[d.bushing_body].initial_angle;
      // A revolute constraint's second body moves: with the pin on the ground, the pair is
      // written the other way round (p_bushing − p_pin = −e).
      const mbs::Vec2 e = mbs::rotate(e0, bushing_angle);
      scene.assembly_constraints.push_back(
        d.pin_body == mbs::ground ?
          mbs::make_revolute(joint, d.pin_body, d.pin_point, d.bushing_body, d.bushing_point, -e) :
          mbs::make_revolute(joint, d.bushing_body, d.bushing_point, d.pin_body, d.pin_point, e));
    }

    /** Output/Plots and Output/Plot bodies (the sliders are already in plot_bodies). */
    void
    read_plot_settings(ParameterReader &r, Scene &scene, const mbs::Mechanism &mech)
    {
      scene.plots       = r.get_bool("Plots");
      const auto chosen = r.get_list("Plot bodies");
      for (const auto &b : chosen)
        if (mech.body_index(b) < 0)
          {
            std::vector<std::string> names;
            for (const auto &body : mech.get_bodies())
              names.push_back(body.name);
            r.fail("Plot bodies", "'" + b + "' is not a moving body; the bodies are " + join(names, ", "));
          }
      if (!chosen.empty())
        scene.plot_bodies = chosen;
    }

    /** Integrator, simulated interval and time-series output of @p scene. */
    void
    read_numerics(ParameterReader &r, Scene &scene, mbs::Mechanism &mech)
    {
      mbs::read_integrator(r, scene.simulation, mech);

      r.enter("Simulation");
      scene.start_time = r.get_double("Start time");
      scene.end_time   = r.get_double("End time");
      if (!(scene.end_time > scene.start_time))
        r.fail("End time", "it must be later than Start time (" + format_number(scene.start_time) + " s)");
      r.leave();

      r.enter("Output");
      scene.write_time_series = r.get_bool("Time series");
      scene.output_interval   = r.get_double("Time series interval");
      const double rows       = (scene.end_time - scene.start_time) / scene.output_interval;
      if (scene.write_time_series && scene.output_interval > 0 && rows > max_time_series_rows)
        r.fail("Time series interval",
               "it would write " + format_number(rows, 3) + " rows over " +
                 format_number(scene.end_time - scene.start_time) + " s; at most " +
                 format_number(max_time_series_rows, 3) + " are allowed",
               "Choose a longer interval, or set Time series = false.");
      read_plot_settings(r, scene, mech);
      r.leave();
    }

    void
    build_scene(Scene                          &scene,
                ParameterHandler               &prm,
                const std::vector<std::string> &bodies,
                const std::vector<std::string> &joints)
    {
      ParameterReader r(prm, scene.file);
      scene.title     = r.get("Title");
      scene.mechanism = std::make_unique<mbs::Mechanism>();
      auto &mech      = *scene.mechanism;

      r.enter("Mechanism");
      mech.set_gravity(vec(r.get_point("Gravity")));
      r.leave();

      for (const auto &name : bodies)
        {
          r.enter("Body " + name);
          mech.add_body(mbs::read_body(r, name));
          r.leave();
        }

      // The wear loop's clearance form first: a clearance joint's normal force law builds
      // what that form needs when the joint is made (NormalForceLaw::use_conformal()).
      scene.wear_loop = wear::read_wear_loop(r);
      for (const auto &name : joints)
        {
          r.enter("Joint " + name);
          const auto joint = mbs::read_joint(r, mech);
          if (joint.clearance)
            {
              build_clearance_joint(scene, r, name, joint.body_1, joint.point_1, joint.body_2, joint.point_2);
              EffectLedger::instance().record_construction("joint model", "clearance");
            }
          else
            {
              if (joint.type == "angle-driver")
                scene.drivers.push_back(static_cast<unsigned int>(mech.get_constraints().size()));
              mech.add_constraint(mbs::make_ideal_joint(r, name, joint));
              if (joint.type == "revolute")
                EffectLedger::instance().record_construction("joint model", "ideal");
              if (joint.type == "translational")
                scene.plot_bodies.push_back(r.get("Body 2")); // a slider (Output/Plot bodies)
            }
          r.leave();
        }

      read_numerics(r, scene, mech);

      mech.finalize();
      unsigned int m = mech.n_constraint_equations();
      for (const auto &c : scene.assembly_constraints)
        m += c->n_equations();
      if (m > mech.n_coordinates())
        throw InputError("In " + scene.file + ", the joints impose " + std::to_string(m) + " constraint equations on " +
                         std::to_string(mech.n_coordinates()) +
                         " coordinates (3 per body): the mechanism is over-constrained. "
                         "Remove a joint or driver.");
    }

    /**
     * The sections the analysis layer declares (Analyses, Life, Uncertainty), read
     * against the built scene; a Poincaré section also needs the driving period.
     */
    void
    read_analysis_sections(Scene &scene, dealii::ParameterHandler &prm, const std::vector<std::string> &inactive)
    {
      analysis::AnalysedScene analysed;
      analysed.file       = scene.file;
      analysed.start_time = scene.start_time;
      analysed.end_time   = scene.end_time;
      for (const auto *j : scene.clearance_joints)
        analysed.clearance_joints.push_back(j->name());
      for (const auto &b : scene.mechanism->get_bodies())
        analysed.bodies.push_back(b.name);
      scene.analyses = analysis::read_analyses(prm, analysed);
      if (scene.analyses.poincare)
        driving_period(scene, scene.analyses); // throws if there is none, or the phase exceeds it
      scene.life        = analysis::read_life(prm, scene.file, analysed.bodies);
      scene.uncertainty = analysis::read_uncertainty(prm, scene.file, inactive);
    }
  } // namespace

  Scene
  read_scene(const std::string &file, const ParameterOverrides &overrides)
  {
    std::vector<std::string> bodies, joints;
    pre_scan(file, overrides, bodies, joints);

    Scene scene;
    scene.file       = file;
    scene.overrides  = overrides;
    scene.parameters = std::make_unique<ParameterHandler>();
    auto &prm        = *scene.parameters;
    declare_scene(prm, bodies, joints);
    read_prm_file(prm, file, false);
    apply_overrides(prm, overrides);

    // Required entries count only where they are used: the Clearance subsection of an
    // ideal joint and the subsections of laws a joint did not choose are inactive.
    std::vector<std::string> inactive;
    for (const auto &j : joints)
      {
        prm.enter_subsection("Joint " + j);
        const bool clearance = prm.get("Model") == "clearance" && prm.get("Type") == "revolute";
        if (!clearance)
          inactive.push_back("Joint " + j + "/Clearance/");
        else
          {
            prm.enter_subsection("Clearance");
            for (const auto &law : contact::normal_force_laws().names())
              if (law != prm.get("Normal force law"))
                inactive.push_back("Joint " + j + "/Clearance/" + law + "/");
            for (const auto &law : contact::friction_laws().names())
              if (law != prm.get("Friction law"))
                inactive.push_back("Joint " + j + "/Clearance/" + law + "/");
            for (const auto &section : wear::inactive_wear_sections(prm))
              inactive.push_back("Joint " + j + "/Clearance/" + section);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }
    check_active_required_entries(prm, file, inactive);

    build_scene(scene, prm, bodies, joints);
    read_analysis_sections(scene, prm, inactive);
    check_cycle_period(scene, scene.warnings);
    return scene;
  }

  void
  print_scene_parameters(std::ostream &out, const std::string &file)
  {
    std::vector<std::string> bodies = {"<name>"}, joints = {"<name>"};
    if (!file.empty())
      pre_scan(file, {}, bodies, joints);
    ParameterHandler prm;
    declare_scene(prm, bodies, joints);
    if (!file.empty())
      read_prm_file(prm, file, false);
    prm.print_parameters(out, ParameterHandler::Text);
  }
} // namespace wearlink::io
