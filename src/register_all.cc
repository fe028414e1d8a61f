// SPDX-License-Identifier: LGPL-2.1-or-later
#include "register_all.h"

namespace wearlink
{
  namespace contact
  {
    void
    register_contact_effects();
  }
  namespace fe
  {
    void
    register_fe_effects();
  }

  void
  register_all()
  {
    static bool done = false;
    if (done)
      return;
    done = true;
    contact::register_contact_effects();
    fe::register_fe_effects();
  }
} // namespace wearlink
