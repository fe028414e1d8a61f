// SPDX-License-Identifier: LGPL-2.1-or-later
// What an ensemble is asked for and where it goes (workflows/ensemble/ensemble.h): the
// request's checks, its help text, its folder's files and member folders, and the hold
// on that folder from rank 0.
#include "base/exceptions.h"
#include "base/text.h"
#include "io/output_names.h"
#include "workflows/ensemble/ensemble.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace wearlink::workflows
{
  EnsembleRequest
  ensemble_request(const double members, const double seed, const double perturbation, const bool saltelli)
  {
    EnsembleRequest r;
    if (!(members >= 2 && members <= 1000 && members == std::floor(members)))
      throw InputError("--ensemble " + format_number(members) +
                       ": the number of members must be a whole number from 2 to 1000 (a spread needs two).");
    r.members = static_cast<unsigned int>(members);
    if (!(seed >= 0 && seed <= 9007199254740992.0 && seed == std::floor(seed)))
      throw InputError("--seed " + format_number(seed) + ": the seed must be a whole number from 0 to 2^53.");
    r.seed = static_cast<std::uint64_t>(seed);
    if (!(perturbation > 0 && perturbation <= 1e-3))
      throw InputError("--perturbation " + format_number(perturbation) +
                       ": the initial-angle perturbation must be > 0 and at most 1e-3 rad (it is meant to be "
                       "physically tiny; default 1e-9 rad).");
    r.perturbation = perturbation;
    r.saltelli     = saltelli;
    return r;
  }

  std::unique_ptr<OutputDirectory>
  held_on_root(const std::function<std::unique_ptr<OutputDirectory>()> &hold)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
      return hold();
    // Rank 0's outcome for everyone: 0 held, 2 InputError, 4 IoError, and the message.
    std::pair<int, std::string>      outcome{0, ""};
    std::unique_ptr<OutputDirectory> held;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          held = hold();
        }
      catch (const InputError &e)
        {
          outcome = {2, e.message()};
        }
      catch (const IoError &e)
        {
          outcome = {4, e.message()};
        }
    outcome = dealii::Utilities::MPI::broadcast(comm, outcome, 0);
    if (outcome.first == 2)
      throw InputError(outcome.second);
    if (outcome.first == 4)
      throw IoError(outcome.second);
    return held;
  }

  RunFiles
  ensemble_files(const std::string &dir, const unsigned int members, const RunFiles &member_files)
  {
    RunFiles f = member_files;
    for (const auto &name : io::outputs::ensemble().patterns)
      f.patterns.push_back(name);
    for (unsigned int k = 0; k < members; ++k)
      f.subdirectories.push_back(member_directory_name(k, members));
    std::error_code ec;
    for (const auto &e : std::filesystem::directory_iterator(dir, ec))
      if (e.is_directory(ec) && e.path().filename().string().rfind("member_", 0) == 0)
        f.subdirectories.push_back(e.path().filename().string());
    return f;
  }

  std::string
  ensemble_help()
  {
    return R"(  --ensemble N        run N members (2 … 1000) whose initial conditions differ by a
                      physically tiny, seeded perturbation: member k shifts the initial
                      angle of every angle driver by σ z (z standard normal from the seed
                      and k; σ = --perturbation), each a complete run in DIR/member_<k>/.
                      With `mpirun -np R` the members are spread over R ranks (member k on
                      rank k mod R); the results do not depend on R. DIR/summary.json holds
                      ensemble.<figure>.{mean,std,ci95_low,ci95_high,members} (95 %
                      interval of the mean, Student t for the member count) for every
                      figure of the members' summaries, and the members; DIR/ensemble.csv
                      one row per member, DIR/ensemble.png each figure's spread; the
                      figures' P05 / P50 / P95 too. A scene with `subsection Uncertainty`
                      also samples its uncertain inputs (member k: Sobol point k through
                      each input's inverse CDF) and reports the headline figures'
                      sensitivities to them (summary.json `sensitivity`, sensitivity.png).
  --seed S            seed of the perturbations (default 1): the same seed, the same members
  --perturbation RAD  σ of the initial-angle shifts (default 1e-9 rad)
  --sensitivity saltelli
                      lay the uncertain inputs out as a Saltelli design (N = n (inputs + 2)
                      members): first-order and total Sobol indices from n ≥ 64 base rows,
                      rank correlations below; default: Sobol points and rank correlations
)";
  }

  std::string
  member_directory_name(const unsigned int k, const unsigned int n)
  {
    const auto         width = std::to_string(n > 0 ? n - 1 : 0).size();
    std::ostringstream os;
    os << "member_" << std::setw(static_cast<int>(std::max<std::size_t>(2, width))) << std::setfill('0') << k;
    return os.str();
  }
} // namespace wearlink::workflows
