// SPDX-License-Identifier: LGPL-2.1-or-later
// The on-disk cache of the `fe` normal force law's tables: the force–approach table of
// fe/fe_normal_force_law.h and the conformal table of fe/fe_conformal_table.h. A table is
// kept by geometry — the text key holds everything it depends on (the profiles' samples,
// those of the kept mesh if it is of other profiles, materials, axial length, FE and
// table settings) — in $WEARLINK_CACHE_DIR, else $XDG_CACHE_HOME/wearlink, else
// ~/.cache/wearlink. Each kind of table has its own file-name stem, format name and
// version; an entry that does not read back cleanly, or is of another format, version or
// key, is not used (the table is rebuilt and the file overwritten).
#pragma once

#include "base/json.h"
#include "contact/pressure_model.h"

#include <string>

namespace wearlink::fe
{
  struct FeForceLawSettings; // fe/fe_normal_force_law.h

  /**
   * Everything a table of @p geometry built with @p settings depends on, as text; the
   * profiles of @p meshed too if it is given and of other profiles (a kept mesh).
   */
  std::string
  table_geometry_key(const contact::JointGeometry &geometry,
                     const FeForceLawSettings     &settings,
                     const contact::JointGeometry *meshed);

  /** The cache file of a table of the kind @p stem (a file-name stem) with @p key. */
  std::string
  table_cache_file(const std::string &stem, const std::string &key);

  /**
   * The entry in @p file if it is a JSON object of @p format, @p version and @p key, else
   * null (missing, damaged, another format, version or key).
   */
  Json
  read_table_cache(const std::string &file, const std::string &format, int version, const std::string &key);

  /**
   * Write @p entry with its @p format, @p version and @p key to @p file (atomically); a
   * cache that cannot be written only costs time: a warning on standard error.
   */
  void
  write_table_cache(const std::string &file,
                    const std::string &format,
                    int                version,
                    const std::string &key,
                    Json               entry);
} // namespace wearlink::fe
