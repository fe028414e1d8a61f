// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/wear_state.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace wearlink::wear
{
  namespace
  {
    constexpr const char *magic = "wearlink-wear-checkpoint 1";

    void
    put(std::ostream &os, const std::string &key, const std::vector<double> &v)
    {
      os << key << ' ' << v.size();
      for (const double x : v)
        os << ' ' << x;
      os << '\n';
    }

    void
    put(std::ostream &os, const std::string &key, double x)
    {
      os << key << ' ' << x << '\n';
    }

    class Reader
    {
    public:
      Reader(const std::string &path)
        : path(path)
        , in(path)
      {
        if (!in)
          throw InputError("Cannot resume: the checkpoint '" + path +
                           "' does not exist (was the run started with this output "
                           "directory, and did it finish at least one wear iteration?).");
      }

      std::string
      line(const std::string &key)
      {
        std::string l;
        if (!std::getline(in, l) || l.compare(0, key.size() + 1, key + " ") != 0)
          fail("expected '" + key + "'");
        return l.substr(key.size() + 1);
      }

      void
      expect_end()
      {
        std::string l;
        if (!std::getline(in, l) || l != "end")
          fail("the file is truncated");
      }

      double
      number(const std::string &key)
      {
        return parse(line(key), key);
      }

      std::vector<double>
      vector(const std::string &key)
      {
        std::istringstream ls(line(key));
        std::size_t        n = 0;
        if (!(ls >> n))
          fail("bad size of '" + key + "'");
        std::vector<double> v(n);
        for (auto &x : v)
          {
            std::string t;
            if (!(ls >> t))
              fail("'" + key + "' is truncated");
            x = parse(t, key);
          }
        return v;
      }

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw InputError("The checkpoint '" + path + "' is malformed (" + what +
                         "); it was not written by this wearlink or was edited.");
      }

    private:
      double
      parse(const std::string &t, const std::string &key) const
      {
        char *       end = nullptr;
        const double x   = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || (*end != '\0' && *end != ' '))
          fail("bad number in '" + key + "'");
        return x;
      }

      std::string   path;
      std::ifstream in;
    };
  } // namespace

  void
  WearState::write(const std::string &path) const
  {
    AtomicFile f(path);
    auto &     os = f.stream();
    os << magic << '\n' << std::hexfloat;
    os << "fingerprint " << fingerprint << '\n';
    put(os, "iterations", iterations_done);
    put(os, "revolutions", revolutions);
    put(os, "time", time);
    put(os, "state", std::vector<double>(state.data(), state.data() + state.size()));
    put(os, "factors", factors);
    put(os, "modes", modes);
    put(os, "joints", joints.size());
    for (const auto &j : joints)
      {
        os << "joint " << j.name << '\n';
        put(os, "initial_bore", j.initial_bore.samples());
        put(os, "initial_pin", j.initial_pin.samples());
        put(os, "bore", j.bore.samples());
        put(os, "pin", j.pin.samples());
        put(os, "meshed_bore", j.meshed_bore.samples());
        put(os, "meshed_pin", j.meshed_pin.samples());
        put(os, "records", j.history.size());
        for (const auto &r : j.history)
          {
            put(os,
                "record",
                std::vector<double>{r.volume_pin,
                                    r.volume_bore,
                                    r.archard_pin,
                                    r.archard_bore,
                                    r.max_depth_pin,
                                    r.max_depth_bore,
                                    r.mean_normal_force,
                                    r.sliding_distance,
                                    r.relative_revolutions});
            put(os, "depth_pin", r.depth_pin);
            put(os, "depth_bore", r.depth_bore);
          }
      }
    os << "end\n";
    f.commit();
  }

  WearState
  WearState::read(const std::string &path)
  {
    Reader    r(path);
    WearState s;
    if (r.line("wearlink-wear-checkpoint") != "1")
      r.fail("unknown version");
    s.fingerprint         = r.line("fingerprint");
    s.iterations_done     = static_cast<unsigned int>(r.number("iterations"));
    s.revolutions         = r.number("revolutions");
    s.time                = r.number("time");
    const auto y          = r.vector("state");
    s.state               = Eigen::Map<const Eigen::VectorXd>(y.data(), y.size());
    s.factors             = r.vector("factors");
    s.modes               = r.vector("modes");
    const auto n_joints   = static_cast<unsigned int>(r.number("joints"));
    for (unsigned int i = 0; i < n_joints; ++i)
      {
        JointWearState j;
        j.name           = r.line("joint");
        const std::string what = "checkpoint '" + path + "' joint " + j.name;
        j.initial_bore   = Profile::from_samples(r.vector("initial_bore"), what);
        j.initial_pin    = Profile::from_samples(r.vector("initial_pin"), what);
        j.bore           = Profile::from_samples(r.vector("bore"), what);
        j.pin            = Profile::from_samples(r.vector("pin"), what);
        j.meshed_bore    = Profile::from_samples(r.vector("meshed_bore"), what);
        j.meshed_pin     = Profile::from_samples(r.vector("meshed_pin"), what);
        const auto n_rec = static_cast<unsigned int>(r.number("records"));
        for (unsigned int k = 0; k < n_rec; ++k)
          {
            const auto v = r.vector("record");
            if (v.size() != 9)
              r.fail("a record has " + std::to_string(v.size()) + " fields");
            IterationRecord rec;
            rec.volume_pin           = v[0];
            rec.volume_bore          = v[1];
            rec.archard_pin          = v[2];
            rec.archard_bore         = v[3];
            rec.max_depth_pin        = v[4];
            rec.max_depth_bore       = v[5];
            rec.mean_normal_force    = v[6];
            rec.sliding_distance     = v[7];
            rec.relative_revolutions = v[8];
            rec.depth_pin            = r.vector("depth_pin");
            rec.depth_bore           = r.vector("depth_bore");
            j.history.push_back(std::move(rec));
          }
        s.joints.push_back(std::move(j));
      }
    r.expect_end();
    return s;
  }
} // namespace wearlink::wear
