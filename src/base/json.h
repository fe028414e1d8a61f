// SPDX-License-Identifier: LGPL-2.1-or-later
// A small JSON value for run summaries and checkpoint metadata: objects keep their
// insertion order (a summary reads top-down), numbers are written with full precision,
// non-finite numbers are written as null (JSON has no NaN) so a broken run is visible.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace wearlink
{
  class Json
  {
  public:
    enum class Type
    {
      null,
      boolean,
      number,
      string,
      array,
      object
    };

    Json()
      : type_(Type::null)
    {}
    Json(double v)
      : type_(Type::number)
      , number_(v)
    {}
    Json(int v)
      : Json(static_cast<double>(v))
    {}
    Json(long v)
      : Json(static_cast<double>(v))
    {}
    Json(unsigned long v)
      : Json(static_cast<double>(v))
    {}
    Json(unsigned int v)
      : Json(static_cast<double>(v))
    {}
    Json(bool v)
      : type_(Type::boolean)
      , bool_(v)
    {}
    Json(const char *s)
      : type_(Type::string)
      , string_(s)
    {}
    Json(std::string s)
      : type_(Type::string)
      , string_(std::move(s))
    {}

    static Json
    object();
    static Json
    array();

    Type
    type() const
    {
      return type_;
    }

    /** Object access; inserts a null member if absent (keeps insertion order). */
    Json &
    operator[](const std::string &key);
    /** Object read access; throws std::out_of_range if absent. */
    const Json &
    at(const std::string &key) const;
    bool
    contains(const std::string &key) const;
    const std::vector<std::pair<std::string, Json>> &
    members() const
    {
      return members_;
    }

    /** Array access. */
    void
    push_back(Json v);
    const Json &
    operator[](std::size_t i) const
    {
      return items_.at(i);
    }
    std::size_t
    size() const;

    double
    as_number() const;
    bool
    as_bool() const;
    const std::string &
    as_string() const;

    /** Serialize; @p indent < 0 gives one line. */
    std::string
    dump(int indent = 2) const;

    /** Parse JSON text; throws std::runtime_error with the offset on malformed input. */
    static Json
    parse(const std::string &text);

  private:
    void
    dump_to(std::string &out, int indent, int level) const;

    Type                                    type_;
    double                                  number_ = 0;
    bool                                    bool_   = false;
    std::string                             string_;
    std::vector<Json>                       items_;
    std::vector<std::pair<std::string, Json>> members_;
  };

  /** Read and parse a JSON file; an InputError naming the file if unreadable/malformed. */
  Json
  read_json_file(const std::string &path);
} // namespace wearlink
