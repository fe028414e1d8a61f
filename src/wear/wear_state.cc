// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/wear_state.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/json.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <zlib.h>

namespace wearlink::wear
{
  namespace
  {
    constexpr const char *format_name    = "wearlink wear checkpoint";
    constexpr int         format_version = 7;
    constexpr const char *payload_key    = "\"payload\": ";
    constexpr const char *refused =
      " Resume is refused; start the run afresh (`--overwrite`) or restore an intact copy of the checkpoint.";

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
      j["envelope_depth_pin"]   = r.envelope_depth_pin;
      j["envelope_depth_bore"]  = r.envelope_depth_bore;
      j["roughness_pin"]        = r.roughness_pin;
      j["roughness_bore"]       = r.roughness_bore;
      j["mean_normal_force"]    = r.mean_normal_force;
      j["sliding_distance"]     = r.sliding_distance;
      j["relative_revolutions"] = r.relative_revolutions;
      j["depth_pin"]            = to_json(r.depth_pin);
      j["depth_bore"]           = to_json(r.depth_bore);
      return j;
    }

    Json
    to_json(const WearRate &r)
    {
      Json j                    = Json::object();
      j["depth_pin"]            = to_json(r.depth_pin);
      j["depth_bore"]           = to_json(r.depth_bore);
      j["volume_pin"]           = r.volume_pin;
      j["volume_bore"]          = r.volume_bore;
      j["archard_pin"]          = r.archard_pin;
      j["archard_bore"]         = r.archard_bore;
      j["sliding_distance"]     = r.sliding_distance;
      j["relative_revolutions"] = r.relative_revolutions;
      return j;
    }

    Json
    to_json(const JointWearState &js)
    {
      Json j             = Json::object();
      j["name"]          = js.name;
      j["initial_bore"]  = to_json(js.initial_bore.samples());
      j["initial_pin"]   = to_json(js.initial_pin.samples());
      j["bore"]          = to_json(js.bore.samples());
      j["pin"]           = to_json(js.pin.samples());
      j["meshed_bore"]   = to_json(js.meshed_bore.samples());
      j["meshed_pin"]    = to_json(js.meshed_pin.samples());
      j["contact_width"] = js.contact_width;
      j["last_rate"]     = to_json(js.last_rate);
      const auto &u      = js.start_up;
      j["start_up"]      = {{"impacts", u.impacts},
                            {"mean_normal_force", u.mean_normal_force},
                            {"peak_normal_force", u.peak_normal_force},
                            {"carries", u.carries},
                            {"largest_carry", u.largest_carry},
                            {"carry_failures", u.carry_failures}};
      j["history"]       = Json::array();
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
                         "); it was not written by this wearlink or was edited." + refused);
      }

      [[noreturn]] void
      damaged(const std::string &what) const
      {
        throw InputError("The checkpoint '" + path + "' is damaged: " + what + "." + refused);
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

    std::string
    crc32_of(const std::string &bytes)
    {
      const auto *data = reinterpret_cast<const Bytef *>(bytes.data());
      char        hex[16];
      std::snprintf(hex, sizeof(hex), "%08lx", ::crc32_z(::crc32_z(0L, Z_NULL, 0), data, bytes.size()));
      return hex;
    }

    std::string
    file_text(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      if (!in)
        throw InputError("Cannot resume: the checkpoint '" + path +
                         "' does not exist (was the run started with this output "
                         "directory, and did it finish at least one wear iteration?).");
      std::stringstream text;
      text << in.rdbuf();
      return text.str();
    }

    /** A file without the header line: an older format (named), or not a checkpoint. */
    [[noreturn]] void
    refuse_headerless(const Reader &r, const std::string &text)
    {
      Json j;
      try
        {
          j = Json::parse(text);
        }
      catch (const Json::parse_error &)
        {
          r.fail("no header line: it is truncated or not a wear checkpoint");
        }
      if (j.is_object() && j.contains("version") && j.contains("format") && j.at("format") == format_name)
        r.fail("format version " + j.at("version").dump() + ", this wearlink reads version " +
               std::to_string(format_version));
      r.fail("not a wear checkpoint");
    }

    /** The header's checks, then the payload checked against its length and checksum. */
    Json
    parse_checkpoint(const std::string &path)
    {
      const std::string text = file_text(path);
      const Reader      r(path);
      const auto        nl = text.find('\n');
      const std::string key(payload_key);
      if (nl == std::string::npos || nl == 0 || text[nl - 1] != ',' || text.compare(nl + 1, key.size(), key) != 0)
        refuse_headerless(r, text);
      Json header;
      try
        {
          header = Json::parse(text.substr(0, nl - 1) + "}");
        }
      catch (const Json::parse_error &)
        {
          r.damaged("its header line is not valid JSON");
        }
      if (r.text(header, "format") != format_name)
        r.fail("not a wear checkpoint");
      if (r.number(header, "version") != format_version)
        r.fail("format version " + r.entry(header, "version", "").dump() + ", this wearlink reads version " +
               std::to_string(format_version));
      const double      bytes   = r.number(header, "payload_bytes");
      const std::string crc     = r.text(header, "payload_crc32");
      const std::string payload = text.substr(nl + 1 + key.size());
      if (!(bytes >= 0 && bytes == std::floor(bytes)))
        r.damaged("its header's payload_bytes is not a count");
      const auto n = static_cast<std::size_t>(bytes);
      if (payload.size() < n + 2)
        r.damaged("it is truncated: " + std::to_string(payload.size() < 2 ? 0 : payload.size() - 2) + " of the " +
                  std::to_string(n) + " bytes its header announces (a full disk, or a copy that did not finish)");
      if (payload.size() != n + 2 || payload.compare(n, 2, "}\n") != 0)
        r.damaged("it does not end where its header says (" + std::to_string(payload.size() - 2) + " bytes, " +
                  std::to_string(n) + " announced)");
      const std::string body = payload.substr(0, n);
      if (crc32_of(body) != crc)
        r.damaged("its checksum does not match its content (CRC-32 " + crc32_of(body) + ", the header says " + crc +
                  "): a byte was changed after it was written");
      try
        {
          return Json::parse(body);
        }
      catch (const Json::parse_error &e)
        {
          r.fail(std::string("not valid JSON: ") + e.what());
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
      rec.envelope_depth_pin   = r.number(j, "envelope_depth_pin", where);
      rec.envelope_depth_bore  = r.number(j, "envelope_depth_bore", where);
      rec.roughness_pin        = r.number(j, "roughness_pin", where);
      rec.roughness_bore       = r.number(j, "roughness_bore", where);
      rec.mean_normal_force    = r.number(j, "mean_normal_force", where);
      rec.sliding_distance     = r.number(j, "sliding_distance", where);
      rec.relative_revolutions = r.number(j, "relative_revolutions", where);
      rec.depth_pin            = r.numbers(j, "depth_pin", where);
      rec.depth_bore           = r.numbers(j, "depth_bore", where);
      return rec;
    }

    WearRate
    read_rate(const Reader &r, const Json &j, const std::string &where)
    {
      WearRate rate;
      rate.depth_pin            = r.numbers(j, "depth_pin", where);
      rate.depth_bore           = r.numbers(j, "depth_bore", where);
      rate.volume_pin           = r.number(j, "volume_pin", where);
      rate.volume_bore          = r.number(j, "volume_bore", where);
      rate.archard_pin          = r.number(j, "archard_pin", where);
      rate.archard_bore         = r.number(j, "archard_bore", where);
      rate.sliding_distance     = r.number(j, "sliding_distance", where);
      rate.relative_revolutions = r.number(j, "relative_revolutions", where);
      return rate;
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
      js.contact_width    = r.number(j, "contact_width", where);
      js.last_rate        = read_rate(r, r.entry(j, "last_rate", where), where + "last_rate.");
      const Json &u       = r.entry(j, "start_up", where);
      const auto  w       = where + "start_up.";
      js.start_up         = {r.number(u, "impacts", w),
                             r.number(u, "mean_normal_force", w),
                             r.number(u, "peak_normal_force", w),
                             r.number(u, "carries", w),
                             r.number(u, "largest_carry", w),
                             r.number(u, "carry_failures", w)};
      const Json &history = r.list(j, "history", where);
      for (std::size_t k = 0; k < history.size(); ++k)
        js.history.push_back(read_record(r, history[k], where + "history[" + std::to_string(k) + "]."));
      return js;
    }
  } // namespace

  namespace
  {
    Json
    ledger_to_json(const std::map<std::string, std::map<std::string, long>> &ledger)
    {
      Json j = Json::object();
      for (const auto &[category, counts] : ledger)
        {
          Json c = Json::object();
          for (const auto &[key, n] : counts)
            c[key] = n;
          j[category] = c;
        }
      return j;
    }

    std::map<std::string, std::map<std::string, long>>
    read_ledger(const Reader &r, const Json &j)
    {
      std::map<std::string, std::map<std::string, long>> out;
      const Json                                        &ledger = r.entry(j, "ledger", "");
      if (!ledger.is_object())
        r.fail("'ledger' is not an object");
      for (const auto &[category, counts] : ledger.items())
        {
          if (!counts.is_object())
            r.fail("'ledger." + category + "' is not an object");
          for (const auto &[key, n] : counts.items())
            {
              if (!n.is_number_integer())
                r.fail("'ledger." + category + "." + key + "' is not a count");
              out[category][key] = n.get<long>();
            }
        }
      return out;
    }

    /** A warning's value or limit: a number, or "inf" / "-inf" (JSON has no infinity). */
    Json
    warning_number(const double x)
    {
      return std::isfinite(x) ? Json(x) : Json(x > 0 ? "inf" : "-inf");
    }

    double
    read_warning_number(const Reader &r, const Json &j, const std::string &key, const std::string &where)
    {
      const Json &v = r.entry(j, key, where);
      if (v.is_string() && (v == "inf" || v == "-inf"))
        return (v == "inf" ? 1 : -1) * std::numeric_limits<double>::infinity();
      return r.number(j, key, where);
    }

    Json
    warnings_to_json(const ValidityWarnings &warnings)
    {
      Json list = Json::array();
      for (const auto &w : warnings.warnings())
        {
          Json j         = Json::object();
          j["quantity"]  = w.quantity;
          j["value"]     = warning_number(w.value);
          j["limit"]     = warning_number(w.limit);
          j["unit"]      = w.unit;
          j["why_limit"] = w.why_limit;
          j["meaning"]   = w.meaning;
          list.push_back(j);
        }
      return list;
    }

    ValidityWarnings
    read_warnings(const Reader &r, const Json &j)
    {
      ValidityWarnings out;
      const Json      &list = r.list(j, "warnings");
      for (std::size_t k = 0; k < list.size(); ++k)
        {
          const std::string where = "warnings[" + std::to_string(k) + "].";
          ValidityWarning   w;
          w.quantity  = r.text(list[k], "quantity", where);
          w.value     = read_warning_number(r, list[k], "value", where);
          w.limit     = read_warning_number(r, list[k], "limit", where);
          w.unit      = r.text(list[k], "unit", where);
          w.why_limit = r.text(list[k], "why_limit", where);
          w.meaning   = r.text(list[k], "meaning", where);
          if (!(w.value > w.limit))
            r.fail("'" + where + "value' does not exceed its limit");
          out.check(w);
        }
      return out;
    }

    std::map<std::string, std::string>
    read_scene_entries(const Reader &r, const Json &j)
    {
      std::map<std::string, std::string> out;
      const Json                        &scene = r.entry(j, "scene", "");
      if (!scene.is_object())
        r.fail("'scene' is not an object");
      for (const auto &[key, value] : scene.items())
        out[key] = r.text(scene, key, "scene.");
      return out;
    }

    /** The sizes inside the state agree with each other (before anything is used). */
    void
    check_consistency(const Reader &r, const WearState &s)
    {
      const auto n = std::to_string(s.iterations_done);
      if (s.factors.size() != s.iterations_done)
        r.fail("'factors' has " + std::to_string(s.factors.size()) + " entries for " + n + " iterations");
      if (s.modes.size() % 2 != 0)
        r.fail("'modes' has an odd number of entries");
      if (!std::isfinite(s.time) || !std::isfinite(s.revolutions) || s.revolutions < 0)
        r.fail("'time_s' or 'revolutions' is not a finite time or count");
      for (std::size_t i = 0; i < s.joints.size(); ++i)
        {
          const auto       &js = s.joints[i];
          const std::string at = "joints[" + std::to_string(i) + "].";
          const auto        nb = js.initial_bore.n_points(), np = js.initial_pin.n_points();
          if (js.bore.n_points() != nb || js.meshed_bore.n_points() != nb)
            r.fail("'" + at + "bore' and 'meshed_bore' must have as many samples as 'initial_bore' (" +
                   std::to_string(nb) + ")");
          if (js.pin.n_points() != np || js.meshed_pin.n_points() != np)
            r.fail("'" + at + "pin' and 'meshed_pin' must have as many samples as 'initial_pin' (" +
                   std::to_string(np) + ")");
          if (js.history.size() != s.iterations_done)
            r.fail("'" + at + "history' has " + std::to_string(js.history.size()) + " records for " + n +
                   " iterations");
          const bool rate_known = !js.last_rate.empty();
          if (rate_known != (s.iterations_done > 0) ||
              (rate_known && (js.last_rate.depth_pin.size() != np || js.last_rate.depth_bore.size() != nb)))
            r.fail("'" + at + "last_rate' has depths of another size than the profiles, or does not match the " +
                   "number of iterations");
          for (std::size_t k = 0; k < js.history.size(); ++k)
            if (js.history[k].depth_pin.size() != np || js.history[k].depth_bore.size() != nb)
              r.fail("'" + at + "history[" + std::to_string(k) + "]' has depths of another size than the profiles");
        }
    }
  } // namespace

  void
  WearState::write(const std::string &path) const
  {
    Json j           = Json::object();
    j["fingerprint"] = fingerprint;
    j["scene"]       = Json::object();
    for (const auto &[key, value] : scene)
      j["scene"][key] = value;
    j["iterations"]                 = iterations_done;
    j["revolutions"]                = revolutions;
    j["time_s"]                     = time;
    j["state"]                      = to_json(std::vector<double>(state.data(), state.data() + state.size()));
    j["factors"]                    = to_json(factors);
    j["settling_cycles"]            = settling_cycles;
    j["modes"]                      = to_json(modes);
    j["response_before_peaks_m_s2"] = to_json(response_before_peaks);
    j["ledger"]                     = ledger_to_json(ledger);
    j["timings_s"]                  = timings.to_json();
    j["warnings"]                   = warnings_to_json(warnings);
    j["joints"]                     = Json::array();
    for (const auto &js : joints)
      j["joints"].push_back(to_json(js));
    // Doubles are written in their shortest form that reads back to the same bits.
    const std::string payload = j.dump(1);
    Json              header  = Json::object();
    header["format"]          = format_name;
    header["version"]         = format_version;
    header["payload_bytes"]   = payload.size();
    header["payload_crc32"]   = crc32_of(payload);
    std::string text          = header.dump();
    text.pop_back(); // the closing brace: the payload is the last entry
    write_file_atomically(path, text + ",\n" + payload_key + payload + "}\n");
  }

  WearState
  WearState::read(const std::string &path)
  {
    const Json   j = parse_checkpoint(path);
    const Reader r(path);
    WearState    s;
    s.fingerprint       = r.text(j, "fingerprint");
    s.scene             = read_scene_entries(r, j);
    const double n_iter = r.number(j, "iterations");
    if (!(n_iter >= 0 && n_iter <= 1e9 && n_iter == std::floor(n_iter)))
      r.fail("'iterations' is not a count");
    s.iterations_done       = static_cast<unsigned int>(n_iter);
    s.revolutions           = r.number(j, "revolutions");
    s.time                  = r.number(j, "time_s");
    const auto y            = r.numbers(j, "state");
    s.state                 = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    s.factors               = r.numbers(j, "factors");
    s.settling_cycles       = r.number(j, "settling_cycles");
    s.modes                 = r.numbers(j, "modes");
    s.response_before_peaks = r.numbers(j, "response_before_peaks_m_s2");
    s.ledger                = read_ledger(r, j);
    const Json &joints      = r.list(j, "joints");
    for (std::size_t i = 0; i < joints.size(); ++i)
      s.joints.push_back(read_joint(r, joints[i], "joints[" + std::to_string(i) + "]."));
    if (!PhaseTimings::from_json(r.entry(j, "timings_s", ""), s.timings))
      r.fail("'timings_s' is not the phases' wall times");
    s.warnings = read_warnings(r, j);
    check_consistency(r, s);
    return s;
  }

  void
  WearState::check_shape(const StateShape &shape, const std::string &where) const
  {
    const std::string cannot = "Cannot resume from '" + where + "': ";
    const std::string fix    = " Resume with the scene the run was started with, or start afresh (`--overwrite`).";
    if (joints.size() != shape.joints.size())
      throw InputError(cannot + "it holds " + std::to_string(joints.size()) + " wearing joints, the scene has " +
                       std::to_string(shape.joints.size()) + "." + fix);
    for (std::size_t i = 0; i < joints.size(); ++i)
      {
        const auto &have = joints[i];
        const auto &want = shape.joints[i];
        if (have.name != want.name)
          throw InputError(cannot + "its wearing joint " + std::to_string(i + 1) + " is '" + have.name +
                           "', the scene's is '" + want.name + "'." + fix);
        if (have.bore.n_points() != want.n_bore || have.pin.n_points() != want.n_pin)
          throw InputError(cannot + "the profiles of joint " + have.name + " have " +
                           std::to_string(have.bore.n_points()) + " (bore) and " + std::to_string(have.pin.n_points()) +
                           " (pin) samples, the scene's " + std::to_string(want.n_bore) + " and " +
                           std::to_string(want.n_pin) + "." + fix);
      }
    if (static_cast<std::size_t>(state.size()) != shape.n_state)
      throw InputError(cannot + "its state has " + std::to_string(state.size()) +
                       " entries, the mechanism of the scene needs " + std::to_string(shape.n_state) + "." + fix);
    if (modes.size() != shape.n_modes)
      throw InputError(cannot + "it holds contact modes of " + std::to_string(modes.size() / 2) +
                       " clearance joints, the scene has " + std::to_string(shape.n_modes / 2) + "." + fix);
  }
} // namespace wearlink::wear
