// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/json.h"

#include "base/exceptions.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace wearlink
{
  Json
  Json::object()
  {
    Json j;
    j.type_ = Type::object;
    return j;
  }

  Json
  Json::array()
  {
    Json j;
    j.type_ = Type::array;
    return j;
  }

  Json &
  Json::operator[](const std::string &key)
  {
    if (type_ == Type::null)
      type_ = Type::object;
    if (type_ != Type::object)
      throw std::logic_error("JSON: member access on a non-object");
    for (auto &m : members_)
      if (m.first == key)
        return m.second;
    members_.emplace_back(key, Json());
    return members_.back().second;
  }

  const Json &
  Json::at(const std::string &key) const
  {
    for (const auto &m : members_)
      if (m.first == key)
        return m.second;
    throw std::out_of_range("JSON: no member '" + key + "'");
  }

  bool
  Json::contains(const std::string &key) const
  {
    for (const auto &m : members_)
      if (m.first == key)
        return true;
    return false;
  }

  void
  Json::push_back(Json v)
  {
    if (type_ == Type::null)
      type_ = Type::array;
    if (type_ != Type::array)
      throw std::logic_error("JSON: push_back on a non-array");
    items_.push_back(std::move(v));
  }

  std::size_t
  Json::size() const
  {
    return type_ == Type::array ? items_.size() : members_.size();
  }

  double
  Json::as_number() const
  {
    if (type_ == Type::null)
      return std::numeric_limits<double>::quiet_NaN();
    if (type_ != Type::number)
      throw std::logic_error("JSON: value is not a number");
    return number_;
  }

  bool
  Json::as_bool() const
  {
    if (type_ != Type::boolean)
      throw std::logic_error("JSON: value is not a boolean");
    return bool_;
  }

  const std::string &
  Json::as_string() const
  {
    if (type_ != Type::string)
      throw std::logic_error("JSON: value is not a string");
    return string_;
  }

  namespace
  {
    void
    escape(std::string &out, const std::string &s)
    {
      out += '"';
      for (const char c : s)
        switch (c)
          {
            case '"':
              out += "\\\"";
              break;
            case '\\':
              out += "\\\\";
              break;
            case '\n':
              out += "\\n";
              break;
            case '\t':
              out += "\\t";
              break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char buf[8];
                  std::snprintf(buf, sizeof(buf), "\\u%04x", c);
                  out += buf;
                }
              else
                out += c;
          }
      out += '"';
    }

    void
    newline(std::string &out, int indent, int level)
    {
      if (indent < 0)
        return;
      out += '\n';
      out.append(static_cast<std::size_t>(indent * level), ' ');
    }
  } // namespace

  void
  Json::dump_to(std::string &out, int indent, int level) const
  {
    switch (type_)
      {
        case Type::null:
          out += "null";
          break;
        case Type::boolean:
          out += bool_ ? "true" : "false";
          break;
        case Type::number:
          if (!std::isfinite(number_))
            out += "null";
          else if (number_ == std::floor(number_) && std::abs(number_) < 1e15)
            out += std::to_string(static_cast<long long>(number_));
          else
            {
              char buf[32];
              std::snprintf(buf, sizeof(buf), "%.17g", number_);
              out += buf;
            }
          break;
        case Type::string:
          escape(out, string_);
          break;
        case Type::array:
          out += '[';
          for (std::size_t i = 0; i < items_.size(); ++i)
            {
              if (i)
                out += ',';
              newline(out, indent, level + 1);
              items_[i].dump_to(out, indent, level + 1);
            }
          if (!items_.empty())
            newline(out, indent, level);
          out += ']';
          break;
        case Type::object:
          out += '{';
          for (std::size_t i = 0; i < members_.size(); ++i)
            {
              if (i)
                out += ',';
              newline(out, indent, level + 1);
              escape(out, members_[i].first);
              out += indent < 0 ? ":" : ": ";
              members_[i].second.dump_to(out, indent, level + 1);
            }
          if (!members_.empty())
            newline(out, indent, level);
          out += '}';
          break;
      }
  }

  std::string
  Json::dump(int indent) const
  {
    std::string out;
    dump_to(out, indent, 0);
    if (indent >= 0)
      out += '\n';
    return out;
  }

  namespace
  {
    class Parser
    {
    public:
      explicit Parser(const std::string &t)
        : text(t)
      {}

      Json
      parse_document()
      {
        Json v = value();
        skip();
        if (pos != text.size())
          error("trailing characters");
        return v;
      }

    private:
      const std::string &text;
      std::size_t        pos = 0;

      [[noreturn]] void
      error(const std::string &what) const
      {
        throw std::runtime_error("malformed JSON at offset " + std::to_string(pos) + ": " +
                                 what);
      }

      void
      skip()
      {
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos])))
          ++pos;
      }

      bool
      consume(const char *word)
      {
        const std::size_t n = std::char_traits<char>::length(word);
        if (text.compare(pos, n, word) == 0)
          {
            pos += n;
            return true;
          }
        return false;
      }

      std::string
      string_literal()
      {
        if (text[pos] != '"')
          error("expected a string");
        ++pos;
        std::string s;
        while (pos < text.size() && text[pos] != '"')
          {
            char c = text[pos++];
            if (c == '\\')
              {
                if (pos >= text.size())
                  error("unterminated escape");
                const char e = text[pos++];
                switch (e)
                  {
                    case 'n':
                      c = '\n';
                      break;
                    case 't':
                      c = '\t';
                      break;
                    case 'r':
                      c = '\r';
                      break;
                    case 'b':
                      c = '\b';
                      break;
                    case 'f':
                      c = '\f';
                      break;
                    case 'u':
                      {
                        if (pos + 4 > text.size())
                          error("short \\u escape");
                        c = static_cast<char>(std::stoi(text.substr(pos, 4), nullptr, 16));
                        pos += 4;
                        break;
                      }
                    default:
                      c = e;
                  }
              }
            s += c;
          }
        if (pos >= text.size())
          error("unterminated string");
        ++pos;
        return s;
      }

      Json
      value()
      {
        skip();
        if (pos >= text.size())
          error("unexpected end");
        const char c = text[pos];
        if (c == '{')
          {
            ++pos;
            Json o = Json::object();
            skip();
            if (text[pos] == '}')
              {
                ++pos;
                return o;
              }
            while (true)
              {
                skip();
                const std::string key = string_literal();
                skip();
                if (text[pos] != ':')
                  error("expected ':'");
                ++pos;
                o[key] = value();
                skip();
                if (text[pos] == ',')
                  {
                    ++pos;
                    continue;
                  }
                if (text[pos] == '}')
                  {
                    ++pos;
                    return o;
                  }
                error("expected ',' or '}'");
              }
          }
        if (c == '[')
          {
            ++pos;
            Json a = Json::array();
            skip();
            if (text[pos] == ']')
              {
                ++pos;
                return a;
              }
            while (true)
              {
                a.push_back(value());
                skip();
                if (text[pos] == ',')
                  {
                    ++pos;
                    continue;
                  }
                if (text[pos] == ']')
                  {
                    ++pos;
                    return a;
                  }
                error("expected ',' or ']'");
              }
          }
        if (c == '"')
          return Json(string_literal());
        if (consume("true"))
          return Json(true);
        if (consume("false"))
          return Json(false);
        if (consume("null"))
          return Json();
        const char *begin = text.c_str() + pos;
        char *      end   = nullptr;
        const double v    = std::strtod(begin, &end);
        if (end == begin)
          error("unexpected character");
        pos += static_cast<std::size_t>(end - begin);
        return Json(v);
      }
    };
  } // namespace

  Json
  Json::parse(const std::string &text)
  {
    return Parser(text).parse_document();
  }

  Json
  read_json_file(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError("Cannot open the JSON file '" + path + "'.");
    std::stringstream ss;
    ss << in.rdbuf();
    try
      {
        return Json::parse(ss.str());
      }
    catch (const std::runtime_error &e)
      {
        throw InputError("The JSON file '" + path + "' is " + e.what() + ".");
      }
  }
} // namespace wearlink
