// SPDX-License-Identifier: LGPL-2.1-or-later
// Scene files as text, the shipped scenes and how to shorten them, the process runner
// and the checks on a run's outputs (see fuzz.h).
#include "fuzz.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace wearlink::fuzz
{
  namespace fs = std::filesystem;

  bool
  is_documented_exit_status(const int status)
  {
    return std::find(documented_exit_statuses.begin(), documented_exit_statuses.end(), status) !=
           documented_exit_statuses.end();
  }

  // ---- randomness -------------------------------------------------------------------

  Random::Random(const std::uint64_t seed, const std::uint64_t stream, const std::uint64_t index)
  {
    std::seed_seq seq{static_cast<std::uint32_t>(seed),
                      static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(stream),
                      static_cast<std::uint32_t>(index),
                      static_cast<std::uint32_t>(index >> 32)};
    engine.seed(seq);
  }

  double
  Random::uniform()
  {
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
  }

  double
  Random::uniform(const double lo, const double hi)
  {
    return lo + (hi - lo) * uniform();
  }

  double
  Random::log_uniform(const double lo, const double hi)
  {
    return std::exp(uniform(std::log(lo), std::log(hi)));
  }

  std::size_t
  Random::below(const std::size_t n)
  {
    return static_cast<std::size_t>(engine() % n);
  }

  bool
  Random::chance(const double p)
  {
    return uniform() < p;
  }

  // ---- scene files ------------------------------------------------------------------

  namespace
  {
    std::string
    read_file(const fs::path &p)
    {
      std::ifstream in(p, std::ios::binary);
      if (!in)
        throw std::runtime_error("cannot read " + p.string());
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }

    std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r");
      if (b == std::string::npos)
        return "";
      const auto e = s.find_last_not_of(" \t\r");
      return s.substr(b, e - b + 1);
    }

    bool
    starts_with_word(const std::string &s, const std::string &word)
    {
      return s.compare(0, word.size(), word) == 0 &&
             (s.size() == word.size() || s[word.size()] == ' ' || s[word.size()] == '\t');
    }

    std::vector<std::string>
    split_list(const std::string &s)
    {
      std::vector<std::string> out;
      std::stringstream        in(s);
      std::string              item;
      while (std::getline(in, item, ','))
        if (!trim(item).empty())
          out.push_back(trim(item));
      return out;
    }

    std::string
    number(const double x)
    {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.6g", x);
      return buf;
    }

    double
    number_or(const std::map<std::string, std::string> &flat, const std::string &key, const double fallback)
    {
      const auto it = flat.find(key);
      if (it == flat.end())
        return fallback;
      char        *end = nullptr;
      const double v   = std::strtod(it->second.c_str(), &end);
      return end == it->second.c_str() ? fallback : v;
    }

    std::string
    value_or(const std::map<std::string, std::string> &flat, const std::string &key)
    {
      const auto it = flat.find(key);
      return it == flat.end() ? std::string() : it->second;
    }

    bool
    is_prm(const std::string &path)
    {
      return path.size() > 4 && path.compare(path.size() - 4, 4, ".prm") == 0;
    }
  } // namespace

  Tree
  read_tree(const std::string &source_dir)
  {
    Tree           tree;
    const fs::path root(source_dir);
    for (const auto &e : fs::recursive_directory_iterator(root / "params"))
      if (e.is_regular_file() && e.path().extension() == ".prm")
        tree[e.path().lexically_relative(root).generic_string()] = read_file(e.path());
    if (fs::exists(root / "meshes" / "worn"))
      for (const auto &e : fs::directory_iterator(root / "meshes" / "worn"))
        if (e.is_regular_file() && e.path().extension() == ".csv")
          tree[e.path().lexically_relative(root).generic_string()] = read_file(e.path());
    if (tree.empty())
      throw std::runtime_error("no scenes under " + (root / "params").string());
    return tree;
  }

  void
  write_tree(const Tree &tree, const std::string &dir)
  {
    for (const auto &[path, text] : tree)
      {
        const fs::path p = fs::path(dir) / path;
        fs::create_directories(p.parent_path());
        std::ofstream out(p, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out)
          throw std::runtime_error("cannot write " + p.string());
      }
  }

  std::vector<std::string>
  split_lines(const std::string &text)
  {
    std::vector<std::string> lines;
    std::size_t              start = 0;
    while (start < text.size())
      {
        const auto nl = text.find('\n', start);
        if (nl == std::string::npos)
          {
            lines.push_back(text.substr(start));
            break;
          }
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
      }
    return lines;
  }

  std::string
  join_lines(const std::vector<std::string> &lines)
  {
    std::string text;
    for (const auto &l : lines)
      text += l + '\n';
    return text;
  }

  std::vector<PrmLine>
  classify(const std::vector<std::string> &lines)
  {
    std::vector<PrmLine>     out;
    std::vector<std::string> sections;
    for (const auto &line : lines)
      {
        PrmLine     l;
        const auto  hash = line.find('#');
        std::string body = trim(hash == std::string::npos ? line : line.substr(0, hash));
        if (trim(line).empty())
          l.kind = PrmLine::Kind::blank;
        else if (body.empty())
          l.kind = PrmLine::Kind::comment;
        else if (starts_with_word(body, "subsection"))
          {
            l.kind = PrmLine::Kind::subsection;
            sections.push_back(trim(body.substr(10)));
          }
        else if (body == "end")
          {
            l.kind = PrmLine::Kind::end;
            if (!sections.empty())
              sections.pop_back();
          }
        else if (starts_with_word(body, "include"))
          {
            l.kind  = PrmLine::Kind::include;
            l.value = trim(body.substr(7));
          }
        else if (starts_with_word(body, "set") && body.find('=') != std::string::npos)
          {
            l.kind          = PrmLine::Kind::set;
            const auto  eq  = line.find('=');
            const auto  end = hash == std::string::npos ? line.size() : hash;
            std::string p;
            for (const auto &s : sections)
              p += s + "/";
            l.path  = p + trim(body.substr(3, body.find('=') - 3));
            l.value = trim(line.substr(eq + 1, end - eq - 1));
            // The value's span in the line: after '=' and its blanks, up to the comment.
            l.value_begin = line.find_first_not_of(" \t", eq + 1);
            if (l.value_begin == std::string::npos || l.value_begin > end)
              l.value_begin = eq + 1;
            l.value_end = l.value_begin + l.value.size();
          }
        out.push_back(l);
      }
    return out;
  }

  std::string
  relative_to(const std::string &path, const std::string &from)
  {
    return fs::path(path).lexically_relative(fs::path(from).parent_path()).generic_string();
  }

  namespace
  {
    std::string
    resolve(const std::string &from, const std::string &relative)
    {
      return (fs::path(from).parent_path() / relative).lexically_normal().generic_string();
    }

    void
    collect(const Tree &tree, const std::string &file, std::vector<std::string> &out, unsigned depth)
    {
      if (depth > 16 || std::find(out.begin(), out.end(), file) != out.end() || tree.count(file) == 0)
        return;
      out.push_back(file);
      if (!is_prm(file))
        return;
      for (const auto &l : classify(split_lines(tree.at(file))))
        if (l.kind == PrmLine::Kind::include)
          collect(tree, resolve(file, l.value), out, depth + 1);
        else if (l.kind == PrmLine::Kind::set && l.path.size() > 12 &&
                 l.path.compare(l.path.size() - 12, 12, "profile file") == 0 && !l.value.empty())
          collect(tree, resolve(file, l.value), out, depth + 1);
    }

    void
    flatten_into(const Tree &tree, const std::string &file, std::map<std::string, std::string> &flat, unsigned depth)
    {
      if (depth > 16 || tree.count(file) == 0)
        return;
      for (const auto &l : classify(split_lines(tree.at(file))))
        if (l.kind == PrmLine::Kind::include)
          flatten_into(tree, resolve(file, l.value), flat, depth + 1);
        else if (l.kind == PrmLine::Kind::set)
          flat[l.path] = l.value;
    }
  } // namespace

  std::vector<std::string>
  closure(const Tree &tree, const std::string &scene)
  {
    std::vector<std::string> out;
    collect(tree, scene, out, 0);
    return out;
  }

  std::map<std::string, std::string>
  flatten(const Tree &tree, const std::string &scene)
  {
    std::map<std::string, std::string> flat;
    flatten_into(tree, scene, flat, 0);
    return flat;
  }

  // ---- shipped scenes ---------------------------------------------------------------

  std::vector<BaseScene>
  base_scenes(const Tree &tree)
  {
    std::vector<BaseScene> scenes;
    for (const auto &[path, text] : tree)
      {
        const fs::path p(path);
        if (p.parent_path() != "params" || p.extension() != ".prm")
          continue;
        BaseScene s;
        s.name          = p.stem().string();
        s.file          = path;
        const auto flat = flatten(tree, path);

        if (flat.count("FE model/Surface element size") != 0 || flat.count("Loads/Load magnitudes") != 0)
          {
            // A `wearlink contact` case: coarse elements, two loads, no VTU.
            s.command    = "contact";
            s.shortening = {"FE model/Surface element size=2e-4",
                            "FE model/Refined layer thickness=4e-4",
                            "Loads/Load magnitudes=100, 10000",
                            "Output/Write VTU=false"};
            scenes.push_back(s);
            continue;
          }

        s.command = "run";
        for (const auto &j : split_list(value_or(flat, "Mechanism/Joints")))
          if (value_or(flat, "Joint " + j + "/Model") == "clearance")
            {
              s.clearance_joints.push_back(j);
              const std::string c = "Joint " + j + "/Clearance/";
              const std::string w = value_or(flat, c + "Wear law");
              if (!w.empty() && w != "none")
                s.wear = true;
              if (value_or(flat, c + "Normal force law") == "fe" || value_or(flat, c + "Pressure model") == "fe")
                s.fe = true;
            }
        s.analyses = !value_or(flat, "Analyses/List of analyses").empty();

        // A few percent of a crank cycle: long enough for contact, short enough for
        // hundreds of runs (the nine-bar: 30 ms of a 0.5 s cycle; the slider-crank at
        // 5000 rpm: 6 ms of 12 ms). Analyses need a few hundred samples.
        const double end = number_or(flat, "Simulation/End time", 1.0);
        s.end_time       = s.analyses ? std::min(end, 0.5) : std::min(0.03, end / 8);
        s.shortening     = {"Simulation/End time=" + number(s.end_time)};
        if (s.wear)
          {
            s.shortening.insert(s.shortening.end(),
                                {"Wear/Number of iterations=1",
                                 "Wear/Cycles per iteration=1",
                                 "Wear/Response cycles=1",
                                 "Wear/Cycle period=" + number(std::min(0.03, end / 8)),
                                 "Wear/FE output=false"});
            if (value_or(flat, "Wear/Pressure evaluation") == "samples per cycle")
              s.shortening.push_back("Wear/Load samples per cycle=8");
          }
        if (s.fe)
          for (const auto &j : s.clearance_joints)
            {
              const std::string fe = "Joint " + j + "/Clearance/fe/";
              s.shortening.insert(s.shortening.end(),
                                  {fe + "Surface element size=2e-4",
                                   fe + "Refined layer thickness=4e-4",
                                   fe + "Table load levels=4",
                                   fe + "Table bore directions=2",
                                   fe + "Table pin directions=2"});
            }
        if (s.analyses)
          s.shortening.insert(s.shortening.end(),
                              {"Analyses/Transient=0",
                               "Analyses/Lyapunov/Embedding dimension=3",
                               "Analyses/Lyapunov/Delay=2",
                               "Analyses/Before-after wear/Two-trajectory cycles=1",
                               "Analyses/Before-after wear/Two-trajectory tolerance=1e-6",
                               "Analyses/Before-after wear/Delay scan=",
                               "Analyses/Before-after wear/Embedding dimension=3",
                               "Analyses/Before-after wear/Delay=0.002"});
        // Even shortened, a run with analyses takes seconds and one with FE tables
        // about one: most of their mutants are only validated.
        s.validate_fraction = s.analyses ? 0.9 : s.fe ? 0.5 : 0.2;
        scenes.push_back(s);
      }
    return scenes;
  }

  // ---- running wearlink -------------------------------------------------------------

  std::string
  Outcome::status_text(const double timeout_s) const
  {
    if (timed_out)
      return "timeout after " + number(timeout_s) + " s";
    if (!exited)
      return "signal " + std::to_string(signal) + " (" + ::strsignal(signal) + ")";
    return "exit " + std::to_string(exit_status);
  }

  Outcome
  run_program(const std::vector<std::string>                         &argv,
              const std::string                                      &cwd,
              const std::vector<std::pair<std::string, std::string>> &environment,
              const std::string                                      &log_file,
              const Limits                                           &limits)
  {
    // Everything the child needs is prepared before fork().
    std::vector<char *> c_argv;
    for (const auto &a : argv)
      c_argv.push_back(const_cast<char *>(a.c_str()));
    c_argv.push_back(nullptr);

    const auto  start = std::chrono::steady_clock::now();
    const pid_t pid   = ::fork();
    if (pid < 0)
      throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0)
      {
        ::setpgid(0, 0);
        const int in  = ::open("/dev/null", O_RDONLY);
        const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || log < 0 || ::chdir(cwd.c_str()) != 0)
          ::_exit(126);
        ::dup2(in, 0);
        ::dup2(log, 1);
        ::dup2(log, 2);
        const rlimit as{limits.address_space, limits.address_space};
        const rlimit fsize{limits.file_size, limits.file_size};
        const rlimit core{0, 0};
        ::setrlimit(RLIMIT_AS, &as);
        ::setrlimit(RLIMIT_FSIZE, &fsize);
        ::setrlimit(RLIMIT_CORE, &core);
        for (const auto &[name, value] : environment)
          ::setenv(name.c_str(), value.c_str(), 1);
        ::execv(c_argv[0], c_argv.data());
        ::_exit(127);
      }
    ::setpgid(pid, pid); // also here: whichever of parent and child runs first

    Outcome o;
    int     status = 0;
    for (;;)
      {
        const pid_t r = ::waitpid(pid, &status, WNOHANG);
        if (r == pid)
          break;
        if (r < 0 && errno != EINTR)
          throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (limits.stop_signal != 0 && !o.stopped && elapsed > limits.stop_after_s)
          {
            ::kill(pid, limits.stop_signal);
            o.stopped = true;
          }
        if (elapsed > limits.timeout_s)
          {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            o.timed_out = true;
            break;
          }
        std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 1 ? 2 : 20));
      }
    o.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!o.timed_out)
      {
        o.exited = WIFEXITED(status);
        if (o.exited)
          o.exit_status = WEXITSTATUS(status);
        else if (WIFSIGNALED(status))
          o.signal = WTERMSIG(status);
      }
    if (o.exited && (o.exit_status == 126 || o.exit_status == 127))
      throw std::runtime_error("cannot start " + argv[0] + " in " + cwd + " (exit " + std::to_string(o.exit_status) +
                               ")");
    try
      {
        o.output = read_file(log_file);
      }
    catch (const std::exception &)
      {
      }
    return o;
  }

  std::string
  shell_command(const std::vector<std::string> &args)
  {
    std::string cmd;
    for (const auto &a : args)
      {
        const bool  plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                              "0123456789_-./=:,+") == std::string::npos;
        std::string q     = "'";
        for (const char c : a)
          q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        cmd += (cmd.empty() ? "" : " ") + (plain ? a : q + "'");
      }
    return cmd;
  }

  // ---- checks -----------------------------------------------------------------------

  std::vector<std::string>
  non_finite_numbers(const nlohmann::json &j, const std::string &at)
  {
    std::vector<std::string> out;
    if (j.is_null())
      out.push_back(at + " = null (how a NaN or inf is written)");
    else if (j.is_number_float() && !std::isfinite(j.get<double>()))
      out.push_back(at + " = " + std::to_string(j.get<double>()));
    else if (j.is_object())
      for (const auto &[key, value] : j.items())
        {
          const auto sub = non_finite_numbers(value, at + "/" + key);
          out.insert(out.end(), sub.begin(), sub.end());
        }
    else if (j.is_array())
      for (std::size_t i = 0; i < j.size(); ++i)
        {
          const auto sub = non_finite_numbers(j[i], at + "/" + std::to_string(i));
          out.insert(out.end(), sub.begin(), sub.end());
        }
    return out;
  }

  std::string
  first_non_finite_csv_value(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line, header;
    std::getline(in, header);
    const auto  columns = split_list(header);
    std::size_t row     = 1;
    while (std::getline(in, line))
      {
        ++row;
        std::size_t col   = 0;
        std::size_t start = 0;
        while (start <= line.size())
          {
            auto comma = line.find(',', start);
            if (comma == std::string::npos)
              comma = line.size();
            const std::string field = trim(line.substr(start, comma - start));
            char             *end   = nullptr;
            const double      v     = std::strtod(field.c_str(), &end);
            if (!field.empty() && end != field.c_str() && !std::isfinite(v))
              return "row " + std::to_string(row) + ", column " +
                     (col < columns.size() ? columns[col] : std::to_string(col + 1)) + " = " + field;
            start = comma + 1;
            ++col;
          }
      }
    return "";
  }

  std::vector<std::string>
  partial_files(const std::string &dir)
  {
    std::vector<std::string> out;
    std::error_code          ec;
    if (!fs::exists(dir, ec))
      return out;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (it->path().filename().string().find(".partial") != std::string::npos)
        out.push_back(it->path().string());
    return out;
  }

  std::vector<std::string>
  check_run(const Outcome     &outcome,
            const std::string &output_dir,
            const bool         expect_summary,
            const double       timeout_s,
            nlohmann::json    &summary)
  {
    std::vector<std::string> problems;
    const fs::path           summary_file = fs::path(output_dir) / "summary.json";
    summary                               = nlohmann::json();

    if (outcome.timed_out || !outcome.exited)
      problems.push_back(outcome.status_text(timeout_s));
    else if (outcome.exit_status == 1)
      problems.push_back("exit status 1 (an internal error)");
    else if (!is_documented_exit_status(outcome.exit_status))
      problems.push_back("exit status " + std::to_string(outcome.exit_status) + " is not a documented one");

    if (outcome.exited && outcome.exit_status == 0)
      {
        if (expect_summary)
          {
            if (!fs::exists(summary_file))
              problems.push_back("exit 0 but no summary.json");
            else
              try
                {
                  summary          = nlohmann::json::parse(read_file(summary_file));
                  const auto bad   = non_finite_numbers(summary);
                  const auto shown = std::min<std::size_t>(bad.size(), 5);
                  for (std::size_t i = 0; i < shown; ++i)
                    problems.push_back("summary.json: " + bad[i]);
                  if (bad.size() > shown)
                    problems.push_back("summary.json: " + std::to_string(bad.size() - shown) +
                                       " more non-finite numbers");
                }
              catch (const std::exception &e)
                {
                  problems.push_back(std::string("summary.json does not parse: ") + e.what());
                }
          }
        // Every table the run wrote (time series, wear history, responses, analyses).
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(output_dir, ec);
             !ec && it != fs::recursive_directory_iterator();
             it.increment(ec))
          if (it->is_regular_file() && it->path().extension() == ".csv")
            {
              const auto bad = first_non_finite_csv_value(it->path().string());
              if (!bad.empty())
                problems.push_back(it->path().lexically_relative(output_dir).string() + ": " + bad);
            }
      }
    else if (outcome.exited)
      {
        if (fs::exists(summary_file))
          problems.push_back("a failed run (" + outcome.status_text(timeout_s) + ") left summary.json behind");
        if (trim(outcome.output).empty())
          problems.push_back("a failed run (" + outcome.status_text(timeout_s) + ") printed no message");
      }
    if (outcome.exited)
      for (const auto &p : partial_files(output_dir))
        problems.push_back("partial file left behind: " + fs::path(p).lexically_relative(output_dir).string());
    return problems;
  }

  std::string
  tail_lines(const std::string &text, const std::size_t n)
  {
    std::vector<std::string> lines;
    for (const auto &l : split_lines(text))
      if (!trim(l).empty())
        lines.push_back(l.size() > 300 ? l.substr(0, 300) + " ..." : l);
    std::string out;
    for (std::size_t i = lines.size() > n ? lines.size() - n : 0; i < lines.size(); ++i)
      out += "      | " + lines[i] + "\n";
    return out;
  }
} // namespace wearlink::fuzz
