// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed contact solver's active block: the Cholesky factor of the compliance
// of the active positions (single or double precision, updated row block by row block)
// and the solve of the active system through it (Schur step on the rigid-body rows).
// Internal to condensed_contact_solver.cc (the one file that includes it).
#pragma once

#include "base/exceptions.h"
#include "base/text.h"
#include "base/timings.h"
#include "fe/active_set_rules.h"
#include "fe/blas_threads.h"
#include "fe/blas_trsm.h"
#include "fe/boundary_ids.h"
#include "fe/condensed_window.h"
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
  inline bool
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
  inline ActiveSolution
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

} // namespace wearlink::fe::condensed_detail
