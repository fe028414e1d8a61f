// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink study accuracy` on the nine-bar wear scene (params/nine_bar_wear.prm),
// shortened to fractions of a cycle so that the whole file runs in about 10 s:
//  - Convergence: dopri5 controls the local error, so the peak contact force of each
//    clearance joint — reached at the first hard impacts, before the trajectories of
//    different tolerances part (doc/running.md, "Which integrator") — approaches the 1e-8
//    reference as the tolerance tightens. Measured over a quarter cycle, the error
//    falls 4–300× per decade of tolerance (1e-3 … 1e-6); we ask at least 2× per decade,
//    so a tolerance that stops reaching the integrator (or an error measured against
//    the wrong run) fails.
//  - The quick study varies exactly the knobs of the scene's active effects (no FE
//    knobs for a hertz-strip scene), times every run (positive, finite), marks one
//    reference per knob (its last, finest value), and the coarse wear step — 1
//    iteration instead of 4 of the same simulated length — costs less wall time than
//    its reference.
//  - Input errors (unknown knob, a knob the scene does not use, a malformed study file)
//    exit with status 2 before any run and write nothing.
#include "io/csv.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace wearlink;
using namespace wearlink::testing;

namespace
{
  using Row = std::map<std::string, std::string>;

  /** accuracy.csv as rows of column → text (read by io/csv.h; quoted fields may hold commas). */
  std::vector<Row>
  read_csv(const std::string &path)
  {
    const io::CsvTable table = io::CsvTable::read(path, "accuracy table");
    EXPECT_NO_THROW(table.require_rectangular()) << path;
    std::vector<Row> rows;
    for (std::size_t r = 0; r < table.n_rows(); ++r)
      {
        Row row;
        for (std::size_t c = 0; c < table.columns().size(); ++c)
          row[table.columns()[c]] = table.field(r, c);
        rows.push_back(row);
      }
    return rows;
  }

  double
  number(const Row &r, const std::string &column)
  {
    const auto it = r.find(column);
    if (it == r.end())
      {
        ADD_FAILURE() << "no column '" << column << "'";
        return std::nan("");
      }
    return std::strtod(it->second.c_str(), nullptr);
  }

  std::string
  write_study_file(const std::string &dir, const std::string &text)
  {
    const std::string path = dir + "/study.prm";
    std::ofstream(path) << text;
    return path;
  }
} // namespace

TEST(StudyAccuracy, IntegratorToleranceConvergesOnThePeakContactForce)
{
  const std::string dir   = fresh_directory("study_tolerance");
  const std::string study = write_study_file(dir,
                                             "subsection Accuracy study\n"
                                             "  set Knobs = integrator-tolerance\n"
                                             "  subsection integrator-tolerance\n"
                                             "    set Values = 1e-3;1e-6;1e-3, 1e-4;1e-7;1e-4, 1e-5;1e-8;1e-5, "
                                             "1e-6;1e-9;1e-6, 1e-8;1e-11;1e-8\n"
                                             "  end\n"
                                             "end\n");
  const auto        r     = run_wearlink({"study",
                                          "accuracy",
                                          source_path("params/nine_bar_wear.prm"),
                                          "--study",
                                          study,
                                          "--set",
                                          "Wear/Cycles per iteration=0.25",
                                          "--set",
                                          "Wear/Settling cycles=0",
                                          "--set",
                                          "Wear/Number of iterations=1",
                                          "--output",
                                          dir + "/out",
                                          "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto rows = read_csv(dir + "/out/accuracy.csv");
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows.back().at("is_reference"), "1");
  for (const std::string joint : {"A", "B"})
    for (std::size_t i = 1; i + 1 < rows.size(); ++i)
      {
        const double coarse = number(rows[i - 1], joint + " F_peak error");
        const double fine   = number(rows[i], joint + " F_peak error");
        EXPECT_TRUE(std::isfinite(coarse) && std::isfinite(fine));
        // At least 2× smaller per decade of tolerance (measured: 4–300×).
        EXPECT_LT(fine, 0.5 * coarse) << "joint " << joint << ": peak-force error " << fine << " at "
                                      << rows[i].at("value") << " vs " << coarse << " at " << rows[i - 1].at("value");
      }
}

TEST(StudyAccuracy, QuickStudyVariesTheActiveKnobsAndTimesEveryRun)
{
  const std::string dir = fresh_directory("study_quick");
  const auto        r   = run_wearlink({"study",
                                        "accuracy",
                                        source_path("params/nine_bar_wear.prm"),
                                        "--quick",
                                        "--set",
                                        "Wear/Cycles per iteration=0.5",
                                        "--output",
                                        dir,
                                        "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto rows = read_csv(dir + "/accuracy.csv");
  // 6 knobs × 3 values in quick mode.
  EXPECT_GE(rows.size(), 18u);
  std::map<std::string, std::vector<Row>> by_knob;
  for (const auto &row : rows)
    {
      by_knob[row.at("knob")].push_back(row);
      EXPECT_EQ(row.at("status"), "ok") << row.at("knob") << " = " << row.at("value");
      const double t = number(row, "wall_time_s");
      EXPECT_TRUE(std::isfinite(t) && t > 0) << row.at("knob") << " = " << row.at("value") << ": " << t;
    }
  const std::set<std::string> expected =
    {"integrator-tolerance", "contact-law", "discrete-areas", "load-sampling", "wear-step", "simulated-cycles"};
  std::set<std::string> got;
  for (const auto &[k, v] : by_knob)
    got.insert(k);
  EXPECT_EQ(got, expected)
    << "hertz-strip scene: no fe knobs; quick: no pressure-model, wear-update, smoothing, baumgarte";
  for (const auto &[knob, rs] : by_knob)
    {
      ASSERT_GE(rs.size(), 2u) << knob;
      for (std::size_t i = 0; i < rs.size(); ++i)
        EXPECT_EQ(rs[i].at("is_reference"), i + 1 == rs.size() ? "1" : "0") << knob;
      for (std::size_t i = 0; i + 1 < rs.size(); ++i)
        EXPECT_TRUE(std::isfinite(number(rs[i], "worst_error"))) << knob << " = " << rs[i].at("value");
    }
  EXPECT_NE(by_knob["load-sampling"].back().at("value").find("every step"), std::string::npos);
  // Wear step: the same revolutions (iterations × extrapolation factor) in more, smaller
  // steps towards the reference — 1 × 2f, 2 × f, 4 × f/2 for the scene's 2 × f. (What
  // that costs in time is the benchmark's business, not a unit of the default suite.)
  const auto &wear_step = by_knob["wear-step"];
  auto        parts     = [](const Row &row) {
    const auto v    = row.at("value");
    const auto semi = v.find(';');
    return std::make_pair(std::stod(v.substr(0, semi)), std::stod(v.substr(semi + 1)));
  };
  const auto coarse = parts(wear_step.front()), fine = parts(wear_step.back());
  EXPECT_LT(coarse.first, fine.first) << "the reference has the most iterations";
  EXPECT_NEAR(coarse.first * coarse.second, fine.first * fine.second, 1e-6 * fine.first * fine.second)
    << "every wear-step value represents the same revolutions";
  // Rows at the scene's own settings are one run, measured once: the discrete-areas
  // reference (the quick scene's 360 areas) and the wear step 2 × f (its 2 iterations).
  const auto &scene_areas = by_knob["discrete-areas"].back();
  ASSERT_EQ(parts(wear_step[1]).first, 2.0) << "quick: the scene's 2 iterations";
  EXPECT_EQ(scene_areas.at("wall_time_s"), wear_step[1].at("wall_time_s"))
    << scene_areas.at("value") << " areas and " << wear_step[1].at("value") << " are the same scene";

  std::ifstream     md(dir + "/accuracy.md");
  std::stringstream text;
  text << md.rdbuf();
  std::size_t table_lines = 0;
  for (std::string line; std::getline(text, line);)
    table_lines += line.rfind("| ", 0) == 0 ? 1 : 0;
  EXPECT_EQ(table_lines, rows.size() + 1) << "header + one line per run";
  if (std::filesystem::exists("/usr/bin/gnuplot"))
    {
      EXPECT_GT(std::filesystem::file_size(dir + "/accuracy_pareto.png"), 1000u);
    }
}

TEST(StudyAccuracy, UnknownOrInapplicableKnobsAreInputErrorsAndWriteNothing)
{
  const std::string dir   = fresh_directory("study_invalid");
  const std::string scene = source_path("params/nine_bar_wear.prm");
  struct Case
  {
    std::string study_text, knobs, message;
  };
  const std::vector<Case> cases = {
    {"subsection Accuracy study\n  set Knobs = integrator-tolerance, mesh-size\nend\n",
     "",
     "'Accuracy study/Knobs' names 'mesh-size', which is not a knob; the knobs are integrator-tolerance"},
    {"subsection Accuracy study\n  subsection mesh-size\n    set Values = 1, 2\n  end\nend\n",
     "",
     "mesh-size[\\s\\S]*the knobs are integrator-tolerance"},
    {"subsection Accuracy study\n  subsection wear-step\n    set Values = 2, 4\n  end\nend\n",
     "",
     "needs 2 part\\(s\\) separated by ';'"},
    {"", "fe-degree", "'fe-degree' does not apply to .* the knobs of this scene are integrator-tolerance"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i)
    {
      const std::string        out  = dir + "/out" + std::to_string(i);
      std::vector<std::string> args = {"study", "accuracy", scene, "--output", out, "--quiet"};
      if (!cases[i].study_text.empty())
        {
          args.push_back("--study");
          args.push_back(write_study_file(dir, cases[i].study_text));
        }
      if (!cases[i].knobs.empty())
        {
          args.push_back("--knobs");
          args.push_back(cases[i].knobs);
        }
      const auto r = run_wearlink(args);
      EXPECT_EQ(r.exit_status, 2) << r.output;
      EXPECT_TRUE(std::regex_search(r.output, std::regex(cases[i].message))) << r.output;
      EXPECT_TRUE(files_in(out).empty()) << "case " << i;
    }
}

// A scene without wear: its knobs are the dynamics' alone (no discrete areas, load
// sampling, wear step, …), the table has no wear columns, and the errors it does have
// are finite for every non-reference row.
TEST(StudyAccuracy, SceneWithoutWearHasOnlyDynamicsKnobs)
{
  const std::string dir = fresh_directory("study_no_wear");
  const auto        r   = run_wearlink({"study",
                                        "accuracy",
                                        source_path("params/nine_bar_clearance.prm"),
                                        "--quick",
                                        "--set",
                                        "Simulation/End time=0.25",
                                        "--output",
                                        dir,
                                        "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto            rows = read_csv(dir + "/accuracy.csv");
  std::set<std::string> knobs;
  for (const auto &row : rows)
    {
      knobs.insert(row.at("knob"));
      EXPECT_EQ(row.count("A V_pin error"), 0u) << "no wear columns without a wear law";
      if (row.at("is_reference") == "0")
        {
          EXPECT_TRUE(std::isfinite(number(row, "A F_peak error")));
          EXPECT_TRUE(std::isfinite(number(row, "worst_error")));
        }
    }
  EXPECT_EQ(knobs, (std::set<std::string>{"integrator-tolerance", "contact-law"}));
  EXPECT_EQ(rows.size(), 6u);
}
