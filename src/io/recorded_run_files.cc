// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/recorded_run_files.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/csv.h"
#include "io/json_file.h"
#include "io/output_names.h"

#include <fstream>
#include <iomanip>
#include <sstream>

namespace wearlink::io
{
  void
  write_sampled_csv(const analysis::SampledChannels &s, const std::string &path, const bool with_index)
  {
    constexpr int digits = 12;
    std::string   csv    = with_index ? "section,time_s" : "time_s";
    for (const auto &n : s.names)
      csv += ',' + n;
    csv += '\n';
    for (std::size_t k = 0; k < s.n_samples(); ++k)
      {
        if (with_index)
          csv += std::to_string(k) + ',';
        append_number(csv, s.time[k], digits);
        for (const auto &v : s.values)
          {
            csv += ',';
            append_number(csv, v[k], digits);
          }
        csv += '\n';
      }
    write_file_atomically(path, csv);
  }

  namespace
  {
    /** The unit of a channel from its name's suffix (analysis/channels.h). */
    std::string
    unit_of(const std::string &name)
    {
      for (const auto &[suffix, unit] : std::vector<std::pair<std::string, std::string>>{{"_rad_s", "rad/s"},
                                                                                         {"_m_s", "m/s"},
                                                                                         {"_rad", "rad"},
                                                                                         {"_m", "m"}})
        if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
          return unit;
      return "";
    }

    /** A CSV written by write_sampled_csv(); @p skip leading columns before time_s. */
    analysis::SampledChannels
    read_sampled_csv(const std::string &path, const std::size_t skip)
    {
      const CsvTable table = CsvTable::read(path, "recorded run file");
      if (table.columns().size() < skip + 1 || table.columns()[skip] != "time_s")
        throw InputError("'" + path + "' is not a recorded series of wearlink (no time_s column).");
      table.require_rectangular();
      analysis::SampledChannels s;
      s.time = table.numbers(skip);
      for (std::size_t c = skip + 1; c < table.columns().size(); ++c)
        {
          s.names.push_back(table.columns()[c]);
          s.units.push_back(unit_of(table.columns()[c]));
          s.values.push_back(table.numbers(c));
        }
      return s;
    }
  } // namespace

  analysis::RecordedRun
  read_recorded_run(const std::string &output_directory, const std::string &label)
  {
    const std::string dir     = output_directory + "/";
    const Json        summary = io::read_json_file(dir + io::outputs::summary);
    if (!summary.contains("analyses"))
      throw InputError("The run in '" + output_directory +
                       "' recorded no analyses ('Analyses/List of analyses' was empty).");
    const Json           &a = summary.at("analyses");
    analysis::RecordedRun run;
    run.label = label;
    if (a.contains("driving_period_s"))
      run.driving_period = json_number(a.at("driving_period_s"));
    if (a.contains("series_sample_interval_s"))
      {
        run.sample_interval = json_number(a.at("series_sample_interval_s"));
        run.series          = read_sampled_csv(dir + "analysis_series.csv", 0);
      }
    if (a.contains("poincare"))
      {
        run.section.period     = json_number(a.at("poincare").at("period_s"));
        run.section.first_time = json_number(a.at("poincare").at("first_time_s"));
        run.section.points     = read_sampled_csv(dir + "poincare_section.csv", 1);
      }
    return run;
  }
} // namespace wearlink::io
