// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed contact solver (contact_solver.h): one load state on its contact window,
// with the window's columns of the compliance gathered once and the Cholesky factor of
// the active block updated row by row from the first change.
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

namespace wearlink::fe
{
  using namespace dealii;

  namespace condensed_detail
  {
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

    /**
     * A lower Cholesky factor in the precision Number (leading dimension ld, storage in
     * the solver's workspace), built and used row block by row block: LAPACK/BLAS.
     */
    template <typename Number>
    class Cholesky
    {
    public:
      Cholesky(std::vector<Number> &storage, const unsigned int ld)
        : ld(ld)
      {
        if (storage.size() < static_cast<std::size_t>(ld) * ld) // only what is written is read
          storage.resize(static_cast<std::size_t>(ld) * ld);
        L = storage.data();
      }

      /**
       * Rows c … k − 1 of the factor of the k × k matrix whose entry (r, s), r ≥ s, is
       * @p entry(r, s): L21 = A21 L11⁻ᵀ, L22 = chol(A22 − L21 L21ᵀ). A whole factor of
       * many rows is built block column by block column (right-looking; the rows before
       * c, already factored, are the first block column), each block's panel solve and
       * trailing update as two tasks, so that both cores work on it. False if the matrix
       * is not positive definite (in this precision).
       */
      template <typename Entry>
      bool
      refactor_from(const unsigned int c, const unsigned int k, const Entry &entry)
      {
        copy_rows(c, k, entry);
        if (c > 0 && c < k) // the unchanged leading factor acts as one block column
          {
            solve_panel(0, c, k);
            update_trailing(0, c, k);
          }
        constexpr unsigned int block = 128; // rows; the BLAS's own block size for potrf
        for (unsigned int j0 = c; j0 < k; j0 += block)
          {
            const unsigned int j1 = std::min(j0 + block, k);
            if (!factor_block(j0, j1))
              return false;
            if (j1 < k)
              {
                solve_panel(j0, j1, k);
                update_trailing(j0, j1, k);
              }
          }
        return true;
      }

      /** Rows valid … k − 1 of v := L⁻¹ v (k entries), the rows before valid being done. */
      void
      forward_rows(Number *v, const unsigned int k, const unsigned int valid)
      {
        const blas_int t = k - valid, c = valid, ldb = ld, one = 1;
        blas_int       info = 0;
        if (t == 0)
          return;
        if (c > 0)
          {
            const Number minus_one = -1, plus_one = 1;
            gemv("N", &t, &c, &minus_one, &at(c, 0), &ldb, v, &one, &plus_one, v + c, &one);
          }
        trtrs("L", "N", "N", &t, &one, &at(c, c), &ldb, v + c, &t, &info);
      }

      /** v := L⁻ᵀ v (k entries). */
      void
      backward(Number *v, const unsigned int k) const
      {
        const blas_int kk = k, ldb = ld, one = 1;
        blas_int       info = 0;
        if (k > 0)
          trtrs("L", "T", "N", &kk, &one, L, &ldb, v, &kk, &info);
      }

    private:
      Number &
      at(const unsigned int r, const unsigned int s)
      {
        return L[r + static_cast<std::size_t>(s) * ld];
      }

      /** Entries (r, s), s ≤ r, of rows c … k − 1 from @p entry (see refactor_from()). */
      template <typename Entry>
      void
      copy_rows(const unsigned int c, const unsigned int k, const Entry &entry)
      {
        for (unsigned int s = 0; s < k; ++s)
          for (unsigned int r = std::max(c, s); r < k; ++r)
            at(r, s) = entry(r, s);
      }

      /** The diagonal block of rows j0 … j1 − 1, updated by the columns before j0: its factor. */
      bool
      factor_block(const unsigned int j0, const unsigned int j1)
      {
        const blas_int t = j1 - j0, ldb = ld;
        blas_int       info = 0;
        potrf("L", &t, &at(j0, j0), &ldb, &info);
        return info == 0;
      }

      /**
       * The panel of rows j1 … k − 1 in the columns j0 … j1 − 1, whose diagonal block is
       * factored: L21 := L21 L11⁻ᵀ in place (BLAS trsm from the right), in two tasks of
       * half the rows each when it is large.
       */
      void
      solve_panel(const unsigned int j0, const unsigned int j1, const unsigned int k)
      {
        const unsigned int t     = k - j1;
        const unsigned int parts = t * (j1 - j0) >= parallel_from && blas_is_thread_safe() ? 2 : 1;
        const auto         part  = [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int n = begin; n < end; ++n)
            {
              const unsigned int r0 = j1 + n * t / parts, r1 = j1 + (n + 1) * t / parts;
              const blas_int     rows = r1 - r0, cols = j1 - j0, ldb = ld;
              const Number       one = 1;
              blas::trsm("R", "L", "T", "N", &rows, &cols, &one, &at(j0, j0), &ldb, &at(r0, j0), &ldb);
            }
        };
        parallel::apply_to_subranges(0u, parts, part, 1);
      }

      /**
       * A22 −= L21 L21ᵀ (lower triangle) for the rows j1 … k − 1 and the panel's columns
       * j0 … j1 − 1: when large, as two tasks of equal work, the first m = t/√2 rows
       * (syrk) and the others (gemm, syrk).
       */
      void
      update_trailing(const unsigned int j0, const unsigned int j1, const unsigned int k)
      {
        const blas_int     t = k - j1, cc = j1 - j0, ldb = ld;
        const Number       minus_one = -1, one = 1;
        const bool         two  = static_cast<unsigned int>(t) * cc >= parallel_from && blas_is_thread_safe();
        const unsigned int m    = two ? static_cast<unsigned int>(t / std::sqrt(2.0)) : t;
        const auto         part = [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int n = begin; n < end; ++n)
            if (n == 0)
              {
                const blas_int mm = m;
                syrk("L", "N", &mm, &cc, &minus_one, &at(j1, j0), &ldb, &one, &at(j1, j1), &ldb);
              }
            else
              {
                const blas_int rest = t - m, mm = m;
                gemm("N",
                     "T",
                     &rest,
                     &mm,
                     &cc,
                     &minus_one,
                     &at(j1 + m, j0),
                     &ldb,
                     &at(j1, j0),
                     &ldb,
                     &one,
                     &at(j1 + m, j1),
                     &ldb);
                syrk("L", "N", &rest, &cc, &minus_one, &at(j1 + m, j0), &ldb, &one, &at(j1 + m, j1 + m), &ldb);
              }
        };
        parallel::apply_to_subranges(0u, two ? 2u : 1u, part, 1);
      }

      /** Panels of at least this many entries (rows × columns) are split into two tasks. */
      static constexpr unsigned int parallel_from = 128 * 128;

      const unsigned int ld;
      Number            *L = nullptr;
    };

    /**
     * The Cholesky factor of A on the active positions, kept in the order of increasing
     * distance of the candidates from the window's first point of contact, so that the
     * edges of the contact arc, where an active-set iteration changes the set, come
     * last: a new set re-factors only the rows after the longest common prefix with the
     * previous order. The entries come from the gathered columns, lower triangle only
     * (A is symmetric to 3e-14 of its largest entry, measured at 100 kN): entry (r, s),
     * r after s in the factor's order, is A(order[r], order[s]), read from column
     * order[s].
     *
     * Single precision (float) for large active sets: the factorization takes half the
     * time, and a solution to double precision follows from the float factor by
     * iterative refinement with the double-precision columns (refine(); A is well
     * conditioned, cond ≈ 570 at 100 kN, so each step gains ~4 digits). A float factor
     * that fails (not positive definite in float) is replaced by a double one.
     */
    class ActiveFactor
    {
    public:
      ActiveFactor(WindowCompliance        &A,
                   const ContactKinematics &kin,
                   const unsigned int       m,
                   Workspace               &work,
                   const bool               single)
        : A(A)
        , timings(work.timings)
        , single(single)
        , factor_single(work.factor_single, A.size())
        , factor_double(work.factor, A.size())
        , is_active(A.size(), 0)
      {
        unsigned int centre = 0;
        for (unsigned int p = 1; p < kin.g0.size(); ++p)
          if (kin.g0[p] < kin.g0[centre])
            centre = p;
        const long        c = kin.candidates.empty() ? 0 : kin.candidates[centre];
        std::vector<long> key(A.size()); // distance from the centre, then index
        for (unsigned int p = 0; p < key.size(); ++p)
          {
            const long d = std::abs(static_cast<long>(kin.candidates[p]) - c);
            key[p]       = std::min<long>(d, static_cast<long>(m) - d) * static_cast<long>(m) + kin.candidates[p];
          }
        by_key.resize(A.size());
        std::iota(by_key.begin(), by_key.end(), 0u);
        std::sort(by_key.begin(), by_key.end(), [&](unsigned int a, unsigned int b) { return key[a] < key[b]; });
      }

      /** From now on in double precision (re-factored at the next set()). */
      void
      make_double()
      {
        single        = false;
        ok            = true;
        normals_valid = gaps_valid = 0;
        order.clear();
      }

      /** True while the factor is in single precision (its solutions need refine()). */
      bool
      single_precision() const
      {
        return single;
      }

      /** Factor A on @p active (any order); false if it is not positive definite. */
      bool
      set(const std::vector<unsigned int> &active)
      {
        std::vector<unsigned int> next;
        next.reserve(active.size());
        for (const auto p : active)
          is_active[p] = 1;
        for (const auto p : by_key)
          if (is_active[p])
            next.push_back(p);
        for (const auto p : active)
          is_active[p] = 0;
        unsigned int c = 0;
        while (c < next.size() && c < order.size() && next[c] == order[c])
          ++c;
        order = next;
        if (!ok) // the old factor is unusable: start over
          c = 0;
        normals_valid = std::min(normals_valid, c);
        gaps_valid    = std::min(gaps_valid, c);
        if (c == order.size())
          return ok;
        A.ensure(order);
        const ScopedSeconds timer(timings.factorization);
        const auto          entry = [&](const unsigned int r, const unsigned int s) {
          return A.column(order[s])[order[r]];
        };
        ok = single ? factor_single.refactor_from(c, order.size(), entry) :
                      factor_double.refactor_from(c, order.size(), entry);
        if (!ok && single)
          {
            single        = false;
            normals_valid = gaps_valid = 0;
            ok                         = factor_double.refactor_from(0, order.size(), entry);
          }
        return ok;
      }

      /**
       * The forward substitutions in the factor's order, y_d = L⁻¹ n_d (d = x, y) and
       * z = L⁻¹ g0: row r depends on rows ≤ r only, so after set() only the rows from
       * the first change are recomputed (and z in full after gaps_changed()).
       */
      void
      forward(const ContactKinematics &kin, const bool with_normals)
      {
        const ScopedSeconds timer(timings.substitutions);
        for (unsigned int d = 0; with_normals && d < 2; ++d)
          forward_rows([&](unsigned int p) { return kin.normal[p][d]; }, normals_valid, yf[d], y[d]);
        if (with_normals)
          normals_valid = order.size();
        forward_rows([&](unsigned int p) { return kin.g0[p]; }, gaps_valid, zf, z);
        gaps_valid = order.size();
      }

      /** The initial gaps changed (a new linearization): z is recomputed in full. */
      void
      gaps_changed()
      {
        gaps_valid = 0;
      }

      /** y_d (d = 0, 1) and z of forward(), in the factor's order. */
      const std::vector<double> &
      forward_normal(const unsigned int d) const
      {
        return y[d];
      }
      const std::vector<double> &
      forward_gap() const
      {
        return z;
      }

      /** x := L⁻¹ x for x in the factor's order. */
      void
      forward_full(std::vector<double> &x)
      {
        const ScopedSeconds timer(timings.substitutions);
        if (!single)
          return factor_double.forward_rows(x.data(), order.size(), 0);
        std::vector<float> v(x.begin(), x.end());
        factor_single.forward_rows(v.data(), order.size(), 0);
        std::copy(v.begin(), v.end(), x.begin());
      }

      /** x := L⁻ᵀ x for x in the factor's order. */
      void
      backward(std::vector<double> &x) const
      {
        const ScopedSeconds timer(timings.substitutions);
        if (!single)
          return factor_double.backward(x.data(), order.size());
        std::vector<float> v(x.begin(), x.end());
        factor_single.backward(v.data(), order.size());
        std::copy(v.begin(), v.end(), x.begin());
      }

      /** The active positions in the factor's order. */
      const std::vector<unsigned int> &
      ordered() const
      {
        return order;
      }

    private:
      /**
       * Rows valid … k − 1 of the forward substitution of b (the value of each
       * position) into out, through the single-precision copy vf when the factor is.
       */
      template <typename Value>
      void
      forward_rows(const Value &b, const unsigned int valid, std::vector<float> &vf, std::vector<double> &out)
      {
        const unsigned int k = order.size();
        out.resize(k);
        for (unsigned int r = valid; r < k; ++r)
          out[r] = b(order[r]);
        if (!single)
          return factor_double.forward_rows(out.data(), k, valid);
        vf.resize(k);
        for (unsigned int r = valid; r < k; ++r)
          vf[r] = static_cast<float>(out[r]);
        factor_single.forward_rows(vf.data(), k, valid);
        for (unsigned int r = valid; r < k; ++r)
          out[r] = vf[r];
      }

      WindowCompliance                  &A;
      CondensedTimings                  &timings;
      bool                               single;
      Cholesky<float>                    factor_single;
      Cholesky<double>                   factor_double;
      std::vector<unsigned int>          by_key;    ///< the positions by distance from the centre, then index
      std::vector<char>                  is_active; ///< scratch of set()
      std::vector<unsigned int>          order;
      bool                               ok = true;
      std::array<std::vector<double>, 2> y;                 ///< L⁻¹ n_x, L⁻¹ n_y (factor order)
      std::vector<double>                z;                 ///< L⁻¹ g0 (factor order)
      std::array<std::vector<float>, 2>  yf;                ///< y in single precision
      std::vector<float>                 zf;                ///< z in single precision
      unsigned int                       normals_valid = 0; ///< leading rows of y that are up to date
      unsigned int                       gaps_valid    = 0; ///< leading rows of z that are up to date
    };

    /** The multipliers of the active positions (in the order of @p active) and U. */
    struct ActiveSolution
    {
      std::vector<double> lambda;
      Tensor<1, 2>        U;
      bool                ok = true;
    };

    /**
     * The Schur step of the active system in the factor's variables: for the forward
     * substitutions y_d = L⁻¹ n_d and w = L⁻¹ a of a right-hand side a, the U of
     * A λ − N U = a, Nᵀ λ = b is S⁻¹ (b − Yᵀw) with S = Nᵀ A⁻¹ N = YᵀY, and
     * L⁻ᵀ (w + Y U) is λ; x receives w + Y U. False if S is singular.
     */
    bool
    schur_step(const ActiveFactor &factor, const Tensor<1, 2> &b, std::vector<double> &x, Tensor<1, 2> &U)
    {
      const auto &y0 = factor.forward_normal(0), &y1 = factor.forward_normal(1);
      const auto  k       = x.size();
      double      S[2][2] = {{0, 0}, {0, 0}}, rhs[2] = {b[0], b[1]};
      for (unsigned int r = 0; r < k; ++r)
        {
          S[0][0] += y0[r] * y0[r];
          S[0][1] += y0[r] * y1[r];
          S[1][1] += y1[r] * y1[r];
          rhs[0] -= y0[r] * x[r];
          rhs[1] -= y1[r] * x[r];
        }
      S[1][0]          = S[0][1];
      const double det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
      if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
        return false;
      // Two steps of iterative refinement of U: with only a few active candidates of
      // nearly parallel normals, S is near-singular (the pin may slide sideways almost
      // freely) and the 2 × 2 solve leaves a residual of cond(S) ε, which the balance
      // Nᵀλ = b would show at 1e-7 (measured on worn profiles at small loads);
      // Nᵀλ = S U + Yᵀw, so the balance is the residual of S U = rhs.
      U = 0;
      for (unsigned int step = 0; step < 3; ++step)
        {
          const double r0 = rhs[0] - S[0][0] * U[0] - S[0][1] * U[1];
          const double r1 = rhs[1] - S[1][0] * U[0] - S[1][1] * U[1];
          U[0] += (S[1][1] * r0 - S[0][1] * r1) / det;
          U[1] += (S[0][0] * r1 - S[1][0] * r0) / det;
        }
      for (unsigned int r = 0; r < k; ++r)
        x[r] += y0[r] * U[0] + y1[r] * U[1];
      return true;
    }

    /**
     * The active system: A λ = N U − g0 with, under force control, Nᵀ λ = P
     * (schur_step() with a = −g0, b = P), under displacement control λ = −A⁻¹ g0. To
     * the precision of the factor (refine() takes a single-precision one further).
     */
    ActiveSolution
    solve_active(const ContactKinematics         &kin,
                 ActiveFactor                    &factor,
                 const std::vector<unsigned int> &active,
                 const bool                       force_control,
                 const Tensor<1, 2>              &P)
    {
      ActiveSolution out;
      if (!factor.set(active))
        {
          out.ok = false;
          return out;
        }
      const auto        &order = factor.ordered();
      const unsigned int k     = order.size();
      factor.forward(kin, force_control);
      std::vector<double> x(k);
      for (unsigned int r = 0; r < k; ++r)
        x[r] = -factor.forward_gap()[r];
      if (force_control && !schur_step(factor, P, x, out.U))
        {
          out.ok = false;
          return out;
        }
      factor.backward(x);
      // Back to the order of `active` (through the window: x by position first).
      std::vector<double> by_position(kin.g0.size());
      for (unsigned int r = 0; r < k; ++r)
        by_position[order[r]] = x[r];
      out.lambda.resize(k);
      for (unsigned int s = 0; s < k; ++s)
        out.lambda[s] = by_position[active[s]];
      return out;
    }

    /** Which gaps window_gaps() computes. */
    enum class Rows
    {
      all,
      inactive, ///< the only ones the active-set rules read (an active gap is zero up to round-off)
      active    ///< the residual of the active system (refine())
    };

    /** Products window_gaps() does of at least this many entries (rows × columns) are two tasks. */
    constexpr std::size_t gaps_parallel_from = 256 * 256;

    /**
     * g = g0 − n·U + A λ over the window, for the multipliers @p lambda (per position)
     * of @p active, at the positions @p rows names; the others keep their values. One
     * matrix–vector product of the gathered columns (BLAS) per run of positions.
     */
    void
    window_gaps(const ContactKinematics         &kin,
                WindowCompliance                &A,
                const std::vector<unsigned int> &active,
                const std::vector<double>       &lambda,
                const Tensor<1, 2>              &U,
                std::vector<double>             &gap,
                const Rows                       rows_wanted)
    {
      const unsigned int w = kin.g0.size();
      gap.resize(w);
      for (const auto p : active)
        A.ensure(p);
      const ScopedSeconds timer(A.timings().gaps);
      std::vector<double> x(A.n_slots(), 0.0);
      std::vector<char>   skip(w, rows_wanted == Rows::active);
      for (const auto p : active)
        {
          x[A.slot_of(p)] = lambda[p];
          skip[p]         = rows_wanted == Rows::inactive;
        }
      std::vector<std::pair<unsigned int, unsigned int>> runs; // [q0, q1) of wanted rows
      for (unsigned int q0 = 0; q0 < w;)
        {
          unsigned int q1 = q0;
          for (; q1 < w && !skip[q1]; ++q1)
            gap[q1] = kin.g0[q1] - kin.normal[q1] * U;
          if (q1 > q0)
            runs.emplace_back(q0, q1);
          q0 = q1 + 1;
        }
      // Each run's rows in two halves, the first halves one task, the second the other.
      std::size_t rows_total = 0;
      for (const auto &[q0, q1] : runs)
        rows_total += q1 - q0;
      const unsigned int parts = rows_total * x.size() >= gaps_parallel_from && blas_is_thread_safe() ? 2 : 1;
      const auto         part  = [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int n = begin; n < end; ++n)
          for (const auto &[q0, q1] : runs)
            {
              const unsigned int r0 = q0 + n * (q1 - q0) / parts, r1 = q0 + (n + 1) * (q1 - q0) / parts;
              const blas_int     rows = r1 - r0, cols = x.size(), ld = w, one = 1;
              const double       alpha = 1, beta = 1;
              if (rows > 0 && cols > 0)
                gemv("N", &rows, &cols, &alpha, A.data() + r0, &ld, x.data(), &one, &beta, gap.data() + r0, &one);
            }
      };
      parallel::apply_to_subranges(0u, parts, part, 1);
    }

    /** Everything one window solve carries between its phases. */
    struct WindowState
    {
      std::vector<unsigned int> active;
      std::vector<double>       lambda, gap; ///< per position of the window
      Tensor<1, 2>              U;
      unsigned int              iterations = 0;
      /**
       * max |g0_p| / A_pp over the active positions [N/m]: the line load that closing
       * the initial gaps alone would carry. The active solve cancels terms of this size
       * down to the load, so the balance holds to round-off of it, not of the load
       * (a vanishing load on a pin whose rigid translation closes gaps of ~1e-8 m).
       */
      double gap_force = 0;
    };

    /** Apply an active solution: λ on the window, U, and the gaps (see window_gaps()). */
    void
    accept(const ContactKinematics &kin, WindowCompliance &A, const ActiveSolution &x, WindowState &st, const Rows rows)
    {
      std::fill(st.lambda.begin(), st.lambda.end(), 0.0);
      for (unsigned int s = 0; s < st.active.size(); ++s)
        st.lambda[st.active[s]] = x.lambda[s];
      st.U = x.U;
      window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, rows);
    }

    /**
     * Iterative refinement of the applied active solution in @p st, whose gaps are
     * those of the active positions (accept()): the residuals of the active system are
     * −g there (from the double-precision columns) and P − Nᵀλ; the correction solves
     * the same system for them with the factor again. Ends when the error left is below
     * 1e-12 of λ (two corrections from a single-precision factor at 100 kN), with the
     * gaps of the inactive positions; false if that takes more than max_refinements.
     */
    bool
    refine(const ContactKinematics &kin,
           WindowCompliance        &A,
           ActiveFactor            &factor,
           const bool               force_control,
           const Tensor<1, 2>      &P,
           WindowState             &st)
    {
      constexpr unsigned int max_refinements = 6;
      const auto            &order           = factor.ordered();
      const unsigned int     k               = order.size();
      double                 previous        = 0; // the size of the last correction
      for (unsigned int step = 0; step < max_refinements; ++step)
        {
          std::vector<double> x(k);
          Tensor<1, 2>        balance = P, dU;
          double              largest = 0;
          for (unsigned int r = 0; r < k; ++r)
            {
              x[r] = -st.gap[order[r]];
              balance -= st.lambda[order[r]] * kin.normal[order[r]];
              largest = std::max(largest, std::abs(st.lambda[order[r]]));
            }
          factor.forward_full(x);
          if (force_control && !schur_step(factor, balance, x, dU))
            return false;
          factor.backward(x);
          double correction = 0;
          for (unsigned int r = 0; r < k; ++r)
            {
              st.lambda[order[r]] += x[r];
              correction = std::max(correction, std::abs(x[r]));
            }
          st.U += dU;
          // Converged when this correction, or the next one that the contraction of the
          // last two predicts (each correction leaves ρ = c_k / c_(k−1) of itself, ~3e-5
          // from a float factor at 100 kN), is below 1e-12 of λ; the active gaps then
          // move by A δλ, below round-off.
          const double next = step > 0 && previous > 0 ? correction * (correction / previous) : correction;
          if (std::max(next, correction * 1e-4) <= 1e-12 * largest || correction <= 1e-12 * largest)
            {
              window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::inactive);
              return true;
            }
          previous = correction;
          window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::active);
        }
      return false;
    }

    /**
     * Solve the active system on st.active and apply it (accept()), to double precision
     * if @p exact (refine() after a single-precision factor; a double factor if that
     * does not converge). False if a factorization fails.
     */
    bool
    solve_and_accept(const ContactKinematics &kin,
                     WindowCompliance        &A,
                     ActiveFactor            &factor,
                     const bool               force_control,
                     const Tensor<1, 2>      &P,
                     const bool               exact,
                     const bool               inactive_only,
                     WindowState             &st)
    {
      auto x = solve_active(kin, factor, st.active, force_control, P);
      if (!x.ok)
        return false;
      const bool refining = exact && factor.single_precision();
      accept(kin, A, x, st, refining ? Rows::active : inactive_only ? Rows::inactive : Rows::all);
      if (!refining || refine(kin, A, factor, force_control, P, st))
        return true;
      factor.make_double();
      x = solve_active(kin, factor, st.active, force_control, P);
      if (!x.ok)
        return false;
      accept(kin, A, x, st, inactive_only ? Rows::inactive : Rows::all);
      return true;
    }

    /**
     * The primal–dual iteration from @p st.active; true when the active set repeats
     * (converged), false when it cycles, stalls at @p limit, or a factorization fails.
     * Each active solve to double precision if @p exact, else to the factor's.
     */
    bool
    primal_dual(const ContactKinematics &kin,
                WindowCompliance        &A,
                ActiveFactor            &factor,
                const bool               force_control,
                const Tensor<1, 2>      &P,
                const unsigned int       limit,
                const bool               exact,
                WindowState             &st)
    {
      std::set<std::vector<unsigned int>> history;
      for (unsigned int it = 1; it <= limit; ++it)
        {
          ++st.iterations;
          if (!solve_and_accept(kin, A, factor, force_control, P, exact, true, st))
            return false;
          auto next = active_set::update(st.active, st.lambda, st.gap, kin.tolerance, history);
          if (force_control)
            active_set::ensure_two_active(next, st.gap, kin.normal, P);
          if (next == st.active)
            return true;
          if (history.count(next) != 0)
            return false;
          st.active = next;
        }
      return false;
    }

    /**
     * A feasible start of the monotone phase: λ ≥ 0 with Σ λ n = P (force control) on the
     * two positions of ensure_two_active (closest, and the one bracketing P with it), or
     * λ = 0 (displacement control).
     */
    void
    feasible_start(const ContactKinematics &kin, const bool force_control, const Tensor<1, 2> &P, WindowState &st)
    {
      std::fill(st.lambda.begin(), st.lambda.end(), 0.0);
      st.active.clear();
      if (!force_control)
        return;
      active_set::ensure_two_active(st.active, kin.g0, kin.normal, P);
      if (st.active.size() < 2)
        return;
      const auto  &a = kin.normal[st.active[0]], &b = kin.normal[st.active[1]];
      const double d = a[0] * b[1] - a[1] * b[0];
      if (d == 0.0)
        return;
      // Clipped at 0 when the pair does not bracket the load (then the start is not
      // quite feasible; the first full step restores the balance).
      st.lambda[st.active[0]] = std::max(0.0, (P[0] * b[1] - P[1] * b[0]) / d);
      st.lambda[st.active[1]] = std::max(0.0, (a[0] * P[1] - a[1] * P[0]) / d);
    }

    /**
     * The monotone (Lawson–Hanson type) step from the feasible λ towards the minimizer
     * @p x of the current active set: the longest step α ∈ [0, 1) that keeps λ ≥ 0; the
     * positions whose force reaches zero leave the set. Returns α, or 1 (changing
     * nothing) if @p x is feasible itself.
     */
    double
    step_back_to_feasible(std::vector<unsigned int> &active, const std::vector<double> &x, std::vector<double> &lambda)
    {
      double       alpha = 1, tolerance = 0; // forces this close to zero are zero (active_set::update)
      unsigned int blocker = active.size();
      for (const double v : x)
        tolerance = std::max(tolerance, 1e-10 * std::abs(v));
      for (unsigned int s = 0; s < active.size(); ++s)
        if (x[s] < -tolerance)
          {
            const double l = lambda[active[s]];
            const double a = l > 0 ? l / (l - x[s]) : 0.0;
            if (blocker == active.size() || a < alpha)
              {
                alpha   = a;
                blocker = s;
              }
          }
      if (blocker == active.size())
        return 1;
      std::vector<unsigned int> kept;
      if (alpha == 0)
        {
          // Degenerate: positions at zero force that the minimizer wants tensile leave;
          // the point does not move, and the others stay.
          for (unsigned int s = 0; s < active.size(); ++s)
            if (lambda[active[s]] > 0 || x[s] >= -tolerance)
              kept.push_back(active[s]);
          active = kept;
          return 0;
        }
      double max_lambda = 0;
      for (unsigned int s = 0; s < active.size(); ++s)
        {
          double &l = lambda[active[s]];
          l += alpha * (x[s] - l);
          max_lambda = std::max(max_lambda, l);
        }
      lambda[active[blocker]] = 0;
      for (const auto i : active)
        if (lambda[i] > 1e-14 * max_lambda)
          kept.push_back(i);
        else
          lambda[i] = 0;
      active = kept;
      return alpha;
    }

    /** The penetrating positions outside the active set, the worst first. */
    std::vector<unsigned int>
    penetrating(const std::vector<double> &lambda, const std::vector<double> &gap, const double tolerance)
    {
      std::vector<unsigned int> out;
      for (unsigned int i = 0; i < gap.size(); ++i)
        if (lambda[i] == 0.0 && gap[i] < -tolerance)
          out.push_back(i);
      std::stable_sort(out.begin(), out.end(), [&](unsigned int a, unsigned int b) { return gap[a] < gap[b]; });
      return out;
    }

    /**
     * The monotone primal active-set method (see CondensedContactSolver::solve): from the
     * feasible pair, the worst penetrating position joins, one at a time; a step that
     * would make a force tensile stops where it reaches zero and that position leaves.
     * The objective never increases and drops at every step that is not degenerate, so
     * no active set repeats. True when it ends within @p limit steps.
     */
    bool
    monotone(const ContactKinematics &kin,
             WindowCompliance        &A,
             ActiveFactor            &factor,
             const bool               force_control,
             const Tensor<1, 2>      &P,
             const unsigned int       limit,
             WindowState             &st)
    {
      feasible_start(kin, force_control, P, st);
      // A position that joins and is dropped again at once without the point moving
      // (round-off at a penetration near the tolerance) is blocked until the point
      // moves; violations left only at blocked positions below 1 nm count as solved.
      const unsigned int w = kin.g0.size();
      std::vector<char>  blocked(w, 0);
      unsigned int       joined = w;
      for (unsigned int it = 0; it < limit; ++it, ++st.iterations)
        {
          if (force_control)
            active_set::ensure_two_active(st.active, kin.g0, kin.normal, P);
          const auto x = solve_active(kin, factor, st.active, force_control, P);
          if (!x.ok)
            return false;
          const double alpha = step_back_to_feasible(st.active, x.lambda, st.lambda);
          if (alpha == 0 && joined < w && !std::binary_search(st.active.begin(), st.active.end(), joined))
            blocked[joined] = 1;
          else if ((alpha > 0 && alpha < 1) || (alpha == 1 && joined < w)) // the point moved
            std::fill(blocked.begin(), blocked.end(), 0);
          joined = w;
          if (alpha < 1)
            continue;
          accept(kin, A, x, st, Rows::all);
          double worst_blocked = 0;
          for (const auto i : penetrating(st.lambda, st.gap, kin.tolerance))
            if (!blocked[i])
              {
                joined = i;
                break;
              }
            else
              worst_blocked = std::min(worst_blocked, st.gap[i]);
          if (joined == w)
            return worst_blocked > -1e-9;
          st.active.insert(std::upper_bound(st.active.begin(), st.active.end(), joined), joined);
        }
      return false;
    }

    /** Whether some of @p normal lie on either side of @p load (or along it). */
    bool
    brackets(const std::vector<Tensor<1, 2>> &normal, const Tensor<1, 2> &load)
    {
      bool left = false, right = false;
      for (const auto &n : normal)
        if (n * load > 0)
          {
            const double side = load[0] * n[1] - load[1] * n[0];
            left              = left || side >= 0;
            right             = right || side <= 0;
          }
      return left && right;
    }

    /** The starting active set: @p warm (candidates) in the window, else the overlapping positions. */
    std::vector<unsigned int>
    starting_set(const ContactKinematics         &kin,
                 const double                     clearance,
                 const std::vector<unsigned int> &warm,
                 const bool                       force_control,
                 const Tensor<1, 2>              &P)
    {
      std::vector<unsigned int> active;
      for (const auto c : warm)
        {
          const auto it = std::lower_bound(kin.candidates.begin(), kin.candidates.end(), c);
          if (it != kin.candidates.end() && *it == c)
            active.push_back(it - kin.candidates.begin());
        }
      if (active.empty())
        {
          // The rigid overlap of the pose (of depth δ) reaches farther than the contact,
          // whose edges the elastic deformation carries: on the round steel pair the
          // contact's half-angle is r = 0.45, 0.52, 0.63, 0.78 of the overlap's at
          // δ/c = 5e-4, 4e-3, 0.027, 0.16 (100 N … 100 kN; r ≈ 0.89 + 0.134 log10(δ/c)).
          // An overlap δ − (c + δ)θ²/2 ≥ (1 − r²) δ marks that arc; the iteration
          // corrects the rest (this only saves iterations).
          const double overlap = -*std::min_element(kin.g0.begin(), kin.g0.end());
          const double r       = std::clamp(0.89 + 0.134 * std::log10(std::max(overlap, 1e-30) / clearance), 0.3, 1.0);
          for (unsigned int p = 0; p < kin.g0.size(); ++p)
            if (kin.g0[p] < -std::max((1 - r * r) * overlap, kin.tolerance))
              active.push_back(p);
        }
      if (force_control)
        active_set::ensure_two_active(active, kin.g0, kin.normal, P);
      return active;
    }

    /** Largest elastic opening of the gap, n·U − g0, over the active positions [m] (≥ 0). */
    double
    largest_opening(const ContactKinematics &kin, const WindowState &st)
    {
      double c = 0;
      for (const auto p : st.active)
        c = std::max(c, kin.normal[p] * st.U - kin.g0[p]);
      return c;
    }

    /** Mean bore radius − mean pin radius of the meshed surfaces [m] (> 0). */
    double
    mean_clearance(const ElasticityProblem &problem)
    {
      double r1 = 0, r2 = 0;
      for (const auto &n : problem.bore_nodes)
        r1 += n.point.norm() / problem.bore_nodes.size();
      for (const auto &n : problem.pin_nodes)
        r2 += n.point.norm() / problem.pin_nodes.size();
      return std::max(r1 - r2, 1e-9);
    }

  } // namespace condensed_detail

  using namespace condensed_detail;


  CondensedContactSolver::CondensedContactSolver(const ElasticityProblem &problem,
                                                 BoundaryCompliance      &compliance,
                                                 unsigned int             max_iterations,
                                                 unsigned int             primal_dual_limit)
    : problem(problem)
    , compliance(compliance)
    , max_iterations(max_iterations)
    , primal_dual_limit(primal_dual_limit)
    , clearance(mean_clearance(problem))
    , pin_radius(smallest_pin_radius(problem))
    , spacing(candidate_spacing(problem))
    , workspace(std::make_unique<Workspace>())
  {
  }


  CondensedContactSolver::~CondensedContactSolver() = default;


  const CondensedTimings &
  CondensedContactSolver::timings() const
  {
    return workspace->timings;
  }


  // The window: every candidate whose initial gap is below T. A candidate outside it
  // stays open unless the elastic deformation closes the gap there by more than
  // T − |U|. Near a compressive contact the elastic part of the gap (A λ) opens it; it
  // closes it only where the surfaces bulge, far from the contact: measured on the
  // steel pair (50 µm elements, 10 N … 100 kN, round and with a 30 µm / 10 µm worn
  // dent, three load directions, every candidate evaluated), the elastic part outside
  // the contact was never below −0.055 × its largest value at the contact (the
  // opening). So the window is accepted when T − |U| ≥ 0.25 × the opening (a margin
  // of 4.5), and widened to twice what that needs otherwise. T starts at half the
  // expected approach, at least half the overlap of the pose, and 1e-3 of the
  // candidate spacing above the smallest gap.
  // In the window: the primal–dual iteration (fast; may cycle on worn, conforming
  // pairs), and when it revisits an active set or after primal_dual_limit iterations the
  // monotone method from a feasible point (slower, but the objective ½λᵀAλ + g0ᵀλ never
  // increases, so it ends).
  // The active-set phases of one linearization on the window: primal–dual, then the
  // monotone method if that did not converge. Throws if neither does.
  void
  CondensedContactSolver::solve_linearized(const ContactKinematics &kin,
                                           WindowCompliance        &A,
                                           ActiveFactor            &factor,
                                           const bool               force_control,
                                           const Tensor<1, 2>      &load,
                                           const bool               exact,
                                           WindowState             &st,
                                           bool                    &monotone_used)
  {
    bool done =
      primal_dual(kin, A, factor, force_control, load, std::min(max_iterations, primal_dual_limit), exact, st);
    if (!done)
      {
        ++n_monotone;
        monotone_used = true;
        factor.make_double(); // the monotone phase decides on exact solutions
        done = monotone(kin, A, factor, force_control, load, 10 * max_iterations, st);
      }
    if (!done)
      active_set::not_converged("condensed", st.iterations);
  }


  // The accepted linearization, solved with a single-precision factor, to double
  // precision: its solution refined (refine()) and the active set checked with the
  // refined gaps; if the set changes, the primal–dual iteration goes on with refined
  // solves. Leaves the gaps of every position.
  void
  CondensedContactSolver::solve_exactly(const ContactKinematics &kin,
                                        WindowCompliance        &A,
                                        ActiveFactor            &factor,
                                        const bool               force_control,
                                        const Tensor<1, 2>      &load,
                                        WindowState             &st,
                                        bool                    &monotone_used)
  {
    window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::active);
    if (refine(kin, A, factor, force_control, load, st))
      {
        std::set<std::vector<unsigned int>> history;
        auto next = active_set::update(st.active, st.lambda, st.gap, kin.tolerance, history);
        if (force_control)
          active_set::ensure_two_active(next, st.gap, kin.normal, load);
        if (next == st.active)
          return;
      }
    else
      factor.make_double();
    solve_linearized(kin, A, factor, force_control, load, true, st, monotone_used);
    window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::all);
  }


  // The linearizations of one pairing: each refreshes the gaps about the translated pin
  // (refresh_gaps(), the pairing kept) until the translation of the last one is small
  // (relinearization_done()). First the window is checked (so that the path is the
  // reference solver's, which sees every candidate): too narrow, @p widen receives the
  // threshold it needs; then the linearization and the pairing: a pin that slid by
  // more than pairing_outdated() ends the pairing. U_pair: the translation since it.
  CondensedContactSolver::PairingEnd
  CondensedContactSolver::linearize(const PinPose      &paired,
                                    const double        threshold,
                                    const bool          force_control,
                                    const Tensor<1, 2> &load,
                                    ContactKinematics  &kin,
                                    WindowCompliance   &A,
                                    ActiveFactor       &factor,
                                    WindowState        &st,
                                    Tensor<1, 2>       &U_pair,
                                    unsigned int       &updates,
                                    double             &widen,
                                    bool               &monotone_used)
  {
    PinPose moved = paired;
    for (;;)
      {
        solve_linearized(kin, A, factor, force_control, load, false, st, monotone_used);
        U_pair += st.U;
        const double needed = U_pair.norm() + 0.25 * largest_opening(kin, st) + kin.tolerance;
        if (needed > threshold && threshold < 4 * paired.bore->max_radius())
          {
            widen = 2 * needed;
            return PairingEnd::narrow;
          }
        // Converged: accepted if paired at the solution, else paired there once more.
        const bool done = relinearization_done(st.U, pin_radius);
        if (!force_control || (done && !pairing_off_the_solution(U_pair, load / load.norm(), spacing)) ||
            ++updates >= max_relinearizations)
          return PairingEnd::accepted;
        if (done || pairing_outdated(U_pair, spacing))
          return PairingEnd::slid;
        moved.eccentricity = paired.eccentricity + U_pair;
        refresh_gaps(problem, moved, kin);
        factor.gaps_changed();
      }
  }


  // On a worn, jagged bore the window's few candidates (9 at 87 N, 0.2 mm elements,
  // bores worn ~50 µm) can all face one side of the load: their normals span −22.3° …
  // −10.4° against a load at −9.0°. Then no λ ≥ 0 balances the load, the monotone
  // phase's feasible start is not feasible, and its step drops the pair's second
  // position that ensure_two_active() adds back, forever. The window is widened
  // (the threshold doubled, at least by 5 % of the candidate spacing) until some normal
  // lies on either side of the load; a closed bore always has such normals.
  ContactKinematics
  CondensedContactSolver::load_bracketing_window(const PinPose      &pose,
                                                 const bool          force_control,
                                                 const Tensor<1, 2> &load,
                                                 double             &T,
                                                 double             &threshold) const
  {
    const double largest = 4 * pose.bore->max_radius();
    for (;;)
      {
        auto kin = compute_window_kinematics(problem, pose, {T, 1e-3 * spacing, 0.5}, &threshold);
        if (!force_control || brackets(kin.normal, load) || threshold >= largest)
          return kin;
        T = std::max(2 * threshold, threshold + 0.05 * spacing);
      }
  }


  // Pairings: the window kinematics at a pose, its compliance and factor, and its
  // linearizations (linearize()). A pin that slides by more than a quarter of the
  // candidate spacing since the pairing (a light load on a worn, inclined bore: 70 µm
  // measured) is paired anew at its new pose, warm-started from the active candidates;
  // a window too narrow for the solution's deformation is widened and the pairing
  // solved again. The accepted linearization of a single-precision factor is taken to
  // double precision (solve_exactly()).
  ContactSolution
  CondensedContactSolver::solve(const PinPose      &pose,
                                const bool          force_control,
                                const Tensor<1, 2> &load,
                                const double        closure_estimate,
                                ContactKinematics  &kin)
  {
    const ScopedSeconds timer(workspace->timings.total);
    ++workspace->timings.solves;
    double                    T = 0.5 * std::max(closure_estimate, 0.0);
    std::vector<unsigned int> warm;
    ContactSolution           sol;
    PinPose                   paired  = pose;
    unsigned int              updates = 0;
    for (unsigned int pairing = 0; pairing < 4 * max_relinearizations; ++pairing)
      {
        double threshold = 0;
        kin              = load_bracketing_window(paired, force_control, load, T, threshold);
        WindowCompliance A(problem, compliance, kin, *workspace, wear_diagonal);
        WindowState      st;
        st.lambda.assign(kin.g0.size(), 0.0);
        st.active = starting_set(kin, clearance, warm, force_control, load);
        ActiveFactor factor(A, kin, problem.pin_nodes.size(), *workspace, st.active.size() >= single_precision_from);
        Tensor<1, 2> U_pair;                         // since `paired`
        const unsigned int updates_before = updates; // a widened window solves this pairing again
        const auto         end =
          linearize(paired, threshold, force_control, load, kin, A, factor, st, U_pair, updates, T, sol.monotone);
        sol.iterations += st.iterations;
        warm.clear();
        for (const auto p : st.active)
          warm.push_back(kin.candidates[p]);
        if (end == PairingEnd::narrow)
          {
            updates = updates_before;
            continue;
          }
        if (end == PairingEnd::slid)
          {
            paired.eccentricity += U_pair;
            T = 0.5 * std::max(closure_estimate, 0.0);
            continue;
          }
        if (factor.single_precision())
          {
            const unsigned int before = st.iterations;
            U_pair -= st.U;
            solve_exactly(kin, A, factor, force_control, load, st, sol.monotone);
            U_pair += st.U;
            sol.iterations += st.iterations - before;
          }
        else
          window_gaps(kin, A, st.active, st.lambda, st.U, st.gap, Rows::all);
        A.ensure(st.active);
        for (const auto p : st.active)
          st.gap_force = std::max(st.gap_force, std::abs(kin.g0[p]) / A.column(p)[p]);
        finish(kin, st, force_control, load, sol);
        sol.pin_translation = paired.eccentricity - pose.eccentricity + U_pair;
        return sol;
      }
    throw NumericalError("The condensed contact solver could not find a contact window that holds the contact.");
  }


  // The solution of the last linearization: the balance checked (a gross failure, not
  // round-off: the 2 × 2 Schur complement of two nearly parallel normals has a condition
  // of ~1e6, so it holds to ~1e-10 of the load, not to machine precision — and to
  // round-off of the gaps' line load for a vanishing load), forces zero up to round-off
  // made zero.
  void
  CondensedContactSolver::finish(const ContactKinematics &kin,
                                 WindowState             &st,
                                 const bool               force_control,
                                 const Tensor<1, 2>      &load,
                                 ContactSolution         &sol) const
  {
    sol.resultant = 0;
    for (const auto p : st.active)
      sol.resultant += st.lambda[p] * kin.normal[p];
    // The balance to 1e-8 of the load, or to 1e-12 of the gaps' line load (see
    // WindowState::gap_force) where the load is far smaller than that.
    const double imbalance = (sol.resultant - load).norm();
    const double residual  = imbalance / load.norm();
    if (force_control && !(imbalance <= 1e-8 * load.norm() + 1e-12 * st.gap_force))
      throw NumericalError("The condensed contact solver ended out of equilibrium (resultant off the load by " +
                           format_number(residual, 3) +
                           " of it). Refine the contact surfaces ('Surface element size').");
    for (auto &l : st.lambda) // round-off of a force that is zero (active_set::update)
      l = std::max(l, 0.0);
    sol.lambda           = st.lambda;
    sol.gap              = st.gap;
    sol.active           = st.active;
    sol.last_translation = st.U;
    sol.n_active         = st.active.size();
  }


  // The displacement field for a condensed solution: the contact forces −λ_i ν_i on
  // the pin and +λ_i n_i (interpolated) on the bore, one solve with the clamped
  // factorization, plus the pin's rigid translation U (in the pin frame) on its DoFs.
  Vector<double>
  CondensedContactSolver::displacement_field(const ContactKinematics &kin, const ContactSolution &sol) const
  {
    Vector<double> u(problem.dof_handler.n_dofs());
    for (unsigned int p = 0; p < kin.candidates.size(); ++p)
      if (sol.lambda[p] != 0)
        {
          const auto &node = problem.pin_nodes[kin.candidates[p]];
          u(node.dofs[0]) -= sol.lambda[p] * node.normal[0];
          u(node.dofs[1]) -= sol.lambda[p] * node.normal[1];
          for (unsigned int a = 0; a < kin.n_masters[p]; ++a)
            {
              const auto &b = problem.bore_nodes[kin.masters[p][a]];
              u(b.dofs[0]) += sol.lambda[p] * kin.weights[p][a] * kin.normal[p][0];
              u(b.dofs[1]) += sol.lambda[p] * kin.weights[p][a] * kin.normal[p][1];
            }
        }
    compliance.solve_clamped(u);
    const Tensor<1, 2>            U_pin = rotate(sol.pin_translation, -kin.relative_angle);
    std::vector<char>             done(u.size(), 0);
    std::vector<global_dof_index> dofs(problem.fe.n_dofs_per_cell());
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->material_id() == material_ids::pin)
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (!done[dofs[i]])
              {
                done[dofs[i]] = 1;
                u(dofs[i]) += U_pin[problem.fe.system_to_component_index(i).first];
              }
        }
    return u;
  }
} // namespace wearlink::fe
