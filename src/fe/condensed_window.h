// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed contact solver's window: the compliance between the positions of one
// contact window, its columns gathered once per load state, and the memory the
// window solves keep from one state to the next.
// Internal to condensed_contact_solver.cc (the one file that includes it).
#pragma once

#include "base/exceptions.h"
#include "base/text.h"
#include "base/timings.h"
#include "fe/active_set_rules.h"
#include "fe/blas_threads.h"
#include "fe/blas_trsm.h"
#include "fe/boundary_ids.h"
#include "fe/contact_solver.h"
#include "fe/window_kernels.h"

#include <deal.II/base/parallel.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <set>
#include <tuple>

namespace wearlink::fe::condensed_detail
{
  using namespace dealii;
  using blas_int = types::blas_int;

  /**
   * Active sets from this size on start with a single-precision factor (ActiveFactor,
   * refine()): below it the factorization is cheap and the refinement would cost
   * more than the float factor saves.
   */
  constexpr unsigned int single_precision_from = 160;

  /** Memory that the window solves keep from one load state to the next. */
  struct Workspace
  {
    CondensedTimings    timings;
    std::vector<double> columns;       ///< the gathered columns of A, w entries each
    std::vector<double> factor;        ///< the Cholesky factor of the active block
    std::vector<float>  factor_single; ///< the same in single precision
  };

  /**
   * The compliance between the positions of one window, A(q, p) = ∂g_q/∂λ_p: the pin
   * part read from the pin columns, the bore part from the bore columns of the bore
   * nodes that the window's rays meet (the force +n_p interpolated onto the nodes of
   * the face p meets, its displacement read at the face q meets). A column is gathered
   * on its first use into the next slot of a column-major w × slots matrix and kept
   * for the state. Columns are independent: the many that a new factor needs at once
   * are gathered on the threads deal.II's MultithreadInfo allows (TBB), each column
   * by one thread, so the result does not depend on their number.
   *
   * The bore part in the sector frames of BoundaryCompliance::BoreColumn: with
   * v_pa = w_pa R_aᵀ n_p (weight of bore node a in p's face, R_a the rotation of a's
   * frame), A_bore(q, p) = Σ_b Σ_a v_qbᵀ K(b, a) v_pa. Column p is two passes over
   * contiguous arrays: the field f(b) = Σ_a K(b, a) v_pa over the window's bore nodes,
   * then A(q, p) = pin(q, p) + Σ_b v_qb · f(b) over segments of positions whose face
   * nodes advance with them (one array offset per face node), so that both passes are
   * vector loops (window_kernels.h).
   */
  class WindowCompliance
  {
  public:
    WindowCompliance(const ElasticityProblem   &problem,
                     BoundaryCompliance        &compliance,
                     const ContactKinematics   &kin,
                     Workspace                 &work,
                     const std::vector<double> &wear_diagonal)
      : kin(kin)
      , wear_diagonal(wear_diagonal)
      , compliance(compliance)
      , w(kin.candidates.size())
      , n_pin(problem.pin_nodes.size())
      , n_bore(problem.bore_nodes.size())
      , slot(w, -1)
      , work(work)
    {
      find_rows();
      find_readers();
      find_segments();
    }

    unsigned int
    size() const
    {
      return w;
    }

    /** Gather A(·, p) unless it is gathered (this may move every column in memory). */
    void
    ensure(const unsigned int p)
    {
      if (slot[p] < 0)
        gather({p});
    }

    /** Gather the columns of @p positions that are not gathered yet (this may move every column). */
    void
    ensure(const std::vector<unsigned int> &positions)
    {
      std::vector<unsigned int> missing;
      for (const auto p : positions)
        if (slot[p] < 0)
          missing.push_back(p);
      if (!missing.empty())
        gather(missing);
    }

    /** A(·, p) over the window; ensure(p) first. */
    const double *
    column(const unsigned int p) const
    {
      return work.columns.data() + static_cast<std::size_t>(slot[p]) * w;
    }

    /** The gathered columns: a w × n_slots() column-major matrix. */
    const double *
    data() const
    {
      return work.columns.data();
    }
    unsigned int
    n_slots() const
    {
      return owner.size();
    }
    /** The solver's time by phase (Workspace). */
    CondensedTimings &
    timings() const
    {
      return work.timings;
    }

    /** The slot of position p's column, −1 if it is not gathered. */
    int
    slot_of(const unsigned int p) const
    {
      return slot[p];
    }

  private:
    /** One segment of positions q0 … q0 + length − 1 (see the class). */
    struct Segment
    {
      unsigned int       q0 = 0, length = 0, n_masters = 0;
      std::array<int, 3> offset{}; ///< row of face node m − position, per m
    };

    /** The window's bore nodes (increasing) in runs of consecutive nodes. */
    void
    find_rows()
    {
      std::vector<int> local(n_bore, -1);
      for (unsigned int p = 0; p < w; ++p)
        for (unsigned int a = 0; a < kin.n_masters[p]; ++a)
          local[kin.masters[p][a]] = 0;
      n_rows = 0;
      for (unsigned int b = 0; b < n_bore; ++b)
        if (local[b] == 0)
          {
            local[b] = static_cast<int>(n_rows);
            if (runs.empty() || b != std::get<1>(runs.back()) + std::get<2>(runs.back()))
              runs.emplace_back(n_rows, b, 0);
            ++std::get<2>(runs.back());
            ++n_rows;
          }
      row_of = std::move(local);
    }

    /** Per position and face node m: its row and v = weight × R_bᵀ n (see the class). */
    void
    find_readers()
    {
      for (unsigned int m = 0; m < 3; ++m)
        {
          row[m].assign(w, 0);
          vx[m].assign(w, 0.0);
          vy[m].assign(w, 0.0);
        }
      for (unsigned int q = 0; q < w; ++q)
        for (unsigned int m = 0; m < kin.n_masters[q]; ++m)
          {
            const unsigned int b = kin.masters[q][m];
            const auto         r = compliance.sector_rotation(b);
            const double       c = kin.weights[q][m];
            row[m][q]            = row_of[b];
            vx[m][q]             = c * (r[0] * kin.normal[q][0] + r[1] * kin.normal[q][1]);
            vy[m][q]             = c * (r[0] * kin.normal[q][1] - r[1] * kin.normal[q][0]);
          }
    }

    /** Segments: consecutive candidates with the same face-node count, each face node's row one further. */
    void
    find_segments()
    {
      for (unsigned int q = 0; q < w; ++q)
        {
          bool extends = !segments.empty() && q > 0 && kin.candidates[q] == kin.candidates[q - 1] + 1 &&
                         kin.n_masters[q] == kin.n_masters[q - 1];
          for (unsigned int m = 0; extends && m < kin.n_masters[q]; ++m)
            extends = row[m][q] == row[m][q - 1] + 1;
          if (extends)
            {
              ++segments.back().length;
              continue;
            }
          Segment s;
          s.q0        = q;
          s.length    = 1;
          s.n_masters = kin.n_masters[q];
          for (unsigned int m = 0; m < s.n_masters; ++m)
            s.offset[m] = static_cast<int>(row[m][q]) - static_cast<int>(q);
          segments.push_back(s);
        }
    }

    /** The four blocks of the bore column at @p base from row @p b on. */
    kernels::BlockRows
    block_rows(const double *base, const unsigned int b) const
    {
      return {base + b, base + n_bore + b, base + 2 * n_bore + b, base + 3 * n_bore + b};
    }

    /** The bore field f over the window's rows for the force n_p at p's face (see the class). */
    void
    bore_field(const unsigned int p, double *field_x, double *field_y) const
    {
      const unsigned int n_masters = kin.n_masters[p];
      if (n_masters == 0)
        {
          std::fill(field_x, field_x + n_rows, 0.0);
          std::fill(field_y, field_y + n_rows, 0.0);
        }
      // The first two face nodes in one pass, a third one (quadratic faces) added.
      unsigned int m = 0;
      if (n_masters >= 2)
        {
          add_field(p, 0, 1, field_x, field_y);
          m = 2;
        }
      for (; m < n_masters; ++m)
        add_field(p, m, m, field_x, field_y);
    }

    /**
     * The field of p's face nodes m0 and m1 over the window's rows, in one pass
     * (field_two()); of node m0 alone if m1 = m0, added to the field when m0 > 0.
     */
    void
    add_field(const unsigned int p, const unsigned int m0, const unsigned int m1, double *fx, double *fy) const
    {
      const auto    c0 = compliance.bore_column(kin.masters[p][m0]);
      const auto    c1 = compliance.bore_column(kin.masters[p][m1]);
      const double *x0 = c0.base, *x1 = c1.base;
      for (const auto &[r0, b_first, n] : runs)
        {
          unsigned int r = r0, left = n;
          unsigned int b = (b_first + n_bore - c0.shift) % n_bore, d = (b_first + n_bore - c1.shift) % n_bore;
          while (left > 0) // each column wraps at most once
            {
              const unsigned int len = std::min({left, n_bore - b, n_bore - d});
              if (m1 != m0)
                kernels::field_two(fx + r,
                                   fy + r,
                                   block_rows(x0, b),
                                   vx[m0][p],
                                   vy[m0][p],
                                   block_rows(x1, d),
                                   vx[m1][p],
                                   vy[m1][p],
                                   len);
              else
                kernels::field(fx + r, fy + r, block_rows(x0, b), vx[m0][p], vy[m0][p], len, m0 > 0);
              r += len;
              left -= len;
              b = b + len == n_bore ? 0 : b + len;
              d = d + len == n_bore ? 0 : d + len;
            }
        }
    }

    /**
     * Reserve the next slots for @p positions and compute the bore and pin columns
     * they use (BoundaryCompliance computes missing ones on first use, which only one
     * thread may do).
     */
    void
    reserve(const std::vector<unsigned int> &positions)
    {
      const std::size_t needed = static_cast<std::size_t>(owner.size() + positions.size()) * w;
      if (work.columns.size() < needed)
        work.columns.resize(std::max(needed, 2 * work.columns.size()));
      for (const auto p : positions)
        {
          slot[p] = static_cast<int>(owner.size());
          owner.push_back(p);
          compliance.pin_column(kin.candidates[p]);
          for (unsigned int m = 0; m < kin.n_masters[p]; ++m)
            compliance.bore_column(kin.masters[p][m]);
        }
    }

    /** Gather the columns of @p positions (in parallel when there are many). */
    void
    gather(const std::vector<unsigned int> &positions)
    {
      reserve(positions);
      const ScopedSeconds timer(work.timings.gather);
      const auto          fill_range = [&](const unsigned int begin, const unsigned int end) {
        std::vector<double> fx(n_rows), fy(n_rows);
        for (unsigned int i = begin; i < end; ++i)
          fill(positions[i], fx.data(), fy.data());
      };
      constexpr unsigned int serial_below = 64;
      if (positions.size() < serial_below)
        fill_range(0, positions.size());
      else
        parallel::apply_to_subranges(0u, static_cast<unsigned int>(positions.size()), fill_range, serial_below / 2);
    }

    /** Column p into its slot, with the field buffers fx, fy (n_rows each). */
    void
    fill(const unsigned int p, double *field_x, double *field_y) const
    {
      bore_field(p, field_x, field_y);
      double    *col = work.columns.data() + static_cast<std::size_t>(slot[p]) * w;
      const auto pin = compliance.pin_column(kin.candidates[p]);
      for (const auto &s : segments)
        {
          unsigned int q = s.q0, left = s.length;
          unsigned int i = kin.candidates[q] + n_pin - pin.shift;
          i              = i >= n_pin ? i - n_pin : i;
          while (left > 0) // the pin column wraps at most once
            {
              const unsigned int len = std::min(left, n_pin - i);
              const auto         fx  = [&](unsigned int m) {
                return field_x + q + s.offset[m];
              };
              const auto fy = [&](unsigned int m) {
                return field_y + q + s.offset[m];
              };
              if (s.n_masters >= 2)
                kernels::read_two(col + q,
                                  pin.base + i,
                                  vx[0].data() + q,
                                  vy[0].data() + q,
                                  fx(0),
                                  fy(0),
                                  vx[1].data() + q,
                                  vy[1].data() + q,
                                  fx(1),
                                  fy(1),
                                  len);
              else
                std::copy(pin.base + i, pin.base + i + len, col + q);
              for (unsigned int m = s.n_masters >= 2 ? 2 : 0; m < s.n_masters; ++m)
                kernels::read_add(col + q, vx[m].data() + q, vy[m].data() + q, fx(m), fy(m), len);
              q += len;
              left -= len;
              i = 0;
            }
        }
      if (!wear_diagonal.empty())
        col[p] += wear_diagonal[kin.candidates[p]];
    }

    const ContactKinematics   &kin;
    const std::vector<double> &wear_diagonal; ///< CondensedContactSolver::set_wear_diagonal()
    BoundaryCompliance        &compliance;
    const unsigned int         w, n_pin, n_bore;
    unsigned int               n_rows = 0;
    std::vector<int>           row_of; ///< row of each bore node in the field, −1 outside the window
    /** Runs of consecutive bore nodes: (first row, first node, length). */
    std::vector<std::tuple<unsigned int, unsigned int, unsigned int>> runs;
    std::array<std::vector<unsigned int>, 3>                          row; ///< per face node m: its row, per position
    std::array<std::vector<double>, 3>                                vx, vy; ///< per face node m: v (see the class)
    std::vector<Segment>                                              segments;
    std::vector<int>                                                  slot;
    std::vector<unsigned int>                                         owner; ///< the position of each slot
    Workspace                                                        &work;
  };

} // namespace wearlink::fe::condensed_detail
