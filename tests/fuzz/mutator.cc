// SPDX-License-Identifier: LGPL-2.1-or-later
// The mutator: 1–3 changes to the files a shipped scene reads (the scene, the files it
// includes, the profile CSVs it names). Entries deleted, duplicated, renamed; values
// replaced by extreme, non-finite, negative, huge or wrong-typed ones, or scaled far out
// of range; includes made cyclic or pointed at nothing; files truncated at a random
// byte, given garbage bytes, a UTF-8 BOM or CRLF line ends; subsection structure broken.
#include "fuzz.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>

namespace wearlink::fuzz
{
  namespace
  {
    namespace fs = std::filesystem;

    /** Values that replace an entry's value (or one item of a list). */
    const std::vector<std::string> extreme_values = {"nan",
                                                     "NaN",
                                                     "-nan",
                                                     "inf",
                                                     "-inf",
                                                     "Infinity",
                                                     "-1",
                                                     "0",
                                                     "-0",
                                                     "1e300",
                                                     "-1e300",
                                                     "1e-300",
                                                     "1e309",
                                                     "4.9e-324",
                                                     "-1e-300",
                                                     "99999999999999999999",
                                                     "2147483648",
                                                     "4294967297",
                                                     "-2147483649",
                                                     "1e18",
                                                     "abc",
                                                     "",
                                                     "true",
                                                     "1,2,3",
                                                     ",",
                                                     "0x1p3",
                                                     "1e",
                                                     "--1",
                                                     "1.5.2",
                                                     "\xef\xbc\x91",
                                                     "0, nan",
                                                     "nan, 0",
                                                     "1e300, -1e300",
                                                     "ground",
                                                     "body 3",
                                                     "none"};

    /** Factors that take a numeric value far out of its physical range. */
    const std::vector<double> scale_factors = {-1, 0, 1e-12, 1e-6, 1e-3, 1e3, 1e6, 1e12, 1e30};

    bool
    is_csv(const std::string &path)
    {
      return fs::path(path).extension() == ".csv";
    }

    std::string
    format(const double x)
    {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", x);
      return buf;
    }

    std::string
    where(const std::string &file, const std::size_t line)
    {
      return file + ":" + std::to_string(line + 1);
    }

    /** Shown in descriptions: short, with control and non-ASCII bytes escaped. */
    std::string
    printable(const std::string &s)
    {
      std::string out;
      for (const unsigned char c : s.substr(0, 40))
        {
          if (c >= 32 && c < 127)
            out += static_cast<char>(c);
          else
            {
              char buf[8];
              std::snprintf(buf, sizeof buf, "\\x%02x", c);
              out += buf;
            }
        }
      return s.size() > 40 ? out + "...(" + std::to_string(s.size()) + " bytes)" : out;
    }

    /** Indices of the lines of kind @p kind. */
    std::vector<std::size_t>
    lines_of_kind(const std::vector<PrmLine> &lines, PrmLine::Kind kind)
    {
      std::vector<std::size_t> out;
      for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].kind == kind)
          out.push_back(i);
      return out;
    }

    /** Indices of lines that are not blank or comments. */
    std::vector<std::size_t>
    content_lines(const std::vector<PrmLine> &lines)
    {
      std::vector<std::size_t> out;
      for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].kind != PrmLine::Kind::blank && lines[i].kind != PrmLine::Kind::comment)
          out.push_back(i);
      return out;
    }

    /** Line indices i at which a new line can be inserted at the top level (before line i). */
    std::vector<std::size_t>
    top_level_positions(const std::vector<PrmLine> &lines)
    {
      std::vector<std::size_t> out{0};
      int                      depth = 0;
      for (std::size_t i = 0; i < lines.size(); ++i)
        {
          if (lines[i].kind == PrmLine::Kind::subsection)
            ++depth;
          else if (lines[i].kind == PrmLine::Kind::end)
            --depth;
          if (depth == 0)
            out.push_back(i + 1);
        }
      return out;
    }

    /** Where a subsection that starts at line @p begin ends (its `end` line), or lines.size(). */
    std::size_t
    block_end(const std::vector<PrmLine> &lines, const std::size_t begin)
    {
      int depth = 0;
      for (std::size_t i = begin; i < lines.size(); ++i)
        {
          if (lines[i].kind == PrmLine::Kind::subsection)
            ++depth;
          else if (lines[i].kind == PrmLine::Kind::end && --depth == 0)
            return i;
        }
      return lines.size();
    }

    class Mutator
    {
    public:
      Mutator(Tree &tree, Random &random)
        : tree(tree)
        , random(random)
      {
      }

      /** One mutation of @p file; returns its description. */
      std::string
      apply(const std::string &file, const std::vector<std::string> &files)
      {
        using Op = std::string (Mutator::*)(const std::string &, const std::vector<std::string> &);
        struct Choice
        {
          double weight;
          Op     op;
          bool   csv; ///< also applies to a profile CSV
        };
        // Value replacements weigh most (every reader and check of every entry); include
        // cycles little, since every one of them fails the same way until the include
        // reader detects them (about 8 % of all mutants at weight 6).
        static const std::vector<Choice> choices = {
          {12, &Mutator::delete_line, true},
          {8, &Mutator::duplicate, true},
          {26, &Mutator::replace_value, true},
          {10, &Mutator::scale_value, false},
          {4, &Mutator::rename_entry, false},
          {2, &Mutator::cyclic_include, false},
          {4, &Mutator::bad_include, false},
          {8, &Mutator::truncate, true},
          {6, &Mutator::garbage, true},
          {3, &Mutator::bom, true},
          {2, &Mutator::crlf, true},
          {6, &Mutator::break_structure, false},
          {2, &Mutator::long_value, false},
        };
        double total = 0;
        for (const auto &c : choices)
          if (c.csv || !is_csv(file))
            total += c.weight;
        double x = random.uniform(0, total);
        for (const auto &c : choices)
          if (c.csv || !is_csv(file))
            {
              if (x < c.weight)
                return (this->*c.op)(file, files);
              x -= c.weight;
            }
        return truncate(file, files);
      }

    private:
      Tree   &tree;
      Random &random;

      std::string
      delete_line(const std::string &file, const std::vector<std::string> &)
      {
        auto       lines   = split_lines(tree[file]);
        const auto content = content_lines(classify(lines));
        if (content.empty())
          return truncate(file, {});
        const auto i = random.pick(content);
        const auto d = "delete line '" + printable(lines[i]) + "' at " + where(file, i);
        lines.erase(lines.begin() + i);
        tree[file] = join_lines(lines);
        return d;
      }

      std::string
      duplicate(const std::string &file, const std::vector<std::string> &)
      {
        auto       lines = split_lines(tree[file]);
        const auto kinds = classify(lines);
        const auto subs  = lines_of_kind(kinds, PrmLine::Kind::subsection);
        if (!is_csv(file) && !subs.empty() && random.chance(0.3))
          {
            // A whole subsection twice, right after itself.
            const auto               b = random.pick(subs);
            const auto               e = std::min(block_end(kinds, b), lines.size() - 1);
            std::vector<std::string> block(lines.begin() + b, lines.begin() + e + 1);
            lines.insert(lines.begin() + e + 1, block.begin(), block.end());
            tree[file] = join_lines(lines);
            return "duplicate the block '" + printable(lines[b]) + "' (" + std::to_string(block.size()) +
                   " lines) at " + where(file, b);
          }
        const auto content = content_lines(kinds);
        if (content.empty())
          return truncate(file, {});
        const auto i = random.pick(content);
        lines.insert(lines.begin() + i + 1, lines[i]);
        tree[file] = join_lines(lines);
        return "duplicate line '" + printable(lines[i]) + "' at " + where(file, i);
      }

      std::string
      replace_value(const std::string &file, const std::vector<std::string> &files)
      {
        auto lines = split_lines(tree[file]);
        if (is_csv(file))
          {
            // One field of a data row.
            if (lines.size() < 2)
              return truncate(file, files);
            const auto  i     = 1 + random.below(lines.size() - 1);
            std::string value = random.pick(extreme_values);
            auto       &line  = lines[i];
            const auto  comma = line.find(',');
            const bool  first = comma == std::string::npos || random.chance(0.5);
            const auto  old   = line;
            line              = first ? value + (comma == std::string::npos ? "" : line.substr(comma)) :
                                        line.substr(0, comma + 1) + value;
            tree[file]        = join_lines(lines);
            return "replace row '" + printable(old) + "' by '" + printable(line) + "' at " + where(file, i);
          }
        const auto kinds = classify(lines);
        const auto sets  = lines_of_kind(kinds, PrmLine::Kind::set);
        if (sets.empty())
          return delete_line(file, files);
        const auto     i     = random.pick(sets);
        const PrmLine &l     = kinds[i];
        std::string    value = random.pick(extreme_values);
        std::string    full  = value;
        if (l.value.find(',') != std::string::npos && random.chance(0.5))
          {
            // One item of a list ("0.45, 0", "crank1, rod2, ...").
            std::vector<std::string> items;
            std::size_t              start = 0;
            for (;;)
              {
                const auto c = l.value.find(',', start);
                items.push_back(l.value.substr(start, c == std::string::npos ? std::string::npos : c - start));
                if (c == std::string::npos)
                  break;
                start = c + 1;
              }
            items[random.below(items.size())] = " " + value;
            full.clear();
            for (std::size_t k = 0; k < items.size(); ++k)
              full += (k == 0 ? "" : ",") + items[k];
          }
        lines[i]   = lines[i].substr(0, l.value_begin) + full + lines[i].substr(l.value_end);
        tree[file] = join_lines(lines);
        return "set '" + l.path + "' from '" + printable(l.value) + "' to '" + printable(full) + "' at " +
               where(file, i);
      }

      std::string
      scale_value(const std::string &file, const std::vector<std::string> &files)
      {
        auto                     lines = split_lines(tree[file]);
        const auto               kinds = classify(lines);
        std::vector<std::size_t> numeric;
        for (const auto i : lines_of_kind(kinds, PrmLine::Kind::set))
          {
            char *end = nullptr;
            std::strtod(kinds[i].value.c_str(), &end);
            if (end != kinds[i].value.c_str() && std::string(end).find_first_not_of(" ") == std::string::npos)
              numeric.push_back(i);
          }
        if (numeric.empty())
          return replace_value(file, files);
        const auto     i      = random.pick(numeric);
        const PrmLine &l      = kinds[i];
        const double   factor = random.pick(scale_factors);
        const auto     value  = format(std::strtod(l.value.c_str(), nullptr) * factor);
        lines[i]              = lines[i].substr(0, l.value_begin) + value + lines[i].substr(l.value_end);
        tree[file]            = join_lines(lines);
        return "scale '" + l.path + "' by " + format(factor) + " ('" + l.value + "' -> '" + value + "') at " +
               where(file, i);
      }

      std::string
      rename_entry(const std::string &file, const std::vector<std::string> &files)
      {
        auto       lines = split_lines(tree[file]);
        const auto sets  = lines_of_kind(classify(lines), PrmLine::Kind::set);
        if (sets.empty())
          return delete_line(file, files);
        const auto i     = random.pick(sets);
        const auto old   = lines[i];
        auto      &line  = lines[i];
        const auto name  = line.find("set") + 4;
        const auto eq    = line.find('=');
        const auto which = random.below(3);
        if (which == 0 && eq > name + 1)
          line.erase(name + random.below(eq - name - 1), 1); // drop a character
        else if (which == 1)
          line[name] =
            static_cast<char>(std::islower(line[name]) ? std::toupper(line[name]) : std::tolower(line[name]));
        else
          line.insert(eq, "x ");
        tree[file] = join_lines(lines);
        return "rename '" + printable(old) + "' to '" + printable(line) + "' at " + where(file, i);
      }

      std::string
      cyclic_include(const std::string &file, const std::vector<std::string> &files)
      {
        auto lines = split_lines(tree[file]);
        // Two files including each other: the file and one it includes, or the file
        // and the one that includes it; otherwise the file includes itself.
        std::vector<std::pair<std::string, std::string>> pairs; // (includer, included)
        for (const auto &f : files)
          if (!is_csv(f))
            for (const auto &l : classify(split_lines(tree[f])))
              if (l.kind == PrmLine::Kind::include)
                {
                  const auto inc = (fs::path(f).parent_path() / l.value).lexically_normal().generic_string();
                  if (tree.count(inc) != 0 && (f == file || inc == file))
                    pairs.emplace_back(f, inc);
                }
        if (!pairs.empty() && random.chance(0.6))
          {
            const auto [includer, included] = random.pick(pairs);
            auto       back                 = split_lines(tree[included]);
            const auto at                   = random.pick(top_level_positions(classify(back)));
            back.insert(back.begin() + at, "include " + relative_to(includer, included));
            tree[included] = join_lines(back);
            return "cycle: " + included + " includes " + includer + " back (line " + std::to_string(at + 1) + ")";
          }
        const auto at = random.pick(top_level_positions(classify(lines)));
        lines.insert(lines.begin() + at, "include " + fs::path(file).filename().string());
        tree[file] = join_lines(lines);
        return "cycle: " + file + " includes itself at line " + std::to_string(at + 1);
      }

      std::string
      bad_include(const std::string &file, const std::vector<std::string> &)
      {
        auto                           lines    = split_lines(tree[file]);
        const auto                     includes = lines_of_kind(classify(lines), PrmLine::Kind::include);
        const std::vector<std::string> targets =
          {"does_not_exist.prm", "", ".", "..", "/dev/null", "/", "../meshes/worn/nine_bar_A_bore.csv", "include"};
        const std::string target = random.pick(targets);
        if (!includes.empty() && random.chance(0.7))
          {
            const auto i   = random.pick(includes);
            const auto old = lines[i];
            lines[i]       = "include " + target;
            tree[file]     = join_lines(lines);
            return "include '" + printable(old) + "' -> 'include " + target + "' at " + where(file, i);
          }
        const auto at = random.pick(top_level_positions(classify(lines)));
        lines.insert(lines.begin() + at, "include " + target);
        tree[file] = join_lines(lines);
        return "add 'include " + target + "' at line " + std::to_string(at + 1) + " of " + file;
      }

      std::string
      truncate(const std::string &file, const std::vector<std::string> &)
      {
        auto      &text = tree[file];
        const auto size = text.size();
        const auto at   = random.chance(0.05) ? 0 : random.below(size + 1);
        text.resize(at);
        return "truncate " + file + " at byte " + std::to_string(at) + " of " + std::to_string(size);
      }

      std::string
      garbage(const std::string &file, const std::vector<std::string> &)
      {
        static const std::string special("\0\xff\xfe\r\t\\#=\v\x80\xc3\x1b", 12);
        auto                    &text = tree[file];
        std::string              bytes;
        const auto               n = 1 + random.below(16);
        for (std::size_t k = 0; k < n; ++k)
          bytes += random.chance(0.5) ? special[random.below(special.size())] : static_cast<char>(random.below(256));
        const auto at = random.below(text.size() + 1);
        text.insert(at, bytes);
        return "insert " + std::to_string(n) + " bytes '" + printable(bytes) + "' at byte " + std::to_string(at) +
               " of " + file;
      }

      std::string
      bom(const std::string &file, const std::vector<std::string> &)
      {
        tree[file].insert(0, "\xef\xbb\xbf");
        return "UTF-8 byte-order mark at the start of " + file;
      }

      std::string
      crlf(const std::string &file, const std::vector<std::string> &)
      {
        std::string out;
        for (const char c : tree[file])
          out += c == '\n' ? std::string("\r\n") : std::string(1, c);
        tree[file] = out;
        return "CRLF line ends in " + file;
      }

      std::string
      break_structure(const std::string &file, const std::vector<std::string> &files)
      {
        auto       lines = split_lines(tree[file]);
        const auto kinds = classify(lines);
        const auto ends  = lines_of_kind(kinds, PrmLine::Kind::end);
        const auto subs  = lines_of_kind(kinds, PrmLine::Kind::subsection);
        const auto which = random.below(4);
        if (which == 0 && !ends.empty())
          {
            const auto i = random.pick(ends);
            lines.erase(lines.begin() + i);
            tree[file] = join_lines(lines);
            return "delete the 'end' at " + where(file, i);
          }
        if (which == 1 && !ends.empty())
          {
            // Swap an `end` with the next content line (a set or a subsection moves out).
            const auto i = random.pick(ends);
            auto       j = i + 1;
            while (j < lines.size() &&
                   (kinds[j].kind == PrmLine::Kind::blank || kinds[j].kind == PrmLine::Kind::comment))
              ++j;
            if (j < lines.size())
              {
                std::swap(lines[i], lines[j]);
                tree[file] = join_lines(lines);
                return "swap the 'end' at " + where(file, i) + " with '" + printable(lines[i]) + "' (line " +
                       std::to_string(j + 1) + ")";
              }
          }
        if (which == 2 && !subs.empty())
          {
            const auto i   = random.pick(subs);
            const auto old = lines[i];
            lines[i]       = random.chance(0.5) ? "subsection" : old + " 2";
            tree[file]     = join_lines(lines);
            return "subsection '" + printable(old) + "' -> '" + printable(lines[i]) + "' at " + where(file, i);
          }
        const auto at = random.below(lines.size() + 1);
        lines.insert(lines.begin() + at, "end");
        tree[file] = join_lines(lines);
        (void)files;
        return "an extra 'end' at line " + std::to_string(at + 1) + " of " + file;
      }

      std::string
      long_value(const std::string &file, const std::vector<std::string> &files)
      {
        auto       lines = split_lines(tree[file]);
        const auto kinds = classify(lines);
        const auto sets  = lines_of_kind(kinds, PrmLine::Kind::set);
        if (sets.empty())
          return delete_line(file, files);
        const auto     i = random.pick(sets);
        const PrmLine &l = kinds[i];
        const auto     v = std::string(100000, random.chance(0.5) ? '9' : 'x');
        lines[i]         = lines[i].substr(0, l.value_begin) + v + lines[i].substr(l.value_end);
        tree[file]       = join_lines(lines);
        return "set '" + l.path + "' to a value of " + std::to_string(v.size()) + " '" + v.substr(0, 1) +
               "' characters at " + where(file, i);
      }
    };
  } // namespace

  Mutant
  mutate(const Tree &base, const BaseScene &scene, Random &random)
  {
    Mutant     m{base, {}};
    const auto files = closure(base, scene.file);
    const auto n     = random.chance(0.7) ? 1 : random.chance(0.67) ? 2 : 3;
    Mutator    mutator(m.tree, random);
    for (int k = 0; k < n; ++k)
      {
        // Half the mutations hit the scene itself, the others what it includes or reads.
        const std::string file =
          files.size() == 1 || random.chance(0.5) ? files.front() : files[1 + random.below(files.size() - 1)];
        m.mutations.push_back(mutator.apply(file, files));
      }
    return m;
  }
} // namespace wearlink::fuzz
