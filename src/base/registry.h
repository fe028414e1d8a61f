// SPDX-License-Identifier: LGPL-2.1-or-later
// Registry<Interface>: the list of named plugins of one effect family (normal force
// laws, friction laws, pressure models, wear laws, analyses). Modeled on ASPECT's
// PluginList: each entry has a user-facing name (lower-case, hyphenated), a one-line
// description, a function declaring its parameters and a factory.
//
// Parameters of a plugin live in a subsection named after the plugin inside the
// family's section, e.g. "Joint A/Clearance/lankarani-nikravesh/Restitution
// coefficient". The factory receives a ParameterReader positioned in that subsection
// and returns a fully constructed, immutable plugin: nothing is built for a name the
// scene did not choose, and the ledger records what was.
//
// Registration is explicit (each layer's register.cc, called from register_all()),
// not static-initializer magic, because several executables link one static library.
#pragma once

#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wearlink
{
  template <class Interface>
  class Registry
  {
  public:
    using Declare = std::function<void(dealii::ParameterHandler &)>;
    using Factory = std::function<std::unique_ptr<Interface>(ParameterReader &)>;

    struct Entry
    {
      std::string name;
      std::string description;
      Declare     declare;
      Factory     create;
    };

    /** @param family user-facing family name, e.g. "normal force law". */
    explicit Registry(std::string family)
      : family_name(std::move(family))
    {
    }

    /** Add a plugin. Names are unique; adding one twice is a programming error. */
    void
    add(const std::string &name, const std::string &description, Declare declare, Factory create)
    {
      for (const auto &e : entries)
        AssertThrow(e.name != name,
                    dealii::ExcMessage("Plugin '" + name + "' registered twice in family '" + family_name + "'."));
      entries.push_back({name, description, std::move(declare), std::move(create)});
    }

    bool
    has(const std::string &name) const
    {
      for (const auto &e : entries)
        if (e.name == name)
          return true;
      return false;
    }

    /** "a|b|c", for Patterns::Selection. */
    std::string
    pattern() const
    {
      std::string p;
      for (const auto &e : entries)
        p += (p.empty() ? "" : "|") + e.name;
      return p;
    }

    /** Names, for contract tests instantiated over every registered plugin. */
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> n;
      for (const auto &e : entries)
        n.push_back(e.name);
      return n;
    }

    /** One line per plugin: "'name': description". Appended to the selection's doc. */
    std::string
    documentation() const
    {
      std::string d;
      for (const auto &e : entries)
        d += " '" + e.name + "': " + e.description;
      return d;
    }

    /** Declare every plugin's subsection (inside the current subsection of @p prm). */
    void
    declare_all(dealii::ParameterHandler &prm) const
    {
      for (const auto &e : entries)
        if (e.declare)
          {
            prm.enter_subsection(e.name);
            e.declare(prm);
            prm.leave_subsection();
          }
    }

    /**
     * Construct plugin @p name; @p reader is positioned in the family's section (the
     * plugin's own subsection is entered here). Unknown names are an InputError that
     * lists the valid ones; @p entry is the selection entry that named the plugin.
     */
    std::unique_ptr<Interface>
    create(const std::string &name, ParameterReader &reader, const std::string &entry) const
    {
      for (const auto &e : entries)
        if (e.name == name)
          {
            reader.enter(e.name);
            auto plugin = e.create(reader);
            reader.leave();
            EffectLedger::instance().record_construction(family_name, name);
            return plugin;
          }
      reader.fail(entry, "the valid " + family_name + " names are " + pattern());
    }

    const std::string &
    family() const
    {
      return family_name;
    }

  private:
    std::string        family_name;
    std::vector<Entry> entries;
  };
} // namespace wearlink
