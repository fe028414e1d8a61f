// SPDX-License-Identifier: LGPL-2.1-or-later
// Small text helpers used across the tree, defined once: trimming, splitting, joining
// and number formatting for messages, tables and files.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace wearlink
{
  /** @p s without leading and trailing characters of @p blanks. */
  std::string
  trim(const std::string &s, const std::string &blanks = " \t\r\n");

  /**
   * @p value with @p significant_digits significant digits in the shortest of fixed and
   * scientific notation (iostream's default). The default digits give back the same
   * double when read (max_digits10).
   */
  std::string
  format_number(double value, int significant_digits = std::numeric_limits<double>::max_digits10);

  /**
   * Append format_number(@p value, @p significant_digits) to @p out: the same characters
   * (printf's %g, which is also iostream's default), without a stream. Writers of long
   * tables use it; through an ostream each number costs ten times as much.
   */
  void
  append_number(std::string &out, double value, int significant_digits);

  /** format_number(), or "n/a" for a value that is not finite (a figure not available). */
  std::string
  format_or_na(double value, int significant_digits = 4);

  /**
   * Whether @p s is well-formed UTF-8 (no stray continuation bytes, no truncated or
   * overlong sequences, no surrogates, nothing above U+10FFFF). Text that ends up in a
   * JSON file must be.
   */
  bool
  is_valid_utf8(const std::string &s);

  /** The parts of @p s between the separators @p sep, each trimmed of blanks and tabs. */
  std::vector<std::string>
  split(const std::string &s, char sep);

  /** @p parts with @p sep between them. */
  std::string
  join(const std::vector<std::string> &parts, const std::string &sep);

  /**
   * @p message with every run of more than @p longest characters without a blank (a
   * value pasted by mistake, a damaged line) cut to its first @p kept characters and
   * "… [N characters]": a message echoes what the user gave, but a 10 MB value echoed
   * whole buries the message. UTF-8 sequences are not cut in half.
   */
  std::string
  shorten_long_words(const std::string &message, std::size_t longest = 1000, std::size_t kept = 80);
} // namespace wearlink
