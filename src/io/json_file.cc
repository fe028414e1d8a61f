// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/json_file.h"

#include "base/exceptions.h"

#include <fstream>
#include <sstream>

namespace wearlink::io
{
  Json
  read_json_file(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw InputError("Cannot open the JSON file '" + path + "'.");
    std::stringstream text;
    text << in.rdbuf();
    try
      {
        return Json::parse(text.str());
      }
    catch (const Json::parse_error &e)
      {
        throw InputError("The JSON file '" + path + "' is malformed: " + e.what());
      }
  }
} // namespace wearlink::io
