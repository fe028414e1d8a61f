// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/text.h"

#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace wearlink
{
  std::string
  trim(const std::string &s, const std::string &blanks)
  {
    const auto first = s.find_first_not_of(blanks);
    if (first == std::string::npos)
      return "";
    return s.substr(first, s.find_last_not_of(blanks) - first + 1);
  }

  std::string
  format_number(const double value, const int significant_digits)
  {
    std::string s;
    append_number(s, value, significant_digits);
    return s;
  }

  void
  append_number(std::string &out, const double value, const int significant_digits)
  {
    if (significant_digits >= 1 && significant_digits <= std::numeric_limits<double>::max_digits10)
      {
        char buffer[32]; // sign, 17 digits, point, exponent
        const auto [end, error] =
          std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, significant_digits);
        if (error == std::errc())
          {
            out.append(buffer, end);
            return;
          }
      }
    std::ostringstream os; // more digits than a double carries, or none: as iostream writes them
    os << std::setprecision(significant_digits) << value;
    out += os.str();
  }

  std::string
  format_or_na(const double value, const int significant_digits)
  {
    return std::isfinite(value) ? format_number(value, significant_digits) : "n/a";
  }

  bool
  is_valid_utf8(const std::string &s)
  {
    std::size_t i = 0;
    while (i < s.size())
      {
        const auto   c = static_cast<unsigned char>(s[i]);
        unsigned int n = 0; // continuation bytes
        char32_t     code;
        if (c < 0x80)
          {
            ++i;
            continue;
          }
        if (c >= 0xC2 && c <= 0xDF)
          n = 1, code = c & 0x1F;
        else if (c >= 0xE0 && c <= 0xEF)
          n = 2, code = c & 0x0F;
        else if (c >= 0xF0 && c <= 0xF4)
          n = 3, code = c & 0x07;
        else
          return false; // a continuation byte without a lead, or an invalid lead
        if (i + n >= s.size())
          return false; // truncated
        for (unsigned int k = 1; k <= n; ++k)
          {
            const auto b = static_cast<unsigned char>(s[i + k]);
            if ((b & 0xC0) != 0x80)
              return false;
            code = (code << 6) | (b & 0x3F);
          }
        const char32_t smallest[] = {0, 0x80, 0x800, 0x10000};
        if (code < smallest[n] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
          return false;
        i += n + 1;
      }
    return true;
  }

  std::vector<std::string>
  split(const std::string &s, const char sep)
  {
    std::vector<std::string> out;
    std::stringstream        in(s);
    for (std::string part; std::getline(in, part, sep);)
      out.push_back(trim(part, " \t"));
    return out;
  }

  std::string
  join(const std::vector<std::string> &parts, const std::string &sep)
  {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i)
      s += (i ? sep : "") + parts[i];
    return s;
  }

  std::string
  shorten_long_words(const std::string &message, const std::size_t longest, const std::size_t kept)
  {
    const auto is_blank = [](const char c) {
      return c == ' ' || c == '\n' || c == '\t' || c == '\r';
    };
    std::string out;
    std::size_t i = 0;
    while (i < message.size())
      {
        std::size_t end = i;
        while (end < message.size() && !is_blank(message[end]))
          ++end;
        if (end - i > longest)
          {
            std::size_t cut = i + kept;
            while (cut > i && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80)
              --cut; // not inside a UTF-8 sequence
            out.append(message, i, cut - i);
            out += "… [" + std::to_string(end - i) + " characters]";
          }
        else
          out.append(message, i, end - i);
        for (i = end; i < message.size() && is_blank(message[i]); ++i)
          out += message[i];
      }
    return out;
  }
} // namespace wearlink
