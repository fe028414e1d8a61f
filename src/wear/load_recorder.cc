// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/load_recorder.h"

#include "base/numbers.h"

#include <cmath>

namespace wearlink::wear
{
  namespace
  {
    using numbers::two_pi;

    mbs::StateView
    view(const Eigen::VectorXd &y, unsigned int n)
    {
      return mbs::StateView(y.data(), y.data() + n);
    }
  } // namespace

  // The pressure models are frictionless: they receive the normal part of the contact
  // force, −F_n u(φ*) on the pin (contact/pressure_model.h).
  LoadSample
  load_sample(const contact::JointDiagnostics &d)
  {
    LoadSample s;
    s.load.bushing_angle = d.bushing_angle;
    s.load.pin_angle     = d.pin_angle;
    s.load.eccentricity  = {{d.eccentricity.x(), d.eccentricity.y()}};
    s.load.penetration   = d.penetration;
    s.load.normal_force  = d.normal_force;
    s.load.contact_angle = d.contact_angle;
    s.load.force         = {{-d.normal_force * std::cos(d.contact_angle), -d.normal_force * std::sin(d.contact_angle)}};
    s.sliding_speed      = std::abs(d.sliding_velocity);
    return s;
  }

  LoadRecorder::LoadRecorder(std::vector<const contact::ClearanceJoint *> j)
    : joints(std::move(j))
    , history(joints.size())
    , pending(joints.size())
    , relative_angle(joints.size(), 0.0)
    , rotation(joints.size(), 0.0)
  {
  }

  void
  LoadRecorder::take(unsigned int j, const LoadSample &s, double weight)
  {
    if (s.load.normal_force > 0 && s.sliding_speed > 0 && weight > 0)
      {
        history[j].push_back(s);
        history[j].back().weight = weight;
      }
  }

  void
  LoadRecorder::evaluate(const mbs::StepContext &c)
  {
    const auto n = c.simulation.get_mechanism().n_coordinates();
    current.resize(joints.size());
    for (unsigned int j = 0; j < joints.size(); ++j)
      current[j] = joints[j]->diagnostics(view(c.y, n));
  }

  void
  LoadRecorder::on_start(const mbs::StepContext &c)
  {
    evaluate(c);
    start(c.t, current);
  }

  void
  LoadRecorder::on_step(const mbs::StepContext &c)
  {
    evaluate(c);
    step(c.t, current);
  }

  void
  LoadRecorder::start(const double t, const std::vector<contact::JointDiagnostics> &d)
  {
    t_start = t_last = t;
    for (unsigned int j = 0; j < joints.size(); ++j)
      {
        relative_angle[j] = d[j].pin_angle - d[j].bushing_angle;
        pending[j]        = load_sample(d[j]);
        pending[j].weight = 0;
        pending[j].time   = t;
      }
  }

  void
  LoadRecorder::step(const double t, const std::vector<contact::JointDiagnostics> &d)
  {
    const double h = t - t_last;
    for (unsigned int j = 0; j < joints.size(); ++j)
      {
        const double rel = d[j].pin_angle - d[j].bushing_angle;
        rotation[j] += std::abs(rel - relative_angle[j]);
        relative_angle[j] = rel;
        // The previous sample's weight is complete with this step's half.
        take(j, pending[j], pending[j].weight + 0.5 * h);
        pending[j]        = load_sample(d[j]);
        pending[j].weight = 0.5 * h;
        pending[j].time   = t;
      }
    t_last = t;
  }

  void
  LoadRecorder::finish()
  {
    for (unsigned int j = 0; j < joints.size(); ++j)
      {
        take(j, pending[j], pending[j].weight);
        pending[j].weight = 0;
      }
  }

  double
  LoadRecorder::relative_revolutions(unsigned int j) const
  {
    return rotation[j] / two_pi;
  }
} // namespace wearlink::wear
