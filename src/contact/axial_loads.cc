// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/axial_loads.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace wearlink::contact
{
  AxialLoads::AxialLoads(const std::vector<ClearanceJoint *> &joints)
  {
    std::map<std::string, std::size_t> where;
    for (unsigned int k = 0; k < joints.size(); ++k)
      {
        const auto &s = joints[k]->get_description().slice;
        if (s.count < 2)
          continue;
        const auto it = where.emplace(s.joint, groups.size()).first;
        if (it->second == groups.size())
          groups.push_back(Group{s.joint, {}, {}, {}, 0, 0, 0, s.elastic_pin.get()});
        auto &g = groups[it->second];
        g.members.push_back(k);
        g.positions.push_back(s.position);
        g.force_time.push_back(0);
      }
  }

  void
  AxialLoads::record(const std::vector<JointDiagnostics> &d, const double h)
  {
    for (auto &g : groups)
      {
        mbs::Vec2 moment(0, 0);
        for (std::size_t i = 0; i < g.members.size(); ++i)
          {
            const auto &x = d[g.members[i]];
            g.force_time[i] += h * x.normal_force;
            g.moment_time += h * g.positions[i] * x.normal_force;
            moment += g.positions[i] * x.force_on_pin;
            g.deflection = std::max(g.deflection, x.pin_deflection.norm());
          }
        g.duration += h;
        g.max_moment = std::max(g.max_moment, moment.norm());
      }
  }

  Json
  AxialLoads::json() const
  {
    Json out = Json::object();
    for (const auto &g : groups)
      {
        const double        duration = std::max(g.duration, 1e-300);
        std::vector<double> mean, share;
        double              sum = 0, largest = 0, moment = 0;
        for (std::size_t i = 0; i < g.members.size(); ++i)
          {
            mean.push_back(g.force_time[i] / duration);
            sum += mean.back();
            largest = std::max(largest, mean.back());
            moment += g.positions[i] * mean.back();
          }
        for (const double m : mean)
          share.push_back(sum > 0 ? m / sum : 0.0);
        Json j                    = Json::object();
        j["slices"]               = g.members.size();
        j["positions_m"]          = g.positions;
        j["mean_normal_force_N"]  = mean;
        j["force_share"]          = share;
        j["edge_to_mean_force"]   = sum > 0 ? largest * g.members.size() / sum : 0.0;
        j["resultant_position_m"] = sum > 0 ? g.moment_time / (sum * duration) : 0.0;
        j["mean_edge_moment_N_m"] = std::abs(moment);
        j["max_edge_moment_N_m"]  = g.max_moment;
        if (g.pin != nullptr)
          {
            j["largest_pin_deflection_m"] = g.deflection;
            j["pin_solve_failures"]       = g.pin->n_failures();
          }
        out[g.joint] = j;
      }
    return out;
  }
} // namespace wearlink::contact
