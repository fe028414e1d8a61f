// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/wear/scene_identity.h"

#include "base/text.h"

#include <cstdint>
#include <cstdio>
#include <sstream>
#include <vector>

namespace wearlink::workflows
{
  bool
  is_run_control(const std::string &entry)
  {
    return entry.rfind("Output/", 0) == 0 || entry == "Wear/Number of iterations" ||
           entry == "Wear/Target revolutions" || entry == "Wear/FE output" || entry == "Wear/Profile magnification" ||
           entry == "Life/Maximum revolutions" || entry == "Life/Maximum iterations" ||
           entry == "Life/Response tolerance";
  }

  std::map<std::string, std::string>
  scene_entries(const io::Scene &scene)
  {
    std::ostringstream os;
    scene.parameters->print_parameters(os, dealii::ParameterHandler::ShortText);
    std::istringstream                 in(os.str());
    std::vector<std::string>           sections;
    std::map<std::string, std::string> out;
    std::string                        line;
    while (std::getline(in, line))
      {
        const std::string t = trim(line);
        if (t.rfind("subsection ", 0) == 0)
          sections.push_back(trim(t.substr(11)));
        else if (t == "end" && !sections.empty())
          sections.pop_back();
        else if (t.rfind("set ", 0) == 0 && t.find('=') != std::string::npos)
          {
            const auto  eq   = t.find('=');
            std::string path = "";
            for (const auto &s : sections)
              path += s + "/";
            path += trim(t.substr(4, eq - 4));
            if (!is_run_control(path))
              out[path] = trim(t.substr(eq + 1));
          }
      }
    return out;
  }

  std::string
  fingerprint(const std::map<std::string, std::string> &entries)
  {
    std::uint64_t h   = 14695981039346656037ull;
    const auto    mix = [&h](const std::string &s) {
      for (const unsigned char c : s)
        h = (h ^ c) * 1099511628211ull;
      h = (h ^ 0xffu) * 1099511628211ull; // a separator no text holds
    };
    for (const auto &[key, value] : entries)
      {
        mix(key);
        mix(value);
      }
    char hex[24];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(h));
    return hex;
  }

  std::string
  scene_differences(const std::map<std::string, std::string> &was,
                    const std::map<std::string, std::string> &now,
                    const unsigned int                        shown)
  {
    std::vector<std::string> lines;
    const auto               quoted = [](const std::map<std::string, std::string> &m, const std::string &key) {
      const auto it = m.find(key);
      return it == m.end() ? std::string("absent") : "'" + it->second + "'";
    };
    std::map<std::string, bool> keys;
    for (const auto &[k, v] : was)
      keys[k] = true;
    for (const auto &[k, v] : now)
      keys[k] = true;
    for (const auto &[k, unused] : keys)
      if (quoted(was, k) != quoted(now, k))
        lines.push_back("'" + k + "' is " + quoted(was, k) + " in the checkpoint and " + quoted(now, k) + " now");
    std::string out;
    for (std::size_t i = 0; i < lines.size() && i < shown; ++i)
      out += (i > 0 ? "; " : "") + lines[i];
    if (lines.size() > shown)
      out += "; and " + std::to_string(lines.size() - shown) + " more";
    return out;
  }
} // namespace wearlink::workflows
