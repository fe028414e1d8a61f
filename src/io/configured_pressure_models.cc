// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/configured_pressure_models.h"

#include "base/parameters.h"
#include "contact/pressure_model.h"

#include <algorithm>

namespace wearlink::io
{
  namespace
  {
    /**
     * The entries pressure model @p name itself requires, relative to its subsection
     * (its subsection may hold another family's entries too: the fe normal force law's
     * required Restitution coefficient sits in the same "fe" subsection).
     */
    std::vector<std::string>
    required_entries_of(const std::string &name)
    {
      dealii::ParameterHandler declared;
      contact::pressure_models().declare_all(declared);
      std::vector<std::string> own;
      for (const auto &path : unset_required_entries(declared))
        if (path.rfind(name + "/", 0) == 0)
          own.push_back(path);
      return own;
    }
  } // namespace

  std::vector<std::string>
  configured_pressure_models(const Scene &scene, const std::vector<std::string> &joints)
  {
    const auto               unset = unset_required_entries(*scene.parameters);
    std::vector<std::string> models;
    for (const auto &name : contact::pressure_models().names())
      {
        const auto required = required_entries_of(name);
        bool       given    = true;
        for (const auto &joint : joints)
          for (const auto &entry : required)
            given =
              given && std::find(unset.begin(), unset.end(), "Joint " + joint + "/Clearance/" + entry) == unset.end();
        if (given)
          models.push_back(name);
      }
    return models;
  }
} // namespace wearlink::io
