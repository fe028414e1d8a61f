// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/wear_state.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/json.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace wearlink::wear
{
  namespace
  {
    constexpr const char *format_name    = "wearlink wear checkpoint";
    constexpr int         format_version = 2;

    Json
    to_json(const std::vector<double> &v)
    {
      return Json(v);
    }

    Json
    to_json(const IterationRecord &r)
    {
      Json j                    = Json::object();
      j["volume_pin"]           = r.volume_pin;
      j["volume_bore"]          = r.volume_bore;
      j["archard_pin"]          = r.archard_pin;
      j["archard_bore"]         = r.archard_bore;
      j["max_depth_pin"]        = r.max_depth_pin;
      j["max_depth_bore"]       = r.max_depth_bore;
      j["mean_normal_force"]    = r.mean_normal_force;
      j["sliding_distance"]     = r.sliding_distance;
      j["relative_revolutions"] = r.relative_revolutions;
      j["depth_pin"]            = to_json(r.depth_pin);
      j["depth_bore"]           = to_json(r.depth_bore);
      return j;
    }

    Json
    to_json(const JointWearState &js)
    {
      Json j            = Json::object();
      j["name"]         = js.name;
      j["initial_bore"] = to_json(js.initial_bore.samples());
      j["initial_pin"]  = to_json(js.initial_pin.samples());
      j["bore"]         = to_json(js.bore.samples());
      j["pin"]          = to_json(js.pin.samples());
      j["meshed_bore"]  = to_json(js.meshed_bore.samples());
      j["meshed_pin"]   = to_json(js.meshed_pin.samples());
      j["history"]      = Json::array();
      for (const auto &r : js.history)
        j["history"].push_back(to_json(r));
      return j;
    }

    /**
     * Typed, checked access to a parsed checkpoint: every entry must be present with
     * its type, or an InputError names the file and the entry.
     */
    class Reader
    {
    public:
      explicit Reader(const std::string &path)
        : path(path)
      {
      }

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw InputError("The checkpoint '" + path + "' is malformed (" + what +
                         "); it was not written by this wearlink or was edited.");
      }

      const Json &
      entry(const Json &object, const std::string &key, const std::string &where) const
      {
        if (!object.is_object() || !object.contains(key))
          fail("no entry '" + where + key + "'");
        return object.at(key);
      }

      double
      number(const Json &object, const std::string &key, const std::string &where = "") const
      {
        const Json &v = entry(object, key, where);
        if (!v.is_number())
          fail("'" + where + key + "' is not a number");
        return v.get<double>();
      }

      std::string
      text(const Json &object, const std::string &key, const std::string &where = "") const
      {
        const Json &v = entry(object, key, where);
        if (!v.is_string())
          fail("'" + where + key + "' is not text");
        return v.get<std::string>();
      }

      std::vector<double>
      numbers(const Json &object, const std::string &key, const std::string &where = "") const
      {
        const Json &v = entry(object, key, where);
        if (!v.is_array())
          fail("'" + where + key + "' is not a list of numbers");
        std::vector<double> out;
        out.reserve(v.size());
        for (const auto &x : v)
          {
            if (!x.is_number())
              fail("'" + where + key + "' holds something that is not a number");
            out.push_back(x.get<double>());
          }
        return out;
      }

      const Json &
      list(const Json &object, const std::string &key, const std::string &where = "") const
      {
        const Json &v = entry(object, key, where);
        if (!v.is_array())
          fail("'" + where + key + "' is not a list");
        return v;
      }

      Profile
      profile(const Json &object, const std::string &key, const std::string &where) const
      {
        return Profile::from_samples(numbers(object, key, where), "checkpoint '" + path + "', " + where + key);
      }

    private:
      std::string path;
    };

    Json
    parse_checkpoint(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      if (!in)
        throw InputError("Cannot resume: the checkpoint '" + path +
                         "' does not exist (was the run started with this output "
                         "directory, and did it finish at least one wear iteration?).");
      std::stringstream text;
      text << in.rdbuf();
      try
        {
          return Json::parse(text.str());
        }
      catch (const Json::parse_error &e)
        {
          Reader(path).fail(std::string("not valid JSON: ") + e.what());
        }
    }

    IterationRecord
    read_record(const Reader &r, const Json &j, const std::string &where)
    {
      IterationRecord rec;
      rec.volume_pin           = r.number(j, "volume_pin", where);
      rec.volume_bore          = r.number(j, "volume_bore", where);
      rec.archard_pin          = r.number(j, "archard_pin", where);
      rec.archard_bore         = r.number(j, "archard_bore", where);
      rec.max_depth_pin        = r.number(j, "max_depth_pin", where);
      rec.max_depth_bore       = r.number(j, "max_depth_bore", where);
      rec.mean_normal_force    = r.number(j, "mean_normal_force", where);
      rec.sliding_distance     = r.number(j, "sliding_distance", where);
      rec.relative_revolutions = r.number(j, "relative_revolutions", where);
      rec.depth_pin            = r.numbers(j, "depth_pin", where);
      rec.depth_bore           = r.numbers(j, "depth_bore", where);
      return rec;
    }

    JointWearState
    read_joint(const Reader &r, const Json &j, const std::string &where)
    {
      JointWearState js;
      js.name             = r.text(j, "name", where);
      js.initial_bore     = r.profile(j, "initial_bore", where);
      js.initial_pin      = r.profile(j, "initial_pin", where);
      js.bore             = r.profile(j, "bore", where);
      js.pin              = r.profile(j, "pin", where);
      js.meshed_bore      = r.profile(j, "meshed_bore", where);
      js.meshed_pin       = r.profile(j, "meshed_pin", where);
      const Json &history = r.list(j, "history", where);
      for (std::size_t k = 0; k < history.size(); ++k)
        js.history.push_back(read_record(r, history[k], where + "history[" + std::to_string(k) + "]."));
      return js;
    }
  } // namespace

  void
  WearState::write(const std::string &path) const
  {
    Json j           = Json::object();
    j["format"]      = format_name;
    j["version"]     = format_version;
    j["fingerprint"] = fingerprint;
    j["iterations"]  = iterations_done;
    j["revolutions"] = revolutions;
    j["time_s"]      = time;
    j["state"]       = to_json(std::vector<double>(state.data(), state.data() + state.size()));
    j["factors"]     = to_json(factors);
    j["modes"]       = to_json(modes);
    j["joints"]      = Json::array();
    for (const auto &js : joints)
      j["joints"].push_back(to_json(js));
    // Doubles are written in their shortest form that reads back to the same bits.
    write_file_atomically(path, j.dump(1) + "\n");
  }

  WearState
  WearState::read(const std::string &path)
  {
    const Json   j = parse_checkpoint(path);
    const Reader r(path);
    if (r.text(j, "format") != format_name)
      r.fail("not a wear checkpoint");
    if (r.number(j, "version") != format_version)
      r.fail("format version " + r.entry(j, "version", "").dump() + ", this wearlink reads version " +
             std::to_string(format_version));
    WearState s;
    s.fingerprint       = r.text(j, "fingerprint");
    const double n_iter = r.number(j, "iterations");
    if (!(n_iter >= 0 && n_iter <= 1e9 && n_iter == std::floor(n_iter)))
      r.fail("'iterations' is not a count");
    s.iterations_done  = static_cast<unsigned int>(n_iter);
    s.revolutions      = r.number(j, "revolutions");
    s.time             = r.number(j, "time_s");
    const auto y       = r.numbers(j, "state");
    s.state            = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    s.factors          = r.numbers(j, "factors");
    s.modes            = r.numbers(j, "modes");
    const Json &joints = r.list(j, "joints");
    for (std::size_t i = 0; i < joints.size(); ++i)
      s.joints.push_back(read_joint(r, joints[i], "joints[" + std::to_string(i) + "]."));
    return s;
  }
} // namespace wearlink::wear
